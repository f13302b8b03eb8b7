#include "gi/core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace gi {

namespace {

// Whether this program can start threads at all. WebAssembly built without -pthread
// (Emscripten's default, and the wasm preset's) runs on one thread: there
// std::thread's constructor always throws. The standard library has no way to ask,
// so the compiler's macros say it; everywhere else threads can be started.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
constexpr bool can_start_threads = false;
#else
constexpr bool can_start_threads = true;
#endif

}  // namespace

int hardware_threads() { return can_start_threads ? std::max(1u, std::thread::hardware_concurrency()) : 1; }

void parallel_for(int count, int threads, const std::function<void(int)>& task) {
  if (count <= 0) return;
  if (threads <= 0 || !can_start_threads) threads = hardware_threads();  // one thread where there are no others
  threads = std::min(threads, count);

  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;

  auto worker = [&] {
    for (int i = next++; i < count && !failed; i = next++) {
      try {
        task(i);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };

  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();  // the calling thread works too
  for (auto& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace gi
