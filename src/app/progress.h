// Progress on stderr: a live bar only when stderr is a terminal (frame k/N, frames per second,
// ETA); logs and pipes get nothing until the one summary line.
#pragma once

#include <chrono>
#include <string>

namespace tumble {

class Progress {
 public:
  Progress(std::string label, int total, bool enabled);
  void update(int done);   // redraws at most ~10 times a second
  void finish();           // clears the bar

 private:
  std::string label_;
  int total_;
  bool live_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

// Seconds since `start`, for the wall-time split in summaries.
double secondsSince(std::chrono::steady_clock::time_point start);

}  // namespace tumble
