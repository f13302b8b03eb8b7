#include "gi/report/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace gi {

namespace {

#ifdef __EMSCRIPTEN__
// In WebAssembly the host draws the bar: the lesson's page (docs/live/) and
// docs/live/node_run.js on a terminal hand the run an onProgress(label, percent).
// Emscripten's stderr counts as a terminal even in a page, where "\r" draws nothing.
EM_JS(int, host_draws_progress, (), { return typeof Module['onProgress'] === 'function' ? 1 : 0; });
EM_JS(void, host_progress, (const char* label, int percent), {
  Module['onProgress'](UTF8ToString(label), percent);
});
bool draws_progress() { return host_draws_progress() != 0; }
#else
bool draws_progress() { return isatty(STDERR_FILENO) != 0; }
#endif

}  // namespace

Progress::Progress(std::string label, long long total)
    : label_(std::move(label)), total_(total > 0 ? total : 1), enabled_(draws_progress()) {}

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
#ifdef __EMSCRIPTEN__
  host_progress(label_.c_str(), static_cast<int>(100 * std::min(done, total_) / total_));
#else
  const int width = 30;
  const int filled = static_cast<int>(width * std::min(done, total_) / total_);
  std::fprintf(stderr, "\r%s [%s%s] %3lld%%", label_.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), 100 * std::min(done, total_) / total_);
  std::fflush(stderr);
#endif
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (!enabled_ || finished_) return;
  finished_ = true;
#ifdef __EMSCRIPTEN__
  host_progress(label_.c_str(), 100);
#else
  std::fprintf(stderr, "\r%s\r", std::string(label_.size() + 40, ' ').c_str());
  std::fflush(stderr);
#endif
}

}  // namespace gi
