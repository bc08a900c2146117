// Ctrl-C (SIGINT) and SIGTERM during a long command: the first one asks the work loop to stop at
// the next frame and finish its output cleanly (a playable video of the frames so far); a second
// one ends the process at once.
#pragma once

namespace tumble {

void installInterruptHandlers();
bool interruptRequested();

}  // namespace tumble
