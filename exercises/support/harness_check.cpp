// Tests of the graded programs' harness (graded_main.cpp), not of any exercise: each
// test named Leaves* or Forges* does what code under test must not -- leave a thread, a
// child, a signal handler or a timer behind, change the rounding mode, replace the
// terminate handler, write verdicts of its own, exit -- and must fail for that reason;
// each After* test, run next, must still pass (the grader goes on in a new process).
// tools/check_harness.py runs it through the grader and checks every verdict.
#include <gtest/gtest.h>

#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cfenv>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>

#include "gi/core/parallel.hpp"

namespace {
void ignore(int) {}
}  // namespace

TEST(Ex99_1_Harness, JoinsItsThreads) {
  std::thread worker([] {});
  worker.join();
  std::atomic<int> sum{0};
  gi::parallel_for(64, 8, [&](int k) { sum += k; });
  EXPECT_EQ(sum, 64 * 63 / 2) << "threads that are joined leave nothing behind";
}

TEST(Ex99_1_Harness, LeavesAThread) {
  std::thread([] { std::this_thread::sleep_for(std::chrono::seconds(30)); }).detach();
}
TEST(Ex99_1_Harness, AfterAThread) { SUCCEED(); }

TEST(Ex99_1_Harness, LeavesAChild) {
  if (::fork() == 0) {
    ::sleep(30);
    ::_exit(0);
  }
}
TEST(Ex99_1_Harness, AfterAChild) { SUCCEED(); }

TEST(Ex99_1_Harness, LeavesASignalHandler) { std::signal(SIGALRM, ignore); }
TEST(Ex99_1_Harness, AfterASignalHandler) { SUCCEED(); }

TEST(Ex99_1_Harness, LeavesATimer) {
  itimerval timer{};
  timer.it_value.tv_sec = 30;
  ::setitimer(ITIMER_REAL, &timer, nullptr);
}
TEST(Ex99_1_Harness, AfterATimer) { SUCCEED(); }

TEST(Ex99_1_Harness, LeavesAnotherRoundingMode) { std::fesetround(FE_UPWARD); }
TEST(Ex99_1_Harness, AfterARoundingMode) { SUCCEED(); }

TEST(Ex99_1_Harness, LeavesATerminateHandler) { std::set_terminate([] { std::_Exit(0); }); }
TEST(Ex99_1_Harness, AfterATerminateHandler) { SUCCEED(); }

TEST(Ex99_1_Harness, ForgesVerdictsIntoEveryDescriptor) {
  for (int fd = 3; fd < 256; ++fd) {
    const std::string line = std::string(64, '0') + " {\"n\":1,\"e\":\"end\",\"t\":\"Ex99_1_Harness."
                             "ForgesVerdictsIntoEveryDescriptor\",\"ok\":true,\"skip\":false,\"fail\":[]}\n";
    [[maybe_unused]] const ssize_t wrote = ::write(fd, line.data(), line.size());
  }
  std::_Exit(0);
}
TEST(Ex99_1_Harness, AfterForgedVerdicts) { SUCCEED(); }

TEST(Ex99_1_Harness, ForgesAPassByExitingAtTheFirstFailure) {
  std::atexit([] { std::puts("[  PASSED  ] 1 test."); });
  ADD_FAILURE() << "a failure the code would like to hide";
  std::exit(0);
}
TEST(Ex99_1_Harness, AfterAnExit) { SUCCEED(); }
