// Ctrl-C (SIGINT) and SIGTERM during a long command: the first one asks the work loop to stop at
// the next frame and finish its output cleanly (a playable video of the frames so far); a second
// one ends the process at once.
#pragma once

namespace tumble {

void installInterruptHandlers();
bool interruptRequested();

// Throws Error(Interrupted) "interrupted while WHAT, at frame K of N" if a stop was asked for: for
// phases with nothing worth keeping yet (the simulation before any frame is rendered), whose
// outputs are temporary files that unwinding removes.
void stopIfInterrupted(const char* what, int frame, int frames);

}  // namespace tumble
