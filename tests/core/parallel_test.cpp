#include "gi/core/parallel.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

TEST(ParallelFor, CallsEveryIndexExactlyOnce) {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<int> calls(1000, 0);
    gi::parallel_for(1000, threads, [&](int i) { ++calls[i]; });
    for (int c : calls) ASSERT_EQ(c, 1) << threads << " threads";
  }
}

TEST(ParallelFor, ZeroOrNegativeCountDoesNothing) {
  int calls = 0;
  gi::parallel_for(0, 4, [&](int) { ++calls; });
  gi::parallel_for(-3, 4, [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, RethrowsATaskException) {
  EXPECT_THROW(gi::parallel_for(100, 2,
                                [](int i) {
                                  if (i == 37) throw std::runtime_error("task 37 failed");
                                }),
               std::runtime_error);
}
