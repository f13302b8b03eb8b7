// The syntax layer of the scene reader: values, their positions, and one test per
// message, the whole line compared.
#include "gi/scene/json.hpp"
#include "gi/scene/utf8.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using Kind = gi::JsonValue::Kind;

std::string error_of(const std::string& text, const gi::JsonLimits& limits = {}) {
  try {
    (void)gi::parse_json(text, "f.json", limits);
  } catch (const gi::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Json, ValuesAndWhereEachStarts) {
  const gi::JsonValue v = gi::parse_json("{\n  \"a\": [1, -2.5e3, true],\n  \"b\": {\"c\": null, \"d\": \"x\"}\n}", "f");
  ASSERT_EQ(v.kind, Kind::Object);
  ASSERT_EQ(v.members.size(), 2u);
  const gi::JsonMember& a = v.members[0];
  EXPECT_EQ(a.key, "a");
  EXPECT_EQ(a.line, 2);
  EXPECT_EQ(a.column, 3);
  ASSERT_EQ(a.value.items.size(), 3u);
  EXPECT_EQ(a.value.items[1].number, -2500.0);
  EXPECT_EQ(a.value.items[1].line, 2);
  EXPECT_EQ(a.value.items[1].column, 12);
  EXPECT_TRUE(a.value.items[2].boolean);
  const gi::JsonValue& b = v.members[1].value;
  EXPECT_EQ(b.members[0].value.kind, Kind::Null);
  EXPECT_EQ(b.members[1].value.text, "x");
  EXPECT_EQ(b.members[1].value.line, 3);
  EXPECT_EQ(b.members[1].value.column, 25);
}

TEST(Json, NumbersReadExactlyAsTheCompilerReadsThem) {
  for (const char* text : {"0.1", "0.7200000000000001", "1e-300", "-0", "39.30764811610661", "123456789012345678"}) {
    EXPECT_EQ(gi::parse_json(text, "f").number, std::strtod(text, nullptr)) << text;
  }
}

TEST(Json, StringsUnescapeAndColumnsCountCharacters) {
  const gi::JsonValue v = gi::parse_json(R"(["tab\there", "\u00e9\ud83d\ude00", "\"\\\/"])", "f");
  EXPECT_EQ(v.items[0].text, "tab\there");
  EXPECT_EQ(v.items[1].text, "\xC3\xA9\xF0\x9F\x98\x80");  // é and an emoji, from escapes
  EXPECT_EQ(v.items[2].text, "\"\\/");
  // Two characters of two bytes each before the value: its column is 8, not 10.
  const gi::JsonValue w = gi::parse_json("[\"\xC3\xA9\xC3\xA9\", 1]", "f");
  EXPECT_EQ(w.items[1].column, 8);
  EXPECT_EQ(gi::parse_json("\xEF\xBB\xBF{}", "f").kind, Kind::Object);  // a byte-order mark
}

TEST(Json, DuplicateKeysAreKeptForTheSchemaToRefuse) {
  EXPECT_EQ(gi::parse_json(R"({"a": 1, "a": 2})", "f").members.size(), 2u);
}

