// nlohmann::json forgets where values were written. This second, tolerant pass over the text maps
// each JSON pointer to the line and column of its value (and of its key), so that validation
// errors can read "scene.json:12:7: /bodies/1/restitution: ...". Comments (// and /* */) are
// skipped, as the loader accepts them.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>

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

 private:
  void scanValue(const std::string& pointer);
  void scanObject(const std::string& pointer);
  void scanArray(const std::string& pointer);
  void skipString();
  void skipSpace();

  std::string_view text_;
  std::size_t at_ = 0;
  std::map<std::string, std::size_t> values_, keys_;
};

// Escapes a member name for a JSON pointer (RFC 6901: "~" -> "~0", "/" -> "~1").
std::string pointerToken(const std::string& key);

}  // namespace tumble
