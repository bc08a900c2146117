#include "io/trajectory_csv.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <system_error>

#include "base/error.h"
#include "io/atomic_file.h"

namespace tumble {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader = "time,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";
constexpr std::size_t kFlushBytes = 1 << 16;

void appendNumber(std::string& out, double value) {
  char text[32];   // the longest shortest-round-trip double is 24 characters
  auto [end, ec] = std::to_chars(text, text + sizeof text, value);
  out.append(text, end);
}

void appendName(std::string& out, const std::string& name) {
  if (name.find_first_of(",\"\r\n") == std::string::npos) {
    out += name;
    return;
  }
  out += '"';
  for (char c : name) {
    if (c == '"') out += '"';   // a quote inside quotes is doubled
    out += c;
  }
  out += '"';
}

}  // namespace

CsvTrajectoryWriter::CsvTrajectoryWriter(const fs::path& path, bool overwrite,
                                         const std::vector<std::string>& comments)
    : path_(path), overwrite_(overwrite) {
  for (const std::string& c : comments) buffer_ += "# " + c + "\n";
  buffer_ += kHeader;
  buffer_ += '\n';
  if (isStreamOutput(path_)) {
    file_ = path_ == "-" ? stdout : std::fopen(path_.c_str(), "wb");
    if (!file_) throwCantWrite(path_, std::strerror(errno));
    return;
  }
  std::error_code ec;
  checkReplaceable(path_);
  if (!overwrite_ && fs::exists(path_, ec)) {
    throwCantWrite(path_, "it already exists (use -y/--overwrite to replace it)");
  }
  temp_ = temporarySibling(path, "tmp");
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_) throwCantWrite(path_, std::strerror(errno));
}

CsvTrajectoryWriter::~CsvTrajectoryWriter() {
  if (!file_) return;
  if (file_ != stdout) std::fclose(file_);
  std::error_code ignored;
  if (!temp_.empty()) fs::remove(temp_, ignored);
}

void CsvTrajectoryWriter::row(double time, const std::string& body, const double values[kValues]) {
  appendNumber(buffer_, time);
  buffer_ += ',';
  appendName(buffer_, body);
  for (int i = 0; i < kValues; ++i) {
    buffer_ += ',';
    appendNumber(buffer_, values[i]);
  }
  buffer_ += '\n';
  if (buffer_.size() >= kFlushBytes) flush();
}

void CsvTrajectoryWriter::flush() {
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
    throwCantWrite(path_, std::strerror(errno));
  }
  buffer_.clear();
}

void CsvTrajectoryWriter::close() {
  if (!file_) return;
  flush();
  std::FILE* file = file_;
  file_ = nullptr;
  // A full device reports itself here, when the buffered bytes finally go out.
  if ((file == stdout ? std::fflush(file) : std::fclose(file)) != 0) {
    int err = errno;
    std::error_code ignored;
    if (!temp_.empty()) fs::remove(temp_, ignored);
    throwCantWrite(path_, std::strerror(err));
  }
  if (!temp_.empty()) commitFile(temp_, path_, overwrite_);
}

}  // namespace tumble
