// The `medusa` command-line tool. Exit codes are documented in the README; every error is one line
// `medusa: <message>` on stderr.
#include "commands.h"
#include "interrupt.h"
#include "run_outputs.h"

#include "medusa/core/error.h"
#include "medusa/core/version.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <exception>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <iostream>
#include <new>
#include <string>
#include <vector>

namespace {

int fail(const std::string& message, int code) {
  std::cerr << "medusa: " << message << std::endl;
  return code;
}

std::string joined(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i)
    line += (i > 0 ? " " : "") + std::string(argv[i]);
  return line;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "medusa: topology of cell-sorting simulations (kinetic alpha complex, alpha medusa, persistence)"};
  app.require_subcommand(1, 1);
  app.set_version_flag("--version", std::string("medusa ") + medusa::version);
  // Accepted after the subcommand too, as users type it there (fallthrough: set before the
  // subcommands, which inherit it).
  app.fallthrough();
  app.add_flag_function(
      "--verbose", [](std::int64_t) { medusa::set_store_error_details(true); },
      "store errors also carry the HDF5 library's own messages (for a bug report)");
  medusa::cli::add_run_command(app, joined(argc, argv));
  medusa::cli::add_info_command(app);
  medusa::cli::add_diagrams_command(app);
  medusa::cli::add_barcode_command(app);
  medusa::cli::add_compare_command(app);
  medusa::cli::add_curves_command(app);
  medusa::cli::add_at_command(app);
  medusa::cli::add_report_command(app);
  medusa::cli::add_sweep_command(app);
  // CLI11 reports an unknown first word as a missing subcommand; name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({}))
      names.push_back(sub->get_name());
    if (std::find(names.begin(), names.end(), word) == names.end()) {
      std::string list;
      for (const std::string& n : names)
        list += (list.empty() ? "" : ", ") + n;
      return fail("unknown command '" + word + "' (the commands are " + list + "; see medusa --help)", 2);
    }
  }
  medusa::cli::install_interrupt_handlers();
  // A store whose final flush failed would otherwise crash HDF5's exit handler (store_writer.h).
  medusa::skip_hdf5_cleanup_at_exit();
#ifdef __GLIBC__
  // Blocks of 128 KiB and more are mapped and unmapped one by one. glibc otherwise raises this
  // threshold after the first such block is freed and serves later large temporaries (store columns,
  // rehashed tables) from the heap, where they stay resident after they are freed: on large_3d that
  // added a third to the peak memory of `medusa run` (the kinetic stage runs no slower).
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
  // `medusa` alone asks what the tool does: the help on stdout, exit 0 (README, Exit codes).
  if (argc <= 1) {
    app.name(argc == 1 ? argv[0] : "medusa");
    std::cout << app.help();
    return 0;
  }
  try {
    app.parse(argc, argv);
    return 0;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0)
      return app.exit(e);
    return fail(e.what(), 2);
  } catch (const medusa::cli::UsageError& e) {
    return fail(e.what(), 2);
  } catch (const medusa::cli::Interrupted&) {
    return fail("interrupted; no partial output left", 130);
  } catch (const medusa::InputError& e) {
    return fail(e.what(), 3);
  } catch (const medusa::GeometryError& e) {
    return fail(e.what(), 4);
  } catch (const medusa::StoreError& e) {
    return fail(e.what(), 5);
  } catch (const medusa::InternalError& e) {
    return fail(std::string("internal error (please report): ") + e.what(), 1);
  } catch (const std::bad_alloc&) {
    return fail("out of memory: the input is larger than the memory available to medusa", 3);
  } catch (const std::exception& e) {
    return fail(std::string("internal error (please report): ") + e.what(), 1);
  }
}
