// The reader half of trajectory_csv.h: RFC 4180 records (quoted fields may hold commas, doubled
// quotes and line breaks), numbers parsed with std::from_chars so they read back exactly.
#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "base/error.h"
#include "io/trajectory_csv.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

// Splits the record starting at `pos` into fields and moves `pos` past its line break.
// Returns false at the end of the text. `line` counts physical lines, for messages.
bool nextRecord(const std::string& text, std::size_t& pos, int& line,
                std::vector<std::string>& fields) {
  if (pos >= text.size()) return false;
  fields.assign(1, std::string());
  bool quoted = false;
  for (; pos < text.size(); ++pos) {
    char c = text[pos];
    if (quoted) {
      if (c == '"' && pos + 1 < text.size() && text[pos + 1] == '"') {
        fields.back() += '"';
        ++pos;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '\n') {
      ++pos;
      break;
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  ++line;
  return true;
}

[[noreturn]] void bad(const fs::path& path, int line, const std::string& what) {
  throw Error(ExitCode::BadInput, path.string() + ":" + std::to_string(line) + ": " + what);
}

double parseNumber(const fs::path& path, int line, const std::string& field) {
  double value = 0;
  const char* end = field.data() + field.size();
  auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (ec != std::errc() || ptr != end) bad(path, line, "'" + field + "' is not a number");
  return value;
}

TrajectoryRow parseRow(const fs::path& path, int line, const std::vector<std::string>& fields) {
  if (fields.size() != 2 + CsvTrajectoryWriter::kValues) {
    bad(path, line, "expected 15 fields, found " + std::to_string(fields.size()));
  }
  TrajectoryRow row;
  row.time = parseNumber(path, line, fields[0]);
  row.body = fields[1];
  for (int i = 0; i < CsvTrajectoryWriter::kValues; ++i) {
    row.v[i] = parseNumber(path, line, fields[2 + i]);
  }
  return row;
}

}  // namespace

TrajectoryCsv readTrajectoryCsvFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ExitCode::MissingInput, "cannot read " + path.string());
  std::ostringstream all;
  all << in.rdbuf();
  const std::string text = all.str();

  TrajectoryCsv csv;
  std::size_t pos = 0;
  int line = 1;
  while (pos < text.size() && text[pos] == '#') {
    std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string comment = text.substr(pos + 1, end - pos - 1);
    if (!comment.empty() && comment.back() == '\r') comment.pop_back();
    csv.comments.push_back(comment.rfind(' ', 0) == 0 ? comment.substr(1) : comment);
    pos = end + 1;
    ++line;
  }
  std::vector<std::string> fields;
  const int header_line = line;
  if (!nextRecord(text, pos, line, fields) || fields.size() != 15 || fields[0] != "time" ||
      fields[1] != "body") {
    bad(path, header_line, "not a trajectory CSV (expected the header time,body,px,...,wz)");
  }
  for (int start = line; nextRecord(text, pos, line, fields); start = line) {
    if (fields.size() == 1 && fields[0].empty()) continue;   // a blank line
    csv.rows.push_back(parseRow(path, start, fields));
  }
  return csv;
}

std::vector<TrajectoryRow> readTrajectoryCsv(const fs::path& path) {
  return readTrajectoryCsvFile(path).rows;
}

}  // namespace tumble
