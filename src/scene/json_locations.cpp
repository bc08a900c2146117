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
  // The scan never throws: on malformed text it simply stops; nlohmann reports syntax errors.
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
  if (c == '{') return scanObject(pointer);
  if (c == '[') return scanArray(pointer);
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
    keys_.emplace(child, key_at);
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

TextPosition JsonLocations::positionOf(std::size_t offset) const {
  TextPosition pos{1, 1};
  for (std::size_t i = 0; i < offset && i < text_.size(); ++i) {
    if (text_[i] == '\n') {
      ++pos.line;
      pos.column = 1;
    } else {
      ++pos.column;
    }
  }
  return pos;
}

}  // namespace tumble
