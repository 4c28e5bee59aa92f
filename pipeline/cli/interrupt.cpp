#include "interrupt.h"

#include <atomic>
#include <csignal>

namespace medusa::cli {
namespace {
volatile std::sig_atomic_t interrupted = 0;
std::atomic<InterruptHook> hook{nullptr};
extern "C" void on_signal(int) { interrupted = 1; }
} // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

void check_interrupted() {
  if (interrupted != 0)
    throw Interrupted();
  if (const InterruptHook h = hook.load(); h != nullptr && h())
    throw Interrupted();
}

void set_interrupt_hook(InterruptHook h) { hook.store(h); }

} // namespace medusa::cli
