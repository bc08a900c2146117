#include "app/interrupt.h"

#include <atomic>
#include <csignal>
#include <cstdlib>

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

}  // namespace tumble
