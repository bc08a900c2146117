#include "bench/run_stamp.h"

#include <ctime>

#include "base/build_info.h"

namespace tumble::bench {

std::string shellQuoted(const std::string& arg) {
  const bool plain = !arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                           "0123456789-_./=,:+@%") == std::string::npos;
  if (plain) return arg;
  std::string q = "'";
  for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

RunStamp stampThisRun(const std::vector<std::string>& args) {
  RunStamp s;
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &utc);
  s.date = date;
  s.command = "tumble-bench";
  for (const std::string& a : args) {
    // Appended piece by piece: " " + std::string trips GCC 12's false -Wrestrict.
    s.command += ' ';
    s.command += shellQuoted(a);
  }
  s.commit = buildCommit();
  s.version = buildVersion();
  s.build_type = *TUMBLE_BENCH_BUILD_TYPE ? TUMBLE_BENCH_BUILD_TYPE : "none (no CMAKE_BUILD_TYPE)";
  s.machine = thisMachine();
  return s;
}

}  // namespace tumble::bench
