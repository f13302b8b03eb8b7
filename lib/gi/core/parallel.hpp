#pragma once
#include <functional>

namespace gi {

// Number of hardware threads (at least 1; 1 where the program cannot start threads,
// as in WebAssembly built without them).
int hardware_threads();

// Calls task(i) for every i in [0, count) on `threads` std::threads (0 = all
// cores). Tasks are handed out one at a time from a shared counter, so a slow
// tile does not hold up a thread's whole share. Determinism is the caller's
// part of the contract: task i must write only its own outputs and draw its
// random numbers from an Rng seeded by i, never from a per-thread one.
// An exception thrown by a task stops the loop and is rethrown here. Where the
// program cannot start threads every task runs on the calling thread, whatever
// `threads` asks: the outputs are the same.
void parallel_for(int count, int threads, const std::function<void(int)>& task);

}  // namespace gi
