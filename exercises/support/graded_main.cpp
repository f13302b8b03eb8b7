// The main of every graded test program: GoogleTest's own, plus a report to the
// grader that the code under test cannot forge by writing text.
//
// Run by a student (`build/release/bin/lab01_graded`) or by ctest, it is plain gtest.
// Run by the grader, it gets two descriptors: `--gi_key=FD`, a pipe holding a key of
// 32 random bytes, and `--gi_report=FD`, a file open for appending only, where it
// writes one line per event, `<HMAC-SHA256 of the payload, hex> <payload>`:
//     {"n":0,"e":"start","t":"Ex1_1_RaySphere.HitsFromOutside"}
//     {"n":1,"e":"end","t":"Ex1_1_RaySphere.HitsFromOutside","ok":false,"skip":false,"fail":["sphere_test.cpp:12\n..."]}
//     ...  {"n":40,"e":"done"}
// The grader believes only lines whose signature checks, in sequence; a pass is an
// "end" line with "ok":true. What the code under test prints, a report file it
// writes, an exit status, a line it writes into every descriptor it finds: none of
// it is signed, so none of it counts.
//
// The key is where a forger would look, so it is kept in one place, out of reach of
// everything but this process's own code:
// - it is read, and its pipe closed, by the program's very first code (from
//   .preinit_array on ELF systems with glibc: before any constructor, so before any
//   code of the course or of a submission could read the pipe; elsewhere first thing
//   in main, and exercise regions, function bodies only, run only when a test calls
//   them); it lives in one static buffer for the whole run (each verdict is signed
//   after the code under test ran, so it cannot be wiped before), and HMAC overwrites
//   its own buffers made from it (the padded key, the hash states) before returning;
// - the program then makes itself non-dumpable (Linux): no other process -- a child
//   the code under test starts, a shell, a debugger -- may ptrace it or read its
//   memory, and it cannot open its own /proc/self/mem (the sandbox's seccomp filter
//   also refuses ptrace and making the program dumpable again);
// - a copy of the process made by fork never signs (it is not the process the key was
//   given to), and the report cannot be read back, so there is no signed line to try
//   a guessed key against.
// What remains: code under test runs in this process, and an exercise function that
// reads or overwrites the harness's memory with pointers while it runs could sign a
// pass (a process may always read its own symbol table and memory map, so the key's
// address is not secret); so could a child it forks, which holds a copy of the key, if
// it computed the signature itself. A program run as root outside the sandbox is open
// to other root processes. exercises/README.md (the threat model) says why no harness
// in the same process can prevent that.
//
// After each test the harness checks that the code left nothing running that could
// act later: no thread, no child process, no signal handler or timer, no replaced
// terminate or new handler, no changed rounding mode. If it did, the test fails with
// the reason and the program stops (the grader runs the remaining tests in a new
// process). The program ends with _exit: no atexit handler and no static destructor
// runs after the last verdict.
#include <gtest/gtest.h>

#include <cfenv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "support/hmac.hpp"

#if defined(__unix__) || defined(__APPLE__)
#define GI_GRADED_POSIX 1
#include <fcntl.h>
#include <signal.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace {

constexpr std::size_t max_message = 4096;  // characters of one failure kept
constexpr int max_failures = 20;           // failures kept per test

// A JSON string of the text; bytes outside printable ASCII as \u00XX (the grader reads
// them back as bytes, so UTF-8 survives and any other byte does no harm).
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c < 0x20 || c >= 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += char(c);
    }
  }
  return out + "\"";
}

#ifdef GI_GRADED_POSIX

// The value of a flag --gi_NAME=FD, or -1.
int descriptor(int argc, char** argv, const char* flag) {
  const std::size_t length = std::strlen(flag);
  for (int k = 1; k < argc && argv[k]; ++k)
    if (std::strncmp(argv[k], flag, length) == 0) return std::atoi(argv[k] + length);
  return -1;
}

// The grader's key: static storage, so no constructor runs to make it.
struct Key {
  char bytes[32];
  bool given;  // the command line names a key descriptor
  bool read;   // all 32 bytes came
  bool sealed;  // the process's memory closed to others (Linux)
};
Key the_key;

