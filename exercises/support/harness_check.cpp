// Tests of the graded programs' harness (graded_main.cpp), not of any exercise: each
// test named Leaves* or Forges* does what code under test must not -- leave a thread, a
// child, a signal handler or a timer behind, change the rounding mode, replace the
// terminate handler, write verdicts of its own, exit -- and must fail for that reason;
// each After* test, run next, must still pass (the grader goes on in a new process).
// The tests named for a way to the key -- a constructor that reads its pipe, the
// program's own memory file, a child that traces it, a forked copy that signs, the
// report read back, the dumpable flag turned back -- must find the way shut.
// tools/check_harness.py runs it through the grader and checks every verdict.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/ptrace.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/uio.h>
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

// The value of --gi_NAME=FD on this program's command line, or -1.
int grader_descriptor(const std::string& flag) {
  std::string args;
  if (std::FILE* in = std::fopen("/proc/self/cmdline", "rb")) {
    char buffer[4096];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, in)) > 0;) args.append(buffer, got);
    std::fclose(in);
  }
  for (std::size_t at = 0; at < args.size(); at = args.find('\0', at) + 1) {
    if (args.compare(at, flag.size(), flag) == 0) return std::atoi(args.c_str() + at + flag.size());
    if (args.find('\0', at) == std::string::npos) break;
  }
  return -1;
}

// Code that runs before main, as a constructor anywhere in a test program would: it
// tries to read the grader's key from its pipe.
struct KeyThief {
  long stolen = 0;  // bytes of the key it read
  KeyThief() {
    const int fd = grader_descriptor("--gi_key=");
    struct stat info {};
    char key[32];
    if (fd >= 0 && ::fstat(fd, &info) == 0 && S_ISFIFO(info.st_mode)) stolen = ::read(fd, key, sizeof key);
  }
} key_thief;

char a_byte_of_memory = 'k';
}  // namespace

TEST(Ex99_1_Harness, TheKeyWasGoneBeforeAnyConstructor) {
  EXPECT_LE(key_thief.stolen, 0) << "a constructor read " << key_thief.stolen << " bytes of the key";
}

TEST(Ex99_1_Harness, OpensItsOwnMemory) {
  const int fd = ::open("/proc/self/mem", O_RDONLY);
  if (fd >= 0) ::close(fd);
  EXPECT_LT(fd, 0) << "/proc/self/mem opened: the harness's key could be read from it";
}

TEST(Ex99_1_Harness, TracesItsParentFromAChild) {
  const pid_t parent = ::getpid(), child = ::fork();
  if (child == 0) {
    int opened = 0;
    if (::ptrace(PTRACE_SEIZE, parent, nullptr, nullptr) == 0) opened |= 1;  // detached when this child exits
    char byte = 0;
    iovec mine{&byte, 1}, theirs{&a_byte_of_memory, 1};
    if (::process_vm_readv(parent, &mine, 1, &theirs, 1, 0) == 1) opened |= 2;
    const int fd = ::open(("/proc/" + std::to_string(parent) + "/mem").c_str(), O_RDONLY);
    if (fd >= 0) opened |= 4;
    ::_exit(opened);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "a child reached its parent's memory (1: ptrace, 2: process_vm_readv, 4: /proc/PID/mem): "
      << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

TEST(Ex99_1_Harness, SignsFromAForkedCopy) {
  const pid_t copy = ::fork();
  if (copy == 0) return;  // the copy goes on as the program would, to its harness's next verdict
  int status = 0;
  ::waitpid(copy, &status, 0);
  SUCCEED() << "the copy never signed: this verdict, the parent's, is the only one in sequence";
}

TEST(Ex99_1_Harness, ReadsTheReportBack) {
  const int fd = grader_descriptor("--gi_report=");
  char line[64];
  const ssize_t got = fd >= 0 ? ::pread(fd, line, sizeof line, 0) : -1;
  EXPECT_LT(got, 0) << "the signed report could be read back: a guessed key could be tried against it";
}

TEST(Ex99_1_Harness, PutsTheDefaultHandlerBack) {  // as std::system does with SIGINT and SIGQUIT
  struct sigaction ignore_it {}, before {};
  ignore_it.sa_handler = SIG_IGN;
  ::sigaction(SIGINT, &ignore_it, &before);
  ::sigaction(SIGINT, &before, nullptr);
  SUCCEED();
}

TEST(Ex99_1_Harness, LeavesItselfDumpable) {
  [[maybe_unused]] const int refused = ::prctl(PR_SET_DUMPABLE, 1, 0, 0, 0);
}
TEST(Ex99_1_Harness, AfterDumpable) { SUCCEED(); }

TEST(Ex99_1_Harness, HidesAThreadFromTheCount) {
  const int report = grader_descriptor("--gi_report=");
  for (int fd = 3; fd < 256; ++fd)
    if (fd != report) ::close(fd);  // whatever the harness holds open, but its report
  std::thread([] { std::this_thread::sleep_for(std::chrono::seconds(30)); }).detach();
}
TEST(Ex99_1_Harness, AfterAHiddenThread) { SUCCEED(); }

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
