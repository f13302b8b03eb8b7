#include "support/process.hpp"

#include <algorithm>

namespace gi_test {

std::vector<std::string> shell_words(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ' ' || c == '\t' || c == '\n') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
      continue;
    }
    in_word = true;
    if (c == '\'') {
      const std::size_t end = std::min(text.find('\'', i + 1), text.size());
      word += text.substr(i + 1, end - i - 1);
      i = end;
    } else if (c == '"') {
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '"' || text[i + 1] == '\\')) ++i;
        word += text[i];
      }
    } else if (c == '\\' && i + 1 < text.size()) {
      word += text[++i];
    } else {
      word += c;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

// GI_TEST_EMULATOR: the emulator's words, separated by '|' (tests/support/CMakeLists.txt).
std::vector<std::string> emulated(const std::vector<std::string>& command) {
  std::vector<std::string> full;
#if defined(GI_TEST_EMULATOR)
  const std::string emulator = GI_TEST_EMULATOR;
  for (std::size_t at = 0; at < emulator.size();) {
    const std::size_t bar = std::min(emulator.find('|', at), emulator.size());
    full.push_back(emulator.substr(at, bar - at));
    at = bar + 1;
  }
#endif
  full.insert(full.end(), command.begin(), command.end());
  return full;
}

std::vector<std::string> exits_at_once() {
#if defined(_WIN32)
  return {"cmd.exe", "/c", "exit 0"};
#else
  return {"/bin/sh", "-c", "exit 0"};
#endif
}

}  // namespace gi_test
