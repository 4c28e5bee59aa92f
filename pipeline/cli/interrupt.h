// SIGINT/SIGTERM handling: the signal only sets a flag; long loops poll it and throw Interrupted, so
// the stack unwinds and every writer removes its temporary file (README: exit code 130).
#pragma once

#include <stdexcept>

namespace medusa::cli {

class Interrupted : public std::runtime_error {
public:
  Interrupted() : std::runtime_error("interrupted") {}
};

void install_interrupt_handlers();
// Throws Interrupted if a signal arrived, or if the interrupt hook says so.
void check_interrupted();

// A further source of interrupts that check_interrupted() polls, on the thread that calls it: returns
// true when the work is to stop. The Python module installs one that asks the interpreter for pending
// signals (its own SIGINT handling stays in place). nullptr removes it.
using InterruptHook = bool (*)();
void set_interrupt_hook(InterruptHook hook);

} // namespace medusa::cli
