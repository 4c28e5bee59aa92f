#include "interrupt.h"

#include <csignal>

namespace medusa::cli {
namespace {
volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_signal(int) { interrupted = 1; }
} // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

void check_interrupted() {
  if (interrupted != 0)
    throw Interrupted();
}

} // namespace medusa::cli
