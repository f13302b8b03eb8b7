#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gi {

// A bad command line: the message is one line a student can act on.
struct OptionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A condition a whole number must meet besides its range, named for --help and for
// the error: "--resolution must be even, got 33".
struct Rule {
  std::string name;
  std::function<bool(long long)> holds;
};
inline const Rule even{"even", [](long long v) { return v % 2 == 0; }};

// A lesson's command-line options: each is bound to a variable that holds its default.
// Accepts "--name value" and "--name=value", each option once; checks ranges, rules and
// choices. Numbers are spelled as number_text.hpp says (decimal ASCII digits: no "0x10",
// "+5", " 5", "inf" or "nan"), a real one neither infinite nor subnormal. A value
// taken from the next argument may not look like an option ("--out --threads" is a
// missing value, not a folder named --threads), and text may not be empty.
class Options {
 public:
  Options(std::string program, std::string summary);

  Options& add(const std::string& name, int& value, const std::string& help, int min, int max);
  Options& add(const std::string& name, int& value, const std::string& help, int min, int max, const Rule& rule);
  Options& add(const std::string& name, double& value, const std::string& help, double min, double max);
  Options& add(const std::string& name, std::uint64_t& value, const std::string& help);  // [0, 2^64 - 1]
  // Empty `choices` accepts any text.
  Options& add(const std::string& name, std::string& value, const std::string& help,
               std::vector<std::string> choices = {});
  Options& add_flag(const std::string& name, bool& value, const std::string& help);
  Options& add_optional(const std::string& name, std::optional<int>& value, const std::string& help, int min,
                        int max);
  // Text of a shape of its own (`shape`, e.g. "EYE:LOOK_AT[:FOV]", shown in --help),
  // handed to `parse`, which stores it or throws OptionError.
  Options& add_parsed(const std::string& name, const std::string& shape, const std::string& help,
                      std::function<void(const std::string&)> parse);

  // Returns false after printing the help for --help or -h (the lesson then exits 0).
  // Throws OptionError for an unknown option, a missing or malformed value, or a value
  // out of range.
  //
  // --options-json prints the options as JSON instead (options_json) and returns false
  // too: the browser's page builds its form from it.
  bool parse(int argc, const char* const* argv);
  std::string help() const;
  // The option table as JSON, one object per option, in the order of --help:
  //   {"name": "--width", "kind": "integer", "default": "128", "min": 16, "max": 4096,
  //    "rule": "", "choices": [], "shape": "", "help": "..."}
  // kind is one of integer, real, unsigned, text, choice, flag, optional, shaped; a
  // value given by the form is still checked by parse(), which has the last word.
  std::string options_json() const;
  const std::string& summary() const { return summary_; }

 private:
  struct Option {
    std::string name, help, default_text, range_text;
    bool takes_value = true;
    std::function<void(const std::string&)> set;  // parses the text, checks it, stores it
    // What options_json says of it: the kind, the range's ends as JSON numbers
    // ("" for none), the rule's name, the choices, the shape of a parsed text.
    std::string kind, min_json, max_json, rule;
    std::vector<std::string> choices;
    std::string shape;
  };
  Options& add_option(Option option);
  const Option* find(const std::string& name) const;

  std::string program_, summary_;
  std::vector<Option> options_;
};

// The options most lessons have: --out DIR (default out/<lesson>; not empty, not
// starting with '-'), --threads N (0 = all cores) and --seed N. A lesson offers
// --threads and --seed only if it uses them (gi::Lesson decides).
struct CommonOptions {
  std::string out;
  int threads = 0;
  std::uint64_t seed = 1;
};
void add_common_options(Options& options, CommonOptions& common, const std::string& lesson_name, bool threads = true,
                        bool seed = true);

// The one range of --width and --height in every lesson that renders a picture.
constexpr int min_image_size = 16, max_image_size = 4096;

}  // namespace gi
