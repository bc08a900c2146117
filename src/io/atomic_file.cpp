#include "io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "base/error.h"

namespace tumble {

namespace fs = std::filesystem;

fs::path temporarySibling(const fs::path& final_path, std::string_view tag, bool keep_extension) {
  // Built by appending: GCC 12 warns falsely (-Wrestrict) about `"." + std::string`.
  std::string name(1, '.');
  name += final_path.filename().string();
  name += '.';
  name += tag;
  name += '-';
  name += std::to_string(::getpid());
  if (keep_extension) name += final_path.extension().string();
  return final_path.parent_path() / name;
}

bool isStreamOutput(const fs::path& path) {
  if (path == "-") return true;
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);   // follows links: /dev/stdout -> /proc/self/fd/1
  return !ec && (fs::is_character_file(st) || fs::is_fifo(st) || fs::is_socket(st));
}

void checkReplaceable(const fs::path& path) {
  std::error_code ec;
  fs::file_status st = fs::symlink_status(path, ec);
  if (ec || !fs::exists(st) || fs::is_regular_file(st) || fs::is_symlink(st)) return;
  const char* what = fs::is_directory(st) ? "a folder" : fs::is_fifo(st) ? "a pipe" : "a device or other special file";
  throwCantWrite(path, std::string("it is ") + what + ", not a file; tumble replaces only files (choose another name)");
}

void throwCantWrite(const fs::path& path, std::string_view reason) {
  throw Error(ExitCode::CantCreate, "cannot write " + path.string() + ": " + std::string(reason));
}

namespace {

// Rename that refuses to replace. Falls back to a check-then-rename on file systems without
// RENAME_NOREPLACE (EINVAL), where the small race is the best we can do.
int renameNoReplace(const fs::path& from, const fs::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return 0;
  if (errno != EINVAL && errno != ENOSYS) return errno;
  std::error_code ec;
  if (fs::exists(to, ec)) return EEXIST;
  return std::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
}

}  // namespace

void commitFile(const fs::path& temp, const fs::path& final_path, bool overwrite) {
  int err = 0;
  if (overwrite) {
    try {
      checkReplaceable(final_path);   // a folder or device may have appeared since the start
    } catch (const Error&) {
      std::error_code ignored;
      fs::remove(temp, ignored);
      throw;
    }
    err = std::rename(temp.c_str(), final_path.c_str()) == 0 ? 0 : errno;
  } else {
    err = renameNoReplace(temp, final_path);
  }
  if (err == 0) return;
  std::error_code ignored;
  fs::remove(temp, ignored);
  if (err == EEXIST) {
    throwCantWrite(final_path, "it already exists (use -y/--overwrite to replace it)");
  }
  throwCantWrite(final_path, std::strerror(err));
}

void writeFileWhole(const std::filesystem::path& path, std::string_view data, bool overwrite) {
  const std::filesystem::path temp = temporarySibling(path, "tmp");
  std::FILE* file = std::fopen(temp.c_str(), "wb");
  if (!file) throwCantWrite(path, std::strerror(errno));
  const bool written = std::fwrite(data.data(), 1, data.size(), file) == data.size();
  // fclose reports a full disk for data still buffered, so its result counts too.
  if (std::fclose(file) != 0 || !written) {
    const int reason = errno;
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throwCantWrite(path, std::strerror(reason));
  }
  commitFile(temp, path, overwrite);
}

}  // namespace tumble
