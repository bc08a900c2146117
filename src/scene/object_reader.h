// Typed, range-checked reading of one JSON object of the scene file. Every error names the file,
// line, column and JSON pointer; keys nobody asked for are reported with the nearest valid name.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/json_locations.h"
#include "scene/scene.h"

namespace tumble {

struct ParseContext {
  std::string file;               // as the user wrote it, for messages
  const JsonLocations* locations;
};

// Throws tumble::Error(BadInput) "file:line:col: pointer: message".
[[noreturn]] void failAt(const ParseContext& ctx, const std::string& pointer,
                         const std::string& message, bool at_key = false);

struct Range {
  double lo, hi;
  bool lo_open = false, hi_open = false;   // open ends exclude the bound: (0, inf) for masses
};

class ObjectReader {
 public:
  ObjectReader(const ParseContext& ctx, const nlohmann::json& value, std::string pointer);

  bool has(const std::string& key);
  const std::string& pointer() const { return pointer_; }
  std::string pointerOf(const std::string& key) const;
  // Pointer, line and column of a member, for errors raised after loading (mesh import).
  SourceLocation locationOf(const std::string& key) const;

  double number(const std::string& key, double fallback, Range range);
  std::optional<double> optionalNumber(const std::string& key, Range range);
  int integer(const std::string& key, int fallback, int lo, int hi);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::optional<std::string> optionalString(const std::string& key);
  // A fixed-length array of finite numbers, each in `range`.
  std::optional<Eigen::VectorXd> optionalVector(const std::string& key, int size, Range range);
  Eigen::Vector3d vector3(const std::string& key, const Eigen::Vector3d& fallback,
                          Range range = {-1e9, 1e9});
  // An sRGB colour: [r, g, b] in 0..1 or "#rrggbb".
  Eigen::Vector3d colour(const std::string& key, const Eigen::Vector3d& fallback);
  std::optional<ObjectReader> optionalObject(const std::string& key);
  const nlohmann::json* optionalArray(const std::string& key);
  // The member as it is, of any type (for a field that takes more than one), or null.
  const nlohmann::json* optionalValue(const std::string& key) { return get(key); }
  // Element i of the array `key` (read with optionalArray first), as an object.
  ObjectReader element(const std::string& key, std::size_t i);

  // Reports the first key that was never asked for, suggesting the closest asked-for name.
  void rejectUnknownKeys() const;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const nlohmann::json* get(const std::string& key);
  double checkedNumber(const nlohmann::json& v, const std::string& pointer, Range range) const;

  const ParseContext& ctx_;
  const nlohmann::json& value_;
  std::string pointer_;
  std::vector<std::string> known_;
};

std::string describeType(const nlohmann::json& v);   // "a string", "an array", ...
std::string formatNumber(double x);                  // shortest form that reads back the same

}  // namespace tumble
