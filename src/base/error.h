// Errors a user can cause (bad scene, missing file, unwritable output, no encoder) travel as
// tumble::Error, carrying the exit code `main` returns. Programmer bugs are asserts, not Errors.
#pragma once

#include <stdexcept>
#include <string>

namespace tumble {

// Exit codes follow sysexits.h, the convention of command-line tools (README, "Exit codes").
enum class ExitCode : int {
  Ok = 0,
  Usage = 64,        // EX_USAGE: bad command line
  BadInput = 65,     // EX_DATAERR: the scene (or a mesh in it) is malformed or out of range
  MissingInput = 66, // EX_NOINPUT: a scene or mesh file does not exist or cannot be read
  Unavailable = 69,  // EX_UNAVAILABLE: no OpenGL (OSMesa) or no H.264 encoder
  Software = 70,     // EX_SOFTWARE: numerical failure at run time (NaN, runaway energy)
  CantCreate = 73,   // EX_CANTCREAT: the output cannot be written or would be overwritten
  Interrupted = 130, // 128 + SIGINT, as shells report it
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

}  // namespace tumble
