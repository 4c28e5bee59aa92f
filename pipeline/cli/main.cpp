// The `medusa` command-line tool. Exit codes are documented in the README.
#include "medusa/kinetic/error.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"medusa: topology of cell-sorting simulations (kinetic alpha complex, alpha medusa, persistence)"};
  app.require_subcommand(0, 1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  std::cout << app.help();
  return 0;
}
