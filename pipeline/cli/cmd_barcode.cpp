// `medusa barcode`: export diagrams as GUDHI .pers, CSV, JSON or an SVG barcode.
#include "atomic_file.h"
#include "commands.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "svg_plot.h"

#include "medusa/medusa/store_reader.h"

#include <iostream>
#include <memory>

namespace medusa::cli {
namespace {

struct BarcodeArguments {
  std::string store;
  std::string format = "pers";
  std::string output;
  unsigned max_bars = default_max_bars;
  unsigned max_points = default_max_points;
  DiagramSelection selection;
};

void barcode_command(const BarcodeArguments& args) {
  const bool to_stdout = args.output.empty() || args.output == "-";
  if (!to_stdout)
    check_output_path(args.output);
  const medusa::Medusa medusa = medusa::read_store(args.store);
  check_interrupted();
  const std::vector<persistence::Diagram> diagrams = selected_diagrams(medusa, args.selection, args.store);
  check_interrupted();
  const double t0 =
      medusa.input.frame_times.empty() ? 0.0 : static_cast<double>(medusa.input.frame_times.front());
  const double t_end =
      medusa.input.frame_times.empty() ? 0.0 : static_cast<double>(medusa.input.frame_times.back());
  auto write = [&](std::ostream& out) {
    if (args.format == "pers")
      write_pers(out, diagrams);
    else if (args.format == "csv")
      write_csv(out, diagrams, medusa.input.type_names);
    else if (args.format == "json")
      write_json(out, diagrams, medusa.input.type_names);
    else if (args.format == "svg")
      write_barcode_svg(out, diagrams, medusa.input.type_names, t0, t_end, args.max_bars);
    else
      write_diagram_svg(out, diagrams, medusa.input.type_names, t0, t_end, args.max_points);
  };
  if (to_stdout)
    write(std::cout);
  else
    write_file_atomically(args.output, write);
}

} // namespace

void add_barcode_command(CLI::App& app) {
  auto args = std::make_shared<BarcodeArguments>();
  CLI::App* barcode = app.add_subcommand(
      "barcode", "Export persistence diagrams (pers, csv, json) or draw them (SVG barcodes or "
                 "persistence diagrams)");
  barcode->add_option("store", args->store, "HDF5 store written by `medusa run`")->required();
  barcode
      ->add_option(
          "--format", args->format,
          "pers (GUDHI: dim birth death), csv (birth,death,dimension,type,direction,type_name), json, svg "
          "(barcodes: one panel per diagram and degree) or diagram-svg (birth-death scatter plots)")
      ->check(CLI::IsMember({"pers", "csv", "json", "svg", "diagram-svg"}))
      ->capture_default_str();
  barcode->add_option("-o,--output", args->output, "output file (default: stdout)");
  barcode
      ->add_option("--max-bars", args->max_bars,
                   "svg: draw only the N longest finite bars of each panel (0: all)")
      ->capture_default_str();
  barcode
      ->add_option("--max-points", args->max_points,
                   "diagram-svg: a panel of more than N finite classes is drawn as a density, squares of 3 "
                   "pixels shaded by their number of classes (0: every class a point)")
      ->capture_default_str();
  add_selection_options(*barcode, args->selection);
  barcode->callback([args] { barcode_command(*args); });
}

} // namespace medusa::cli
