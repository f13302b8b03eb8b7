#include "gi/core/per_thread.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "gi/core/parallel.hpp"

namespace {

std::uint64_t total(const gi::PerThread<std::uint64_t>& tallies) {
  std::uint64_t sum = 0;
  for (std::uint64_t t : tallies.all()) sum += t;
  return sum;
}

}  // namespace

// Tasks 0 .. 999 each add their number to their thread's tally: the totals are
// 0 + 1 + ... + 999 = 499 500 on any number of threads, with no more tallies than threads.
TEST(PerThread, TalliesAddUpToTheSameTotalOnAnyThreadCount) {
  for (int threads : {1, 2, 3}) {
    gi::PerThread<std::uint64_t> tallies;
    gi::parallel_for(1000, threads, [&](int i) { tallies.mine() += static_cast<std::uint64_t>(i); });
    EXPECT_EQ(total(tallies), 499500u) << threads << " threads";
    EXPECT_LE(tallies.all().size(), static_cast<std::size_t>(threads)) << threads << " threads";
  }
}

// One thread switching between two sets of tallies is handed a fresh object at each
// switch: more objects, the same totals; and a set made later never sees an earlier one's.
TEST(PerThread, SwitchingBetweenTwoKeepsEachTotal) {
  gi::PerThread<std::uint64_t> a, b;
  for (int i = 0; i < 5; ++i) {
    a.mine() += 1;
    b.mine() += 10;
  }
  EXPECT_EQ(total(a), 5u);
  EXPECT_EQ(total(b), 50u);
  gi::PerThread<std::uint64_t> later;
  later.mine() += 7;
  EXPECT_EQ(total(later), 7u);
  EXPECT_EQ(later.all().size(), 1u);
}
