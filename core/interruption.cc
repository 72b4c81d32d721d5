#include "core/interruption.h"

#include <csignal>

namespace tightfit {
namespace {

// Written by the handler, read by the solvers: the only type the handler may store to.
volatile std::sig_atomic_t received_signal = 0;

extern "C" void record_signal(int signal) {
  received_signal = signal;
}

}  // namespace

Interrupted::Interrupted(int signal, const std::string& where)
    : std::runtime_error("interrupted by " + signal_name(signal) + " " + where), signal_(signal) {}

void install_interruption_handlers() {
  std::signal(SIGINT, record_signal);
  std::signal(SIGTERM, record_signal);
}

int interruption_signal() {
  return received_signal;
}

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

void throw_if_interrupted(int signal, const std::string& where) {
  if (signal != 0) throw Interrupted(signal, where);
}

}  // namespace tightfit
