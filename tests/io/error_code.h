// The exit code a call fails with (Ok when it does not throw tumble::Error).
#pragma once

#include <functional>

#include "base/error.h"

namespace tumble::test {

inline ExitCode codeOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  return ExitCode::Ok;
}

}  // namespace tumble::test
