#include "gi/report/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace gi {

Progress::Progress(std::string label, long long total)
    : label_(std::move(label)), total_(total > 0 ? total : 1), enabled_(isatty(STDERR_FILENO) != 0) {}

Progress::~Progress() { finish(); }

void Progress::advance(long long n) {
  const long long done = done_ += n;
  if (!enabled_) return;
  std::unique_lock lock(mutex_, std::try_to_lock);  // a busy bar skips a redraw
  if (!lock) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100) && done < total_) return;
  last_draw_ = now;
  draw(done);
}

void Progress::draw(long long done) {
  const int width = 30;
  const int filled = static_cast<int>(width * std::min(done, total_) / total_);
  std::fprintf(stderr, "\r%s [%s%s] %3lld%%", label_.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), 100 * std::min(done, total_) / total_);
  std::fflush(stderr);
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (!enabled_ || finished_) return;
  finished_ = true;
  std::fprintf(stderr, "\r%s\r", std::string(label_.size() + 40, ' ').c_str());
  std::fflush(stderr);
}

}  // namespace gi
