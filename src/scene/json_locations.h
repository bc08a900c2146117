// nlohmann::json forgets where values were written. This second, tolerant pass over the text maps
// each JSON pointer to the line and column of its value (and of its key), so that validation
// errors can read "scene.json:12:7: /bodies/1/restitution: ...". Comments (// and /* */) are
// skipped, as the loader accepts them.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tumble {

struct TextPosition {
  int line = 0, column = 0;   // 1-based; 0 when unknown
};

class JsonLocations {
 public:
  explicit JsonLocations(std::string_view text);
  // Position of the value at `pointer` ("" is the root); of its key when `key` is true and the
  // value is an object member. Falls back to the nearest enclosing value that is known.
  TextPosition find(const std::string& pointer, bool key = false) const;
  // Line and column of a byte offset into the text.
  TextPosition positionOf(std::size_t offset) const;

  // Byte offset of the first value whose text starts with `spelling` (npos if none): where a
  // number nlohmann could not hold ("1e999") was written.
  std::size_t firstValueSpelled(std::string_view spelling) const;

  // Scene files nest a few levels; the scan stops descending at kMaxDepth (so a hostile file
  // cannot exhaust the stack) and remembers where the first too-deep value starts.
  static constexpr int kMaxDepth = 100;
  bool tooDeep() const { return too_deep_at_ != std::string_view::npos; }
  std::size_t tooDeepAt() const { return too_deep_at_; }
  // nlohmann keeps the last of repeated keys silently; a scene that sets a field twice is
  // ambiguous, so the loader refuses it. The pointer of the first repeat ("" if none).
  const std::string& firstDuplicateKey() const { return duplicate_; }

 private:
  void scanValue(const std::string& pointer);
  void scanObject(const std::string& pointer);
  void scanArray(const std::string& pointer);
  void skipString();
  void skipSpace();

  std::string_view text_;
  std::size_t at_ = 0;
  std::vector<std::size_t> line_starts_;   // byte offset of each line's first character
  int depth_ = 0;
  std::size_t too_deep_at_ = std::string_view::npos;
  std::string duplicate_;
  std::map<std::string, std::size_t> values_, keys_;
};

// Escapes a member name for a JSON pointer (RFC 6901: "~" -> "~0", "/" -> "~1").
std::string pointerToken(const std::string& key);

}  // namespace tumble
