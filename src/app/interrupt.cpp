#include "app/interrupt.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string>

#include "base/error.h"

namespace tumble {
namespace {

std::atomic<bool> g_requested{false};

extern "C" void onSignal(int signal) {
  if (g_requested.exchange(true)) std::_Exit(128 + signal);  // second signal: stop now
}

}  // namespace

void installInterruptHandlers() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
}

bool interruptRequested() { return g_requested.load(); }

void stopIfInterrupted(const char* what, int frame, int frames) {
  if (!interruptRequested()) return;
  throw Error(ExitCode::Interrupted, std::string("interrupted while ") + what + ", at frame " +
                                         std::to_string(frame) + " of " + std::to_string(frames) +
                                         "; nothing was written");
}

}  // namespace tumble
