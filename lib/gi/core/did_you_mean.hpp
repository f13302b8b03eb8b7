#pragma once
#include <algorithm>
#include <string>
#include <vector>

namespace gi {

// Levenshtein's edit distance: the fewest insertions, deletions and substitutions of
// one character that turn `a` into `b`.
inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// " (did you mean 'radius'?)" for the candidate nearest to a typo, when it is at
// most 3 edits away; else "". Long words are cut first: a typo is short.
inline std::string did_you_mean(const std::string& typo, const std::vector<std::string>& candidates,
                                const std::string& quote = "'") {
  const std::string word = typo.substr(0, 64);
  const std::string* nearest = nullptr;
  std::size_t best = 4;
  for (const std::string& c : candidates)
    if (const std::size_t d = edit_distance(word, c); d < best) best = d, nearest = &c;
  return nearest ? " (did you mean " + quote + *nearest + quote + "?)" : "";
}

}  // namespace gi
