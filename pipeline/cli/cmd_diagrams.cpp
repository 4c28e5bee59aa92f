// `medusa diagrams`: persistence pairs of a store as text (birth death dim; inf for essential).
#include "commands.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "interrupt.h"

#include "medusa/medusa/store_reader.h"

#include <iostream>
#include <memory>

namespace medusa::cli {
namespace {

struct DiagramsArguments {
  std::string store;
  DiagramSelection selection;
};

} // namespace

void add_diagrams_command(CLI::App& app) {
  auto args = std::make_shared<DiagramsArguments>();
  CLI::App* diagrams =
      app.add_subcommand("diagrams", "Print the persistence pairs of a store (birth death dim)");
  diagrams->add_option("store", args->store, "HDF5 store written by `medusa run`")->required();
  add_selection_options(*diagrams, args->selection);
  diagrams->callback([args] {
    const medusa::Medusa medusa = medusa::read_store(args->store);
    check_interrupted();
    const std::vector<persistence::Diagram> diagrams =
        selected_diagrams(medusa, args->selection, args->store);
    // Nothing on stdout before the last check: an interrupted command prints no partial listing.
    check_interrupted();
    write_pairs_text(std::cout, diagrams, medusa.input.type_names);
  });
}

} // namespace medusa::cli
