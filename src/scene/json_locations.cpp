#include "scene/json_locations.h"

#include <algorithm>

namespace tumble {

std::string pointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

JsonLocations::JsonLocations(std::string_view text) : text_(text) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n') line_starts_.push_back(i + 1);
  // The scan never throws: on malformed text it simply stops; nlohmann reports syntax errors.
  // A UTF-8 byte order mark (some Windows editors write one) is not part of the JSON text.
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;
  skipSpace();
  if (at_ < text_.size()) scanValue("");
}

void JsonLocations::skipSpace() {
  while (at_ < text_.size()) {
    char c = text_[at_];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++at_;
    } else if (c == '/' && at_ + 1 < text_.size() && text_[at_ + 1] == '/') {
      while (at_ < text_.size() && text_[at_] != '\n') ++at_;
    } else if (c == '/' && at_ + 1 < text_.size() && text_[at_ + 1] == '*') {
      std::size_t end = text_.find("*/", at_ + 2);
      at_ = end == std::string_view::npos ? text_.size() : end + 2;
    } else {
      return;
    }
  }
}

void JsonLocations::skipString() {
  ++at_;  // opening quote
  while (at_ < text_.size() && text_[at_] != '"') at_ += text_[at_] == '\\' ? 2 : 1;
  ++at_;  // closing quote
}

void JsonLocations::scanValue(const std::string& pointer) {
  values_.emplace(pointer, at_);
  if (at_ >= text_.size()) return;
  char c = text_[at_];
  if (c == '{' || c == '[') {
    if (depth_ >= kMaxDepth) {
      if (!tooDeep()) too_deep_at_ = at_;
      at_ = text_.size();   // stop: nothing deeper is looked at
      return;
    }
    ++depth_;
    c == '{' ? scanObject(pointer) : scanArray(pointer);
    --depth_;
    return;
  }
  if (c == '"') return skipString();
  // number or literal: runs until a delimiter
  while (at_ < text_.size() && std::string_view(",]} \t\r\n/").find(text_[at_]) == std::string_view::npos)
    ++at_;
}

void JsonLocations::scanObject(const std::string& pointer) {
  ++at_;
  for (skipSpace(); at_ < text_.size() && text_[at_] != '}'; skipSpace()) {
    if (text_[at_] != '"') return;
    std::size_t key_at = at_;
    skipString();
    std::string raw(text_.substr(key_at + 1, std::min(at_, text_.size()) - key_at - 2));
    // Keys with escapes are rare in scene files; they keep their raw spelling here.
    std::string child = pointer + "/" + pointerToken(raw);
    if (!keys_.emplace(child, key_at).second && duplicate_.empty()) {
      duplicate_ = child;
      keys_[child] = key_at;   // errors about the field point at its repeat
    }
    skipSpace();
    if (at_ >= text_.size() || text_[at_] != ':') return;
    ++at_;
    skipSpace();
    scanValue(child);
    skipSpace();
    if (at_ < text_.size() && text_[at_] == ',') ++at_;
  }
  ++at_;
}

void JsonLocations::scanArray(const std::string& pointer) {
  ++at_;
  int index = 0;
  for (skipSpace(); at_ < text_.size() && text_[at_] != ']'; skipSpace()) {
    std::size_t before = at_;
    scanValue(pointer + "/" + std::to_string(index++));
    skipSpace();
    if (at_ < text_.size() && text_[at_] == ',') ++at_;
    if (at_ == before) return;  // no progress: malformed
  }
  ++at_;
}

TextPosition JsonLocations::find(const std::string& pointer, bool key) const {
  std::string p = pointer;
  for (;;) {
    const auto& table = key && p == pointer ? keys_ : values_;
    if (auto it = table.find(p); it != table.end()) return positionOf(it->second);
    if (p.empty()) return {};
    p.erase(p.rfind('/'));
  }
}

std::size_t JsonLocations::firstValueSpelled(std::string_view spelling) const {
  std::size_t first = std::string_view::npos;
  for (const auto& [pointer, at] : values_)
    if (at < first && text_.substr(at, spelling.size()) == spelling) first = at;
  return first;
}

TextPosition JsonLocations::positionOf(std::size_t offset) const {
  // Binary search in the line starts: errors about many keys of a large file stay fast.
  offset = std::min(offset, text_.size());
  auto after = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  std::size_t line = static_cast<std::size_t>(after - line_starts_.begin());   // >= 1: starts hold 0
  return {static_cast<int>(line), static_cast<int>(offset - line_starts_[line - 1]) + 1};
}

}  // namespace tumble
