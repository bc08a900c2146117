// "Did you mean ...?" for misspelled keys and enum values.
#pragma once

#include <string>
#include <vector>

namespace tumble {

// Edit distance (Levenshtein: insertions, deletions, substitutions each cost 1).
int editDistance(const std::string& a, const std::string& b);
// The candidate closest to `word`, if it is close enough to be a plausible misspelling
// (distance at most a third of the word's length, at least 1... at most 3); "" otherwise.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace tumble