// One test per syntax error, the whole line compared.
TEST(Json, SyntaxErrorsNameTheirPosition) {
  const std::pair<const char*, const char*> cases[] = {
      {"", "f.json:1:1: expected a value, got the end of the file"},
      {"{\"a\": 1", "f.json:1:8: expected '}' or ',' after the value of \"a\", got the end of the file"},
      {"{\"a\" 1}", "f.json:1:6: expected ':' after the key \"a\", got '1'"},
      {"{a: 1}", "f.json:1:2: expected a key in double quotes, got 'a'"},
      {"{\"a\": 1,}", "f.json:1:9: a comma before '}': JSON allows none after the last member"},
      {"[1, 2,]", "f.json:1:7: a comma before ']': JSON allows none after the last item"},
      {"[1 2]", "f.json:1:4: expected ']' or ',' after an item of the array, got '2'"},
      {"{\"r\": NaN}", "f.json:1:7: NaN is not a number JSON allows; write a finite number"},
      {"[-Infinity]", "f.json:1:3: Infinity is not a number JSON allows; write a finite number"},
      {"[1e400]", "f.json:1:2: the number 1e400 is out of the range of a double"},
      {"[-1e999]", "f.json:1:2: the number -1e999 is out of the range of a double"},
      {"[1e-320]", "f.json:1:2: the number 1e-320 must be 0 or at least 2.2250738585072014e-308 in size (a smaller "
                   "double has lost digits)"},
      {"[0x10]", "f.json:1:3: expected ']' or ',' after an item of the array, got 'x'"},
      {"[+1]", "f.json:1:2: expected a value, got '+'"},
      {"[07]", "f.json:1:3: a number may not start with 0 (write 7, not 07)"},
      {"[1.]", "f.json:1:4: expected a digit after the decimal point, got ']'"},
      {"[1e]", "f.json:1:4: expected a digit in the exponent, got ']'"},
      {"[-]", "f.json:1:3: expected a digit after '-', got ']'"},
      {"['a']", "f.json:1:2: expected a value, got ''' (JSON strings take double quotes)"},
      {"[tru]", "f.json:1:2: expected a value, got 't'"},
      {"\"abc", "f.json:1:5: the string that starts at line 1, column 1 never ends"},
      {"\"a\nb\"", "f.json:1:3: a control character inside a string; write \\n for a new line"},
      {"\"\\q\"", "f.json:1:3: unknown escape \\q (JSON has \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX)"},
      {"\"\\u12g4\"", "f.json:1:6: expected four hexadecimal digits after \\u, got 'g'"},
      {"\"\\udc00\"", "f.json:1:8: \\u escape: a low surrogate without a high one"},
      {"\"\\ud83d x\"", "f.json:1:8: \\u escape: a high surrogate must be followed by a low one"},
      {"{} {}", "f.json:1:4: text after the end of the JSON value: '{'"},
      {"\n\n  [1, \xFF]", "f.json:3:7: the file is not UTF-8 text (byte 0xff)"},
      {"[\"\xC0\xAF\"]", "f.json:1:3: the file is not UTF-8 text (byte 0xc0)"},      // an overlong '/'
      {"[\"\xED\xA0\x80\"]", "f.json:1:3: the file is not UTF-8 text (byte 0xed)"},  // a surrogate
      {"[\x01]", "f.json:1:2: expected a value, got a control character (code 1)"},
  };
  for (const auto& [text, message] : cases) EXPECT_EQ(error_of(text), message) << "input: " << text;
}

TEST(Json, LimitsStopHostileFilesBeforeTheyCostTimeOrMemory) {
  gi::JsonLimits small;
  small.max_depth = 8;
  small.max_values = 10;
  small.max_bytes = 64;
  EXPECT_EQ(error_of("[[[[[[[[[1]]]]]]]]]", small), "f.json:1:9: nested deeper than 8 arrays and objects");
  EXPECT_EQ(error_of("[1,2,3,4,5,6,7,8,9,10]", small),
            "f.json:1:20: more than 10 values; put large meshes in an OBJ file (\"meshes\")");
  EXPECT_EQ(error_of(std::string(65, ' '), small),
            "f.json: larger than 64 bytes; put large meshes in an OBJ file (\"meshes\")");
  // The default depth, 64, against a file of a million brackets: refused at the 65th.
  EXPECT_EQ(error_of(std::string(1'000'000, '[')), "f.json:1:65: nested deeper than 64 arrays and objects");
  // The default count, a million values: the array and 999 999 zeros pass, the next
  // zero (at column 2 000 000) does not.
  std::string zeros = "[0";
  for (int i = 1; i < 1'000'000; ++i) zeros += ",0";
  EXPECT_EQ(error_of(zeros + "]"), "f.json:1:2000000: more than 1000000 values; put large meshes in an OBJ file "
                                   "(\"meshes\")");
}

TEST(Json, MessagesQuoteInputAsOnePrintableLine) {
  // printable: UTF-8 characters stay, control characters and stray bytes become \xNN.
  EXPECT_EQ(gi::printable("caf\xC3\xA9 \xF0\x9F\x98\x80"), "caf\xC3\xA9 \xF0\x9F\x98\x80");
  EXPECT_EQ(gi::printable(std::string("a\nb\0c\x1b[1m\x7f\xFF\xC3", 12)), "a\\x0ab\\x00c\\x1b[1m\\x7f\\xff\\xc3");
  // C1 controls (U+009B is the terminal's one-byte escape) and bidirectional overrides.
  EXPECT_EQ(gi::printable("a\xC2\x9B" "2Jb"), "a\\xc2\\x9b2Jb");
  EXPECT_EQ(gi::printable("\xE2\x80\xAEtxt.exe"), "\\xe2\\x80\\xaetxt.exe");  // U+202E RIGHT-TO-LEFT OVERRIDE
  EXPECT_EQ(gi::printable("\xE2\x81\xA6x"), "\\xe2\\x81\\xa6x");              // U+2066 LEFT-TO-RIGHT ISOLATE
  // A name that a JSON escape filled with a newline and a NUL: the error is one line,
  // and the NUL no longer ends it (what() is a C string).
  const gi::SceneError e({"f.json", 3, 7, "materials[0]"}, "no material is named 'a\nb" + std::string(1, '\0') + "c'");
  EXPECT_EQ(std::string(e.what()), "f.json:3:7: materials[0]: no material is named 'a\\x0ab\\x00c'");
}
