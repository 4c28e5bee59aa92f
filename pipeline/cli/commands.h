// The subcommands of `medusa`; each adds itself to the application and runs from its callback.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace medusa::cli {

void add_run_command(CLI::App& app, const std::string& command_line);
void add_info_command(CLI::App& app);
void add_diagrams_command(CLI::App& app);
void add_barcode_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_curves_command(CLI::App& app);
void add_at_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_sweep_command(CLI::App& app);

} // namespace medusa::cli
