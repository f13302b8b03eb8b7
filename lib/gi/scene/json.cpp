#include "gi/scene/json.hpp"

#include <cctype>
#include <cmath>

#include "gi/core/decimal.hpp"
#include "gi/core/number_text.hpp"
#include "gi/scene/utf8.hpp"

namespace gi {

namespace {

class Parser {
 public:
  Parser(std::string_view text, const std::string& file, const JsonLimits& limits)
      : text_(text), file_(file), limits_(limits) {}

  JsonValue document() {
    if (text_.size() > limits_.max_bytes)
      throw SceneError(file_, "larger than " + size_text(limits_.max_bytes) +
                                  "; put large meshes in an OBJ file (\"meshes\")");
    check_utf8();
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;  // a byte-order mark, which some editors write
    skip_space();
    JsonValue v = value(0);
    skip_space();
    if (!at_end()) fail("text after the end of the JSON value: " + shown());
    return v;
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }

  // Every byte is consumed here, so the line and column stay right: a column is
  // counted at each character's first byte.
  void advance() {
    const auto byte = static_cast<unsigned char>(text_[pos_++]);
    if (byte == '\n') {
      ++line_, column_ = 1;
    } else if ((byte & 0xC0) != 0x80) {
      ++column_;
    }
  }

  [[noreturn]] void fail(const std::string& message) const { throw SceneError({file_, line_, column_, ""}, message); }

  // The character at the current position, quoted, for messages.
  std::string shown() const {
    if (at_end()) return "the end of the file";
    const unsigned char c = static_cast<unsigned char>(peek());
    if (c < 0x20 || c == 0x7F) return "a control character (code " + std::to_string(c) + ")";
    return "'" + std::string(text_.substr(pos_, utf8_length(text_, pos_))) + "'";
  }

  void check_utf8() {
    while (!at_end()) {
      const std::size_t n = utf8_length(text_, pos_);
      if (n == 0) {
        static const char digits[] = "0123456789abcdef";
        const auto b = static_cast<unsigned char>(peek());
        fail(std::string("the file is not UTF-8 text (byte 0x") + digits[b >> 4] + digits[b & 15] + ")");
      }
      for (std::size_t k = 0; k < n; ++k) advance();
    }
    pos_ = 0, line_ = 1, column_ = 1;
  }

  void skip_space() {
    while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) advance();
  }

  void expect(char c, const std::string& context) {
    if (at_end() || peek() != c) fail("expected '" + std::string(1, c) + "' " + context + ", got " + shown());
    advance();
  }

  JsonValue value(int depth) {
    if (++values_ > limits_.max_values)
      fail("more than " + std::to_string(limits_.max_values) + " values; put large meshes in an OBJ file (\"meshes\")");
    JsonValue v;
    v.line = line_, v.column = column_;
    if (at_end()) fail("expected a value, got the end of the file");
    const char c = peek();
    if (c == '{' || c == '[') {
      if (depth >= limits_.max_depth)
        fail("nested deeper than " + std::to_string(limits_.max_depth) + " arrays and objects");
      c == '{' ? object(v, depth + 1) : array(v, depth + 1);
    } else if (c == '"') {
      v.kind = JsonValue::Kind::String;
      v.text = string();
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      v.kind = JsonValue::Kind::Number;
      v.number = number();
    } else {
      literal(v);
    }
    return v;
  }

  void object(JsonValue& v, int depth) {
    v.kind = JsonValue::Kind::Object;
    advance();
    skip_space();
    if (!at_end() && peek() == '}') return advance();
    while (true) {
      if (at_end() || peek() != '"')
        fail(!at_end() && peek() == '}' ? "a comma before '}': JSON allows none after the last member"
                                        : "expected a key in double quotes, got " + shown());
      JsonMember m;
      m.line = line_, m.column = column_;
      m.key = string();
      skip_space();
      expect(':', "after the key \"" + m.key + "\"");
      skip_space();
      m.value = value(depth);
      v.members.push_back(std::move(m));
      skip_space();
      if (!at_end() && peek() == ',') {
        advance();
        skip_space();
        continue;
      }
      return expect('}', "or ',' after the value of \"" + v.members.back().key + "\"");
    }
  }

  void array(JsonValue& v, int depth) {
    v.kind = JsonValue::Kind::Array;
    advance();
    skip_space();
    if (!at_end() && peek() == ']') return advance();
    while (true) {
      if (!at_end() && peek() == ']') fail("a comma before ']': JSON allows none after the last item");
      v.items.push_back(value(depth));
      skip_space();
      if (!at_end() && peek() == ',') {
        advance();
        skip_space();
        continue;
      }
      return expect(']', "or ',' after an item of the array");
    }
  }

  unsigned hex4() {
    unsigned code = 0;
    for (int k = 0; k < 4; ++k) {
      if (at_end() || !std::isxdigit(static_cast<unsigned char>(peek())))
        fail("expected four hexadecimal digits after \\u, got " + shown());
      const char h = peek();
      code = 16 * code + static_cast<unsigned>(h <= '9' ? h - '0' : (h | 0x20) - 'a' + 10);
      advance();
    }
    return code;
  }