// Reads the key and closes its pipe, then closes the process's memory to others.
void read_key(int argc, char** argv, char**) {
  const int fd = descriptor(argc, argv, "--gi_key=");
  if (fd < 0 || the_key.given) return;
  the_key.given = true;
  std::size_t got = 0;
  while (got < sizeof the_key.bytes) {
    const ssize_t n = ::read(fd, the_key.bytes + got, sizeof the_key.bytes - got);
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  the_key.read = got == sizeof the_key.bytes;
#if defined(__linux__)
  the_key.sealed = ::prctl(PR_SET_DUMPABLE, 0, 0, 0, 0) == 0;  // no ptrace, no /proc/PID/mem, by anyone but root
#endif
}

#if defined(__ELF__) && defined(__GLIBC__)
// glibc calls these with (argc, argv, envp) before the program's constructors.
[[gnu::used, gnu::section(".preinit_array")]] void (*read_key_before_any_constructor)(int, char**, char**) = read_key;
#endif

bool dumpable() {
#if defined(__linux__)
  return the_key.sealed && ::prctl(PR_GET_DUMPABLE, 0, 0, 0, 0) != 0;
#else
  return false;
#endif
}

// What a test must leave as it found it: taken before each test, compared after.
struct ProcessState {
  struct sigaction actions[NSIG] = {};
  std::terminate_handler terminate = nullptr;
  std::new_handler new_handler = nullptr;
  int rounding = 0;
  int threads = 0;
};

class Reporter : public testing::EmptyTestEventListener {
 public:
  Reporter(std::string_view key, int report_fd) : key_(key), fd_(report_fd), signer_(::getpid()) {}

  void OnTestStart(const testing::TestInfo& info) override {
    failures_.clear();
    before_ = snapshot();
    std::string fields = "\"e\":\"start\",\"t\":";
    write_record(fields + json_string(name(info)));
  }

  void OnTestPartResult(const testing::TestPartResult& part) override {
    if (!part.failed() || static_cast<int>(failures_.size()) >= max_failures) return;
    std::string text = part.file_name() ? std::string(part.file_name()) : "unknown file";
    if (part.line_number() >= 0) {
      text += ':';
      text += std::to_string(part.line_number());
    }
    text += '\n';
    text += part.message();
    failures_.push_back(text.substr(0, max_message));
  }

  void OnTestEnd(const testing::TestInfo& info) override {
    const std::string left = left_behind();
    if (!left.empty())
      failures_.push_back("unknown file\nthe code under test left " + left +
                          " after the test: it must leave nothing running or changed");
    const bool ok = info.result()->Passed() && left.empty();
    std::string fields = "\"e\":\"end\",\"t\":";
    fields += json_string(name(info));
    fields += ok ? ",\"ok\":true" : ",\"ok\":false";
    fields += info.result()->Skipped() ? ",\"skip\":true,\"fail\":[" : ",\"skip\":false,\"fail\":[";
    for (std::size_t k = 0; k < failures_.size(); ++k) {
      if (k > 0) fields += ',';
      fields += json_string(failures_[k]);
    }
    write_record(fields + "]");
    if (!left.empty()) finish(4);  // what it left may act on the next test: stop here
  }

  void finish(int status) {
    if (status == 0) write_record("\"e\":\"done\"");
    std::fflush(nullptr);
    ::_exit(status);
  }

 private:
  static std::string name(const testing::TestInfo& info) {
    return std::string(info.test_suite_name()) + "." + info.name();
  }

  void write_record(const std::string& fields) {
    if (::getpid() != signer_) ::_exit(6);  // a copy made by fork in the code under test: it never signs
    const std::string payload = "{\"n\":" + std::to_string(sequence_++) + "," + fields + "}";
    const std::string line = support::hex(support::hmac_sha256(key_, payload)) + " " + payload + "\n";
    for (std::size_t done = 0; done < line.size();) {
      const ssize_t wrote = ::write(fd_, line.data() + done, line.size() - done);
      if (wrote <= 0) ::_exit(5);  // the report cannot be written: nothing more can count
      done += static_cast<std::size_t>(wrote);
    }
  }

  // The process's thread count (Linux: /proc/self/stat, opened afresh each time, so
  // that closing a descriptor cannot hide a thread); -1 when it cannot be read.
  static int threads() {
#if defined(__linux__)
    const int fd = ::open("/proc/self/stat", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return -1;
    char text[1024];
    const ssize_t got = ::read(fd, text, sizeof text - 1);
    ::close(fd);
    if (got <= 0) return -1;
    text[got] = '\0';
    const char* field = std::strrchr(text, ')');  // after "pid (name)": state, then 16 fields, then threads
    for (int k = 0; field && k < 18; ++k) field = std::strchr(field + 1, ' ');
    return field ? std::atoi(field + 1) : -1;
#else
    return 0;  // no thread count here: the check is Linux's
#endif
  }

  ProcessState snapshot() const {
    ProcessState s;
    for (int sig = 1; sig < NSIG; ++sig) ::sigaction(sig, nullptr, &s.actions[sig]);
    s.terminate = std::get_terminate();
    s.new_handler = std::get_new_handler();
    s.rounding = std::fegetround();
    s.threads = threads();
    return s;
  }

  // The same disposition: the same handler and, for a function, the same flags that
  // change how it is called. (The C library adds flags of its own to every action it
  // sets -- std::system puts SIGINT's default back with one -- which change nothing.)
  static bool same_action(const struct sigaction& a, const struct sigaction& b) {
    if (a.sa_handler != b.sa_handler) return false;
    if (a.sa_handler == SIG_DFL || a.sa_handler == SIG_IGN) return true;
    const int meaning = SA_SIGINFO | SA_ONSTACK | SA_RESTART | SA_NODEFER | SA_RESETHAND | SA_NOCLDSTOP | SA_NOCLDWAIT;
    return (a.sa_flags & meaning) == (b.sa_flags & meaning);
  }

  // What the test left that was not there before it ran, or "".
  std::string left_behind() const {
    const ProcessState now = snapshot();
    int count = now.threads;
    for (int wait = 0; count > before_.threads && wait < 50; ++wait) {
      ::usleep(4000);  // a thread just joined may take a moment to leave the count
      count = threads();
    }
    if (count < 0 || before_.threads < 0) return "its threads uncountable (/proc/self/stat could not be read)";
    if (count > before_.threads) return "a thread running";
    if (dumpable()) return "its memory open to other processes (the program made dumpable again)";
    siginfo_t child{};
    if (::waitid(P_ALL, 0, &child, WEXITED | WNOHANG | WNOWAIT) == 0) return "a child process";
    for (int sig = 1; sig < NSIG; ++sig)
      if (!same_action(before_.actions[sig], now.actions[sig]))
        return "a handler installed for signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
    for (int which : {ITIMER_REAL, ITIMER_VIRTUAL, ITIMER_PROF}) {
      itimerval timer{};
      if (::getitimer(which, &timer) == 0 && (timer.it_value.tv_sec || timer.it_value.tv_usec))
        return "a timer set";
    }
    if (now.terminate != before_.terminate) return "a new std::terminate handler";
    if (now.new_handler != before_.new_handler) return "a new std::new_handler";
    if (now.rounding != before_.rounding) return "the floating-point rounding mode changed";
    return "";
  }

  std::string_view key_;
  int fd_;
  pid_t signer_;  // the process the grader gave the key to
  long sequence_ = 0;
  ProcessState before_;
  std::vector<std::string> failures_;
};

#endif  // GI_GRADED_POSIX

}  // namespace

int main(int argc, char** argv) {
#ifdef GI_GRADED_POSIX
  read_key(argc, argv, nullptr);  // where no .preinit_array ran it (it does nothing a second time)
#endif
  testing::InitGoogleTest(&argc, argv);
#ifdef GI_GRADED_POSIX
  const int report_fd = descriptor(argc, argv, "--gi_report=");
  if (the_key.given || report_fd >= 0) {
    if (!the_key.read || report_fd < 0) {
      std::fprintf(stderr, "graded tests: --gi_key and --gi_report name the grader's descriptors\n");
      return 2;
    }
    auto* reporter = new Reporter(std::string_view(the_key.bytes, sizeof the_key.bytes), report_fd);
    testing::UnitTest::GetInstance()->listeners().Append(reporter);
    [[maybe_unused]] const int failed = RUN_ALL_TESTS();  // the verdicts are in the report
    reporter->finish(0);
  }
#endif
  return RUN_ALL_TESTS();
}
