#include "gi/report/options.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "gi/core/did_you_mean.hpp"
#include "gi/core/number_text.hpp"
#include "gi/report/outputs.hpp"
#include "gi/report/table.hpp"

namespace gi {

namespace {

// The text is checked against the grammar of number_text.hpp before it is converted.
long long parse_integer(const std::string& name, const std::string& text, long long min, long long max) {
  if (!is_whole_number_text(text))
    throw OptionError(name + " expects a whole number such as 64 or -3, got '" + quoted_text(text) + "'");
  errno = 0;
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE)  // past +-9.2e18: out of any option's range, which names the range
    throw OptionError(name + " must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                      quoted_text(text));
  return v;
}

// All of 0 .. 2^64 - 1: strtoull alone would take "-1" as 2^64 - 1.
std::uint64_t parse_unsigned(const std::string& name, const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw OptionError(name + " expects a whole number from 0 to 18446744073709551615, got '" + quoted_text(text) +
                      "'");
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE) throw OptionError(name + " must be at most 18446744073709551615, got " + quoted_text(text));
  return v;
}

double parse_real(const std::string& name, const std::string& text) {
  if (!is_real_number_text(text))
    throw OptionError(name + " expects a decimal number such as 2, -0.5 or 1e-3, got '" + quoted_text(text) + "'");
  const double v = std::strtod(text.c_str(), nullptr);
  if (const RealProblem problem = real_problem(v); problem != RealProblem::None)
    throw OptionError(name + " " + real_problem_text(problem) + ", got '" + quoted_text(text) + "'");
  return v == 0 ? 0.0 : v;  // -0 is 0: nothing downstream prints "-0"
}

template <class T>
std::string range_text(T min, T max) {
  std::ostringstream os;
  os << "[" << min << ", " << max << "]";
  return os.str();
}

template <class T>
void check_range(const std::string& name, T v, T min, T max, const std::string& text) {
  if (v < min || v > max) throw OptionError(name + " must be in " + range_text(min, max) + ", got " + quoted_text(text));
}

}  // namespace

Options::Options(std::string program, std::string summary) : program_(std::move(program)), summary_(std::move(summary)) {}

Options& Options::add_option(Option option) {
  options_.push_back(std::move(option));
  return *this;
}

Options& Options::add(const std::string& name, int& value, const std::string& help, int min, int max) {
  return add_option({name, help, std::to_string(value), range_text(min, max), true,
                     [&value, name, min, max](const std::string& t) {
                       const long long v = parse_integer(name, t, min, max);
                       check_range<long long>(name, v, min, max, t);
                       value = static_cast<int>(v);
                     },
                     "integer", std::to_string(min), std::to_string(max), "", {}, ""});
}

Options& Options::add(const std::string& name, int& value, const std::string& help, int min, int max,
                      const Rule& rule) {
  return add_option({name, help, std::to_string(value), range_text(min, max) + ", " + rule.name, true,
                     [&value, name, min, max, rule](const std::string& t) {
                       const long long v = parse_integer(name, t, min, max);
                       check_range<long long>(name, v, min, max, t);
                       if (!rule.holds(v)) throw OptionError(name + " must be " + rule.name + ", got " + t);
                       value = static_cast<int>(v);
                     },
                     "integer", std::to_string(min), std::to_string(max), rule.name, {}, ""});
}

Options& Options::add(const std::string& name, double& value, const std::string& help, double min, double max) {
  std::ostringstream d;
  d << value;
  return add_option({name, help, d.str(), range_text(min, max), true,
                     [&value, name, min, max](const std::string& t) {
                       const double v = parse_real(name, t);
                       check_range(name, v, min, max, t);
                       value = v;
                     },
                     "real", json_number(min), json_number(max), "", {}, ""});
}

Options& Options::add(const std::string& name, std::uint64_t& value, const std::string& help) {
  return add_option({name, help, std::to_string(value), "", true,
                     [&value, name](const std::string& t) { value = parse_unsigned(name, t); }, "unsigned", "0",
                     "18446744073709551615", "", {}, ""});
}

Options& Options::add(const std::string& name, std::string& value, const std::string& help,
                      std::vector<std::string> choices) {
  std::string listed;
  for (const std::string& c : choices) listed += (listed.empty() ? "" : ", ") + c;
  return add_option({name, help, value, listed.empty() ? "" : "one of: " + listed, true,
                     [&value, name, choices, listed](const std::string& t) {
                       if (t.empty()) throw OptionError(name + " needs a value, got an empty one");
                       if (!choices.empty() && std::find(choices.begin(), choices.end(), t) == choices.end())
                         throw OptionError(name + " must be one of: " + listed + "; got '" + quoted_text(t) + "'");
                       value = t;
                     },
                     choices.empty() ? "text" : "choice", "", "", "", choices, ""});
}

Options& Options::add_flag(const std::string& name, bool& value, const std::string& help) {
  return add_option(
      {name, help, "", "", false, [&value](const std::string&) { value = true; }, "flag", "", "", "", {}, ""});
}