  std::string string() {
    const int line = line_, column = column_;
    advance();  // the opening quote
    std::string out;
    while (true) {
      if (at_end())
        fail("the string that starts at line " + std::to_string(line) + ", column " + std::to_string(column) +
             " never ends");
      const char c = peek();
      if (c == '"') break;
      if (static_cast<unsigned char>(c) < 0x20) fail("a control character inside a string; write \\n for a new line");
      if (c != '\\') {
        out += c;
        advance();
        continue;
      }
      advance();
      if (at_end()) continue;  // reported as a string that never ends
      const char e = peek();
      const std::string_view simple = "\"\\/bfnrt", meaning = "\"\\/\b\f\n\r\t";
      if (const std::size_t k = simple.find(e); k != std::string_view::npos) {
        out += meaning[k];
        advance();
      } else if (e == 'u') {
        advance();
        unsigned code = hex4();
        if (code >= 0xDC00 && code <= 0xDFFF) fail("\\u escape: a low surrogate without a high one");
        if (code >= 0xD800 && code <= 0xDBFF) {  // a pair encodes one character past U+FFFF
          if (at_end() || peek() != '\\') fail("\\u escape: a high surrogate must be followed by a low one");
          advance();
          expect('u', "for the low surrogate");
          const unsigned low = hex4();
          if (low < 0xDC00 || low > 0xDFFF) fail("\\u escape: a high surrogate must be followed by a low one");
          code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        }
        append_utf8(out, code);
      } else {
        fail("unknown escape \\" + std::string(1, e) + " (JSON has \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\uXXXX)");
      }
    }
    advance();  // the closing quote
    return out;
  }

  double number() {
    const std::size_t start = pos_;
    const auto digits = [&] {
      std::size_t n = 0;
      for (; !at_end() && peek() >= '0' && peek() <= '9'; ++n) advance();
      return n;
    };
    if (peek() == '-') advance();
    if (!at_end() && peek() == 'I') fail("Infinity is not a number JSON allows; write a finite number");
    if (at_end() || !(peek() >= '0' && peek() <= '9')) fail("expected a digit after '-', got " + shown());
    if (peek() == '0') {
      advance();
      if (!at_end() && peek() >= '0' && peek() <= '9') fail("a number may not start with 0 (write 7, not 07)");
    } else {
      digits();
    }
    if (!at_end() && peek() == '.') {
      advance();
      if (digits() == 0) fail("expected a digit after the decimal point, got " + shown());
    }
    if (!at_end() && (peek() == 'e' || peek() == 'E')) {
      advance();
      if (!at_end() && (peek() == '+' || peek() == '-')) advance();
      if (digits() == 0) fail("expected a digit in the exponent, got " + shown());
    }
    const std::string_view token = text_.substr(start, pos_ - start);
    double v = 0;
    const auto [end, error] = read_decimal(token.data(), token.data() + token.size(), v);
    if (error == std::errc::result_out_of_range || (error == std::errc() && !std::isfinite(v)))
      throw SceneError({file_, line_, column_ - static_cast<int>(token.size()), ""},
                       "the number " + std::string(token.substr(0, 40)) + " is out of the range of a double");
    if (error != std::errc() || end != token.data() + token.size()) fail("cannot read the number");
    if (real_problem(v) == RealProblem::Subnormal)
      throw SceneError({file_, line_, column_ - static_cast<int>(token.size()), ""},
                       "the number " + std::string(token.substr(0, 40)) + " " + real_problem_text(real_problem(v)));
    return v == 0 ? 0.0 : v;  // -0 is 0
  }

  void literal(JsonValue& v) {
    const std::string_view rest = text_.substr(pos_);
    const auto word = [&](std::string_view w) { return rest.substr(0, w.size()) == w; };
    for (std::string_view w : {"NaN", "nan", "Infinity", "inf"})
      if (word(w)) fail(std::string(w) + " is not a number JSON allows; write a finite number");
    std::string_view w;
    if (word("true") || word("false")) {
      v.kind = JsonValue::Kind::Boolean;
      v.boolean = word("true");
      w = v.boolean ? "true" : "false";
    } else if (word("null")) {
      w = "null";
    } else {
      fail("expected a value, got " + shown() + (peek() == '\'' ? " (JSON strings take double quotes)" : ""));
    }
    for (std::size_t n = 0; n < w.size(); ++n) advance();
  }

  std::string_view text_;
  const std::string& file_;
  JsonLimits limits_;
  std::size_t pos_ = 0, values_ = 0;
  int line_ = 1, column_ = 1;
};

}  // namespace

std::string kind_name(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::Null: return "null";
    case JsonValue::Kind::Boolean: return "true or false";
    case JsonValue::Kind::Number: return "a number";
    case JsonValue::Kind::String: return "a string";
    case JsonValue::Kind::Array: return "an array";
    case JsonValue::Kind::Object: return "an object";
  }
  return "a value";
}

std::string size_text(std::uintmax_t bytes) {
  return bytes % (1u << 20) == 0 ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}

JsonValue parse_json(std::string_view text, const std::string& file, const JsonLimits& limits) {
  return Parser(text, file, limits).document();
}

}  // namespace gi
