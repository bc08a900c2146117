#include "scene/json_text.h"

#include <fstream>
#include <sstream>

#include "base/error.h"
#include "scene/object_reader.h"

namespace tumble {
namespace {

constexpr std::uintmax_t kMaxBytes = 64 << 20;   // 64 MB: a 100000-body pile is ~15 MB

// nlohmann's messages begin "[json.exception.parse_error.101] parse error at line 3, column 4: ";
// we keep what follows and put the position in our own "file:line:column:" form.
std::string describeJsonError(const nlohmann::json::exception& e, const std::string& text,
                              const JsonLocations& locations, const std::string& file) {
  std::string what = e.what();
  TextPosition pos{};
  if (auto* parse = dynamic_cast<const nlohmann::json::parse_error*>(&e)) {
    pos = locations.positionOf(parse->byte > 0 ? parse->byte - 1 : 0);
  } else if (std::size_t q = what.find('\''); q != std::string::npos) {
    // "number overflow parsing '1e999'": find the number in the text to say where it is.
    // The first value spelled so, not the first text: the same digits may sit in a comment.
    std::string token = what.substr(q + 1, what.rfind('\'') - q - 1);
    std::size_t at = locations.firstValueSpelled(token);
    if (at == std::string::npos) at = text.find(token);
    if (at != std::string::npos) pos = locations.positionOf(at);
  }
  std::size_t colon = what.find(": ", what.find("parse error"));
  std::string detail = colon != std::string::npos && what.find("parse error") != std::string::npos
                           ? what.substr(colon + 2)
                           : what.substr(what.find(']') + 2);
  std::string where = file;
  if (pos.line > 0) where += ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
  return where + ": invalid JSON: " + detail;
}

}  // namespace

std::string readJsonFile(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw Error(ExitCode::MissingInput, file.string() + ": no such " + what);
  if (std::filesystem::is_directory(file, ec))
    throw Error(ExitCode::MissingInput, file.string() + ": is a folder, not a " + what);
  // A device or a pipe (/dev/zero) would be read forever; a hand-written scene is never this big.
  if (!std::filesystem::is_regular_file(file, ec))
    throw Error(ExitCode::MissingInput, file.string() + ": is not a regular file");
  if (std::filesystem::file_size(file, ec) > kMaxBytes)
    throw Error(ExitCode::BadInput, file.string() + ": " + std::to_string(std::filesystem::file_size(file, ec) >> 20) +
                                        " MB is too large for a " + what + " (at most " +
                                        std::to_string(kMaxBytes >> 20) + " MB)");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  if (!(in && text << in.rdbuf()))
    throw Error(ExitCode::MissingInput, file.string() + ": cannot be read");
  return text.str();
}

nlohmann::json parseJsonText(const std::string& text, const JsonLocations& locations, const std::string& file) {
  if (locations.tooDeep()) {
    TextPosition pos = locations.positionOf(locations.tooDeepAt());
    throw Error(ExitCode::BadInput, file + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column) +
                                        ": invalid JSON: nested deeper than " +
                                        std::to_string(JsonLocations::kMaxDepth) + " levels");
  }
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::exception& e) {
    throw Error(ExitCode::BadInput, describeJsonError(e, text, locations, file));
  }
  if (const std::string& twice = locations.firstDuplicateKey(); !twice.empty())
    failAt(ParseContext{file, &locations}, twice,
           "the field \"" + twice.substr(twice.rfind('/') + 1) + "\" is given twice in this object", /*at_key=*/true);
  return doc;
}

}  // namespace tumble
