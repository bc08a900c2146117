#include "scene/suggest.h"

#include <algorithm>
#include <cctype>

namespace tumble {

int editDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      int above = row[j];
      bool same = std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  // About a third of the length: allows "restitusion" and "bodys" but not "mass" for "name".
  int limit = std::clamp((static_cast<int>(word.size()) + 2) / 3, 1, 3);
  std::string best;
  int best_distance = limit + 1;
  for (const std::string& c : candidates) {
    int d = editDistance(word, c);
    // A candidate that contains the word (or is contained) is a likely near miss too: "size" for
    // "size_m", "dt" for "dt_s".
    if (d > limit && (c.find(word) != std::string::npos || word.find(c) != std::string::npos) &&
        std::min(c.size(), word.size()) >= 2)
      d = limit;
    if (d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace tumble
