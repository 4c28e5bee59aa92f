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
// Throws Interrupted if a signal arrived.
void check_interrupted();

} // namespace medusa::cli
