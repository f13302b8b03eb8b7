#pragma once
// State that many threads add to without a lock, one object per thread: a tally of the
// rays a radiance function casts, say. Each thread that asks is handed an object of its
// own, made at its first ask; once the threads are done, the caller adds them all up.
// Which thread took which pixels never shows in the result as long as the objects are
// summed exactly (integer counts), so an estimator keeps its tallies without knowing
// of tiles or threads, and the totals are the same for any thread count.
//
// A thread finds its object through a thread_local slot marked with this PerThread's
// serial number. A thread that switches between two PerThreads is handed a fresh
// object at each switch: more objects, the same totals.
#include <atomic>
#include <cstdint>
#include <deque>
#include <mutex>

namespace gi {

template <class T>
class PerThread {
 public:
  PerThread() = default;
  PerThread(const PerThread&) = delete;
  PerThread& operator=(const PerThread&) = delete;

  // This thread's object.
  T& mine() {
    thread_local Slot slot;
    if (slot.owner != serial_) {
      const std::lock_guard<std::mutex> lock(mutex_);
      slot = {serial_, &objects_.emplace_back()};  // a deque's elements stay where they are as it grows
    }
    return *slot.object;
  }

  // Every thread's object, once the threads are done.
  const std::deque<T>& all() const { return objects_; }

 private:
  struct Slot {
    std::uint64_t owner = 0;
    T* object = nullptr;
  };
  static std::uint64_t next_serial() {
    static std::atomic<std::uint64_t> last{0};
    return ++last;  // from 1: a fresh slot's owner 0 belongs to none
  }

  const std::uint64_t serial_ = next_serial();
  std::mutex mutex_;
  std::deque<T> objects_;
};

}  // namespace gi
