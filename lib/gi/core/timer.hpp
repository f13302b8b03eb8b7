#pragma once
#include <algorithm>
#include <chrono>
#include <vector>

namespace gi {

// Wall-clock stopwatch for the lessons' tables. Timing is reported, never tested:
// the machines are shared and noisy.
class Timer {
 public:
  Timer() : start_(clock::now()) {}
  void restart() { start_ = clock::now(); }
  double seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }
  double milliseconds() const { return 1e3 * seconds(); }

 private:
  using clock = std::chrono::steady_clock;
  clock::time_point start_;
};

// Median of repeated measurements: robust to the one run the machine was busy.
inline double median(std::vector<double> xs) {
  if (xs.empty()) return 0.0;
  std::sort(xs.begin(), xs.end());
  const std::size_t n = xs.size();
  return n % 2 ? xs[n / 2] : 0.5 * (xs[n / 2 - 1] + xs[n / 2]);
}

}  // namespace gi
