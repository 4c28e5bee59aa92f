// `medusa at`: the alpha complex K(T+) at one time T (docs/MATH.md §6.6), for ParaView (VTK) or as a list
// of simplices (CSV).
#include "atomic_file.h"
#include "commands.h"
#include "complex_export.h"
#include "diagram_export.h"
#include "interrupt.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/store_reader.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

namespace medusa::cli {
namespace {

struct AtArguments {
  std::string store;
  double time = 0;
  std::string output;
  std::optional<int> type;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void at_command(const AtArguments& args) {
  const medusa::Medusa medusa = medusa::read_store(args.store);
  check_interrupted();
  if (args.type) {
    const auto& cells = medusa.input.cells;
    if (std::none_of(cells.begin(), cells.end(),
                     [&](const kinetic::Trajectory& c) { return c.type == *args.type; }))
      throw InputError("cell type " + std::to_string(*args.type) + " does not occur in " + args.store);
  }
  // Validates T against the frames before the (batch-approximate) index query.
  auto positions = positions_at_time(medusa.input, args.time);
  // A periodic run's positions are unwrapped (docs/MATH.md §8.2): shown wrapped into [0, L) on its
  // periodic axes, where CompuCell3D draws the cells.
  for (std::size_t a = 0; a < 3; ++a) {
    if (medusa.run.periodic_lengths[a] <= 0)
      continue;
    const double length =
        static_cast<double>(medusa.run.periodic_lengths[a]) / static_cast<double>(medusa.input.scale);
    for (auto& x : positions)
      if (x) {
        (*x)[a] = std::fmod((*x)[a], length);
        if ((*x)[a] < 0)
          (*x)[a] += length;
      }
  }
  const medusa::ComplexIndex index(medusa, args.type);
  const std::vector<medusa::CellId> cells = index.at_time(args.time);

  std::array<std::size_t, 4> counts{};
  for (medusa::CellId id : cells)
    ++counts[static_cast<std::size_t>(std::clamp(medusa.cell(id).dim(), 0, 3))];
  const std::string what =
      std::string(args.type ? "type " + std::to_string(*args.type) + " subcomplex of " : "") +
      "K(t+) at MCS " + format_time(args.time);
  std::cout << what << ": " << counts[0] << " vertices, " << counts[1] << " edges, " << counts[2]
            << " triangles, " << counts[3] << " tetrahedra\n";
  if (ends_with(args.output, ".vtk"))
    write_file_atomically(args.output, [&](std::ostream& out) {
      write_complex_vtk(out, medusa, cells, positions, "medusa " + what + " of " + args.store);
    });
  else
    write_file_atomically(args.output, [&](std::ostream& out) { write_complex_csv(out, medusa, cells); });
  std::cout << "wrote " << args.output << "\n";
}

} // namespace

void add_at_command(CLI::App& app) {
  auto args = std::make_shared<AtArguments>();
  CLI::App* at = app.add_subcommand("at", "Export the alpha complex at one time as VTK (ParaView) or CSV");
  at->add_option("store", args->store, "HDF5 store written by `medusa run`")->required();
  at->add_option("--time", args->time, "time T in MCS; the complex reported is K(T+), K(t_end-) at the end")
      ->required()
      ->check(CLI::Validator(
          [](std::string& value) {
            // CLI11 reads "" as 0; a time must be written out.
            return value.find_first_not_of(" \t") == std::string::npos
                       ? std::string("an empty time is not a number")
                       : std::string();
          },
          "TIME"));
  at->add_option("-o,--output", args->output,
                 "shape.vtk (legacy ASCII unstructured grid, positions interpolated at T) or shape.csv "
                 "(dimension,v0..v3: one simplex per row, CC3D cell ids sorted)")
      ->required()
      ->check(CLI::Validator(
          [](std::string& value) {
            return ends_with(value, ".vtk") || ends_with(value, ".csv")
                       ? std::string()
                       : "'" + value + "' does not end in .vtk or .csv";
          },
          "FILE"));
  at->add_option("--type", args->type, "only the subcomplex of this cell type id (docs/MATH.md §7.4)");
  at->callback([args] { at_command(*args); });
}

} // namespace medusa::cli
