// The main of every graded test program: GoogleTest's own, plus a report to the
// grader that the code under test cannot forge by writing text.
//
// Run by a student (`build/release/bin/lab01_graded`) or by ctest, it is plain gtest.
// Run by the grader, it gets two descriptors: `--gi_key=FD`, a pipe holding a key of
// 32 random bytes, read and closed before any test runs, and `--gi_report=FD`, where
// it writes one line per event, `<HMAC-SHA256 of the payload, hex> <payload>`:
//     {"n":0,"e":"start","t":"Ex1_1_RaySphere.HitsFromOutside"}
//     {"n":1,"e":"end","t":"Ex1_1_RaySphere.HitsFromOutside","ok":false,"skip":false,"fail":["sphere_test.cpp:12\n..."]}
//     ...  {"n":40,"e":"done"}
// The grader believes only lines whose signature checks, in sequence; a pass is an
// "end" line with "ok":true. What the code under test prints, a report file it
// writes, an exit status, a line it writes into every descriptor it finds: none of
// it is signed, so none of it counts.
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
#include <optional>
#include <string>
#include <vector>

#include "support/hmac.hpp"

#if defined(__unix__) || defined(__APPLE__)
#define GI_GRADED_POSIX 1
#include <fcntl.h>
#include <signal.h>
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
  Reporter(std::string key, int report_fd) : key_(std::move(key)), fd_(report_fd) {
    stat_fd_ = ::open("/proc/self/stat", O_RDONLY | O_CLOEXEC);  // Linux: the thread count
  }

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
    const std::string payload = "{\"n\":" + std::to_string(sequence_++) + "," + fields + "}";
    const std::string line = support::hex(support::hmac_sha256(key_, payload)) + " " + payload + "\n";
    for (std::size_t done = 0; done < line.size();) {
      const ssize_t wrote = ::write(fd_, line.data() + done, line.size() - done);
      if (wrote <= 0) ::_exit(5);  // the report cannot be written: nothing more can count
      done += static_cast<std::size_t>(wrote);
    }
  }

  int threads() const {
    if (stat_fd_ < 0) return 0;
    char text[1024];
    const ssize_t got = ::pread(stat_fd_, text, sizeof text - 1, 0);
    if (got <= 0) return 0;
    text[got] = '\0';
    const char* field = std::strrchr(text, ')');  // after "pid (name)": state, then 16 fields, then threads
    for (int k = 0; field && k < 18; ++k) field = std::strchr(field + 1, ' ');
    return field ? std::atoi(field + 1) : 0;
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

  // What the test left that was not there before it ran, or "".
  std::string left_behind() const {
    const ProcessState now = snapshot();
    for (int wait = 0; now.threads > before_.threads && wait < 50 && threads() > before_.threads; ++wait)
      ::usleep(4000);  // a thread just joined may take a moment to leave the count
    if (threads() > before_.threads) return "a thread running";
    siginfo_t child{};
    if (::waitid(P_ALL, 0, &child, WEXITED | WNOHANG | WNOWAIT) == 0) return "a child process";
    for (int sig = 1; sig < NSIG; ++sig) {
      const struct sigaction &a = before_.actions[sig], &b = now.actions[sig];
      if (a.sa_handler != b.sa_handler || a.sa_flags != b.sa_flags)
        return "a handler installed for signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
    }
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

  std::string key_;
  int fd_;
  int stat_fd_ = -1;
  long sequence_ = 0;
  ProcessState before_;
  std::vector<std::string> failures_;
};

// The value of a flag --gi_NAME=FD, or -1.
int descriptor(int argc, char** argv, const char* flag) {
  const std::size_t length = std::strlen(flag);
  for (int k = 1; k < argc; ++k)
    if (std::strncmp(argv[k], flag, length) == 0) return std::atoi(argv[k] + length);
  return -1;
}

std::optional<std::string> read_key(int fd) {
  std::string key(32, '\0');
  for (std::size_t got = 0; got < key.size();) {
    const ssize_t n = ::read(fd, key.data() + got, key.size() - got);
    if (n <= 0) return std::nullopt;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  return key;
}

#endif  // GI_GRADED_POSIX

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
#ifdef GI_GRADED_POSIX
  const int key_fd = descriptor(argc, argv, "--gi_key="), report_fd = descriptor(argc, argv, "--gi_report=");
  if (key_fd >= 0 || report_fd >= 0) {
    const std::optional<std::string> key = key_fd >= 0 ? read_key(key_fd) : std::nullopt;
    if (!key || report_fd < 0) {
      std::fprintf(stderr, "graded tests: --gi_key and --gi_report name the grader's descriptors\n");
      return 2;
    }
    auto* reporter = new Reporter(*key, report_fd);
    testing::UnitTest::GetInstance()->listeners().Append(reporter);
    [[maybe_unused]] const int failed = RUN_ALL_TESTS();  // the verdicts are in the report
    reporter->finish(0);
  }
#endif
  return RUN_ALL_TESTS();
}
