#include "scene/object_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "base/error.h"
#include "scene/scene_patch.h"
#include "scene/suggest.h"

namespace tumble {

void failAt(const ParseContext& ctx, const std::string& pointer, const std::string& message,
            bool at_key) {
  if (ctx.edits) failInEdit(*ctx.edits, pointer, message, at_key);   // returns if no edit wrote it
  TextPosition pos = ctx.locations ? ctx.locations->find(pointer, at_key) : TextPosition{};
  std::string where = ctx.file;
  if (pos.line > 0) where += ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
  std::string path = pointer.empty() ? "(top level)" : pointer;
  throw Error(ExitCode::BadInput, where + ": " + path + ": " + message);
}

std::string describeType(const nlohmann::json& v) {
  switch (v.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string (\"" + v.get<std::string>() + "\")";
    case nlohmann::json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    default: return "a number";
  }
}

std::string formatNumber(double x) {
  // Whole numbers as people write them (100000, not 1e+05); others in shortest round-trip form.
  if (x == std::floor(x) && std::abs(x) < 1e15) return std::to_string(static_cast<long long>(x));
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

ObjectReader::ObjectReader(const ParseContext& ctx, const nlohmann::json& value, std::string pointer)
    : ctx_(ctx), value_(value), pointer_(std::move(pointer)) {
  if (!value_.is_object())
    failAt(ctx_, pointer_, "expected an object {...}, got " + describeType(value_));
}

std::string ObjectReader::pointerOf(const std::string& key) const {
  return pointer_ + "/" + pointerToken(key);
}

SourceLocation ObjectReader::locationOf(const std::string& key) const {
  SourceLocation loc;
  loc.pointer = pointerOf(key);
  if (ctx_.locations) {
    TextPosition pos = ctx_.locations->find(loc.pointer);
    loc.line = pos.line;
    loc.column = pos.column;
  }
  return loc;
}

void ObjectReader::fail(const std::string& key, const std::string& message) const {
  failAt(ctx_, key.empty() ? pointer_ : pointerOf(key), message);
}

const nlohmann::json* ObjectReader::get(const std::string& key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
  auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

bool ObjectReader::has(const std::string& key) { return get(key) != nullptr; }

double ObjectReader::checkedNumber(const nlohmann::json& v, const std::string& pointer,
                                   Range range) const {
  if (!v.is_number()) failAt(ctx_, pointer, "expected a number, got " + describeType(v));
  double x = v.get<double>();
  // JSON has no NaN or Inf, but a huge exponent (1e999) parses to Inf.
  if (!std::isfinite(x)) failAt(ctx_, pointer, "the number is not finite (too large)");
  bool below = range.lo_open ? x <= range.lo : x < range.lo;
  bool above = range.hi_open ? x >= range.hi : x > range.hi;
  if (below || above) {
    std::string interval = std::string(range.lo_open ? "(" : "[") + formatNumber(range.lo) + ", " +
                           (std::isinf(range.hi) ? "inf" : formatNumber(range.hi)) +
                           (range.hi_open || std::isinf(range.hi) ? ")" : "]");
    failAt(ctx_, pointer, formatNumber(x) + " is outside " + interval);
  }
  return x;
}

double ObjectReader::number(const std::string& key, double fallback, Range range) {
  return optionalNumber(key, range).value_or(fallback);
}

std::optional<double> ObjectReader::optionalNumber(const std::string& key, Range range) {
  const nlohmann::json* v = get(key);
  if (!v) return std::nullopt;
  return checkedNumber(*v, pointerOf(key), range);
}

int ObjectReader::integer(const std::string& key, int fallback, int lo, int hi) {
  const nlohmann::json* v = get(key);
  if (!v) return fallback;
  double x = checkedNumber(*v, pointerOf(key), {double(lo), double(hi)});
  if (x != std::floor(x)) fail(key, "expected a whole number, got " + formatNumber(x));
  return static_cast<int>(x);
}

bool ObjectReader::boolean(const std::string& key, bool fallback) {
  const nlohmann::json* v = get(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(key, "expected true or false, got " + describeType(*v));
  return v->get<bool>();
}

std::optional<std::string> ObjectReader::optionalString(const std::string& key) {
  const nlohmann::json* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) fail(key, "expected a string, got " + describeType(*v));
  return v->get<std::string>();
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) {
  return optionalString(key).value_or(fallback);
}

std::optional<Eigen::VectorXd> ObjectReader::optionalVector(const std::string& key, int size,
                                                            Range range) {
  const nlohmann::json* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_array() || static_cast<int>(v->size()) != size)
    fail(key, "expected an array of " + std::to_string(size) + " numbers, got " +
                  (v->is_array() ? "an array of " + std::to_string(v->size()) : describeType(*v)));
  Eigen::VectorXd out(size);
  for (int i = 0; i < size; ++i)
    out[i] = checkedNumber((*v)[i], pointerOf(key) + "/" + std::to_string(i), range);
  return out;
}

Eigen::Vector3d ObjectReader::vector3(const std::string& key, const Eigen::Vector3d& fallback,
                                      Range range) {
  auto v = optionalVector(key, 3, range);
  return v ? Eigen::Vector3d(*v) : fallback;
}

Eigen::Vector3d ObjectReader::colour(const std::string& key, const Eigen::Vector3d& fallback) {
  const nlohmann::json* v = get(key);
  if (!v) return fallback;
  if (v->is_string()) {
    std::string s = v->get<std::string>();
    bool ok = s.size() == 7 && s[0] == '#' &&
              s.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos;
    if (!ok) fail(key, "expected \"#rrggbb\" or [r, g, b] in 0..1, got \"" + s + "\"");
    Eigen::Vector3d c;
    for (int i = 0; i < 3; ++i) c[i] = std::stoi(s.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;
    return c;
  }
  return *optionalVector(key, 3, {0, 1});
}

std::optional<ObjectReader> ObjectReader::optionalObject(const std::string& key) {
  const nlohmann::json* v = get(key);
  if (!v) return std::nullopt;
  return ObjectReader(ctx_, *v, pointerOf(key));
}

const nlohmann::json* ObjectReader::optionalArray(const std::string& key) {
  const nlohmann::json* v = get(key);
  if (v && !v->is_array()) fail(key, "expected an array [...], got " + describeType(*v));
  return v;
}

ObjectReader ObjectReader::element(const std::string& key, std::size_t i) {
  const nlohmann::json& item = (*get(key))[i];
  const std::string at = pointerOf(key) + "/" + std::to_string(i);
  if (!item.is_object()) ObjectReader(ctx_, value_, at).fail("", "expected an object {...}, got " + describeType(item));
  return ObjectReader(ctx_, item, at);
}

void ObjectReader::rejectUnknownKeys() const {
  // Of several unknown keys, report the one written first, as a reader scans the file.
  std::string first;
  TextPosition first_pos{1 << 30, 0};
  for (auto it = value_.begin(); it != value_.end(); ++it) {
    if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
    TextPosition pos = ctx_.locations ? ctx_.locations->find(pointerOf(it.key()), true) : TextPosition{};
    if (first.empty() || std::pair(pos.line, pos.column) < std::pair(first_pos.line, first_pos.column)) {
      first = it.key();
      first_pos = pos;
    }
  }
  if (first.empty()) return;
  std::string message = "unknown field \"" + first + "\"";
  std::string near = closestMatch(first, known_);
  if (!near.empty()) message += "; did you mean \"" + near + "\"?";
  failAt(ctx_, pointerOf(first), message, true);
}

}  // namespace tumble
