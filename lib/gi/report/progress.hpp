#pragma once
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace gi {

// A progress bar on stderr for long work, drawn only when stderr is a terminal (so
// logs and CI output stay clean). advance() may be called from any thread.
class Progress {
 public:
  Progress(std::string label, long long total);
  ~Progress();
  void advance(long long n = 1);
  void finish();

 private:
  void draw(long long done);
  std::string label_;
  long long total_;
  std::atomic<long long> done_{0};
  bool enabled_, finished_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace gi
