// Ctrl-C (SIGINT) and SIGTERM during a run. The signal handler only records the signal; the
// solvers look at it between iterations (RK4 frames, Newton steps) and throw Interrupted, so a
// run ends at a clean point with every finished load step written, and the program exits with
// 128 + the signal's number (130 for SIGINT, 143 for SIGTERM) as a shell expects.
#pragma once

#include <stdexcept>
#include <string>

namespace tightfit {

class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& where);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// Makes SIGINT and SIGTERM set the flag instead of ending the process. Until this is called
// (tests, other programs) the signals keep their default action.
void install_interruption_handlers();
// The signal received since the handlers were installed, 0 if none.
int interruption_signal();
// "SIGINT", "SIGTERM" or "signal N".
std::string signal_name(int signal);
// Throws Interrupted(`signal`, `where`) when `signal` is not 0.
void throw_if_interrupted(int signal, const std::string& where);

}  // namespace tightfit