Options& Options::add_optional(const std::string& name, std::optional<int>& value, const std::string& help, int min,
                               int max) {
  return add_option({name, help, "unset", range_text(min, max), true,
                     [&value, name, min, max](const std::string& t) {
                       const long long v = parse_integer(name, t, min, max);
                       check_range<long long>(name, v, min, max, t);
                       value = static_cast<int>(v);
                     },
                     "optional", std::to_string(min), std::to_string(max), "", {}, ""});
}

Options& Options::add_parsed(const std::string& name, const std::string& shape, const std::string& help,
                             std::function<void(const std::string&)> parse) {
  return add_option({name, help, "", "written " + shape, true,
                     [name, parse](const std::string& t) {
                       if (t.empty()) throw OptionError(name + " needs a value, got an empty one");
                       parse(t);
                     },
                     "shaped", "", "", "", {}, shape});
}

const Options::Option* Options::find(const std::string& name) const {
  for (const Option& o : options_)
    if (o.name == name) return &o;
  return nullptr;
}

bool Options::parse(int argc, const char* const* argv) {
  // Each option once: "--width 64 --width 4096" would leave a reader guessing which holds.
  std::vector<const Option*> given;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << help();
      return false;
    }
    if (arg == "--options-json") {
      std::cout << options_json();
      return false;
    }
    std::string value;
    bool has_value = false;
    if (const auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      has_value = true;
    }
    const Option* option = find(arg);
    if (!option) {
      std::vector<std::string> names;
      for (const Option& o : options_) names.push_back(o.name);
      throw OptionError("unknown option '" + quoted_text(arg) + "'" + did_you_mean(arg, names, ""));
    }
    if (std::find(given.begin(), given.end(), option) != given.end())
      throw OptionError(arg + " is given twice; give each option once");
    given.push_back(option);
    if (!option->takes_value) {
      if (has_value) throw OptionError(arg + " takes no value");
      option->set("");
      continue;
    }
    if (!has_value) {
      if (i + 1 >= argc) throw OptionError(arg + " needs a value");
      value = argv[++i];
      // "--out --threads": the value was forgotten. Negative numbers ("-3") pass.
      if (value.rfind("--", 0) == 0) throw OptionError(arg + " needs a value, got the option '" + quoted_text(value) + "'");
    }
    option->set(value);
  }
  return true;
}

std::string Options::help() const {
  std::ostringstream os;
  os << "usage: " << program_ << " [options]\n\n" << summary_ << "\n\noptions:\n";
  std::size_t width = 6;
  for (const Option& o : options_) width = std::max(width, o.name.size() + (o.takes_value ? 6 : 0));
  for (const Option& o : options_) {
    const std::string left = o.name + (o.takes_value ? " VALUE" : "");
    os << "  " << left << std::string(width - left.size() + 2, ' ') << o.help;
    if (!o.default_text.empty()) os << " (default " << o.default_text << ")";
    const bool words = o.range_text.rfind("one of", 0) == 0 || o.range_text.rfind("written", 0) == 0;
    if (!o.range_text.empty()) os << (words ? "; " : ", range ") << o.range_text;
    os << '\n';
  }
  os << "  --help" << std::string(width - 4, ' ') << "print this help and exit\n";
  os << "  --options-json" << std::string(width > 12 ? width - 12 : 1, ' ')
     << "print these options as JSON (what the browser's page builds its form from) and exit\n";
  os << "\nNumbers are decimal, in the digits 0-9: 64, -3, 0.5, .5, 1e-3 (no '+', no hex such as 0x10, no spaces,\n"
        "no inf or nan; a real number is 0 or at least 2.2250738585072014e-308 in size). Each option once.\n";
  return os.str();
}

std::string Options::options_json() const {
  std::ostringstream os;
  os << "{\"program\": " << json_string(program_) << ", \"summary\": " << json_string(summary_) << ", \"options\": [";
  for (std::size_t i = 0; i < options_.size(); ++i) {
    const Option& o = options_[i];
    os << (i ? ",\n  " : "\n  ") << "{\"name\": " << json_string(o.name) << ", \"kind\": " << json_string(o.kind)
       << ", \"default\": " << json_string(o.default_text) << ", \"min\": " << (o.min_json.empty() ? "null" : o.min_json)
       << ", \"max\": " << (o.max_json.empty() ? "null" : o.max_json) << ", \"rule\": " << json_string(o.rule)
       << ", \"choices\": [";
    for (std::size_t c = 0; c < o.choices.size(); ++c) os << (c ? ", " : "") << json_string(o.choices[c]);
    os << "], \"shape\": " << json_string(o.shape) << ", \"help\": " << json_string(o.help) << "}";
  }
  os << "\n]}\n";
  return os.str();
}

void add_common_options(Options& options, CommonOptions& common, const std::string& lesson_name, bool threads,
                        bool seed) {
  common.out = "out/" + lesson_name;
  options.add("--out", common.out, "folder for images, tables (CSV) and charts (SVG)");
  if (threads)
    options.add("--threads", common.threads, "worker threads, 0 = all cores (the output is the same for any number)", 0,
                256);
  if (seed) options.add("--seed", common.seed, "seed of the random numbers (0 to 2^64 - 1)");
}

}  // namespace gi
