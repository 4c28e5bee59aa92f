// `medusa at`: the alpha complex K(T+) at one time T (docs/MATH.md §6.6), for ParaView (VTK) or as a list
// of simplices (CSV); with --class, persistence classes' representatives drawn in it (docs/MATH.md
// §7.11); with --times, a series of VTK files and a ParaView collection.
#include "atomic_file.h"
#include "cell_type.h"
#include "commands.h"
#include "complex_export.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "interrupt.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/class_records.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <set>

namespace medusa::cli {
namespace {

// The cells' positions at `time`, interpolated between frames. A periodic run's positions are
// unwrapped (docs/MATH.md §8.2): they are shown wrapped into [0, L) on its periodic axes, where
// CompuCell3D draws the cells. Validates `time` against the frames.
std::vector<std::optional<std::array<double, 3>>> display_positions(const medusa::Medusa& medusa,
                                                                    double time) {
  auto positions = positions_at_time(medusa.input, time);
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
  return positions;
}

namespace fs = std::filesystem;

struct AtArguments {
  std::string store;
  std::optional<double> time;
  std::string times;
  std::string output;
  std::optional<std::string> type_text; // --type as given: an id or a name
  std::optional<int> type;              // its id in the store, once read
  std::vector<std::size_t> classes;
  std::string filtration = "forward";
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The cells of the requested classes' representatives: the cycle, and for H0 the cluster's vertices only.
struct ClassCells {
  std::vector<std::pair<medusa::CellId, std::int64_t>> cells; // (medusa cell, class id)
  double first_birth = 0;
};

ClassCells class_cells(const std::string& path, const medusa::Medusa& medusa, const AtArguments& args) {
  const auto direction =
      args.filtration == "reverse" ? persistence::Direction::reverse : persistence::Direction::forward;
  const int type = args.type ? *args.type : persistence::all_types;
  // The stored representatives cover degrees 0-2 of positive length; other ids need every class.
  persistence::RepresentativeOptions options;
  persistence::DiagramWithClasses found =
      persistence::diagram_with_classes(path, medusa, direction, type, options);
  auto missing = [&] {
    for (std::size_t id : args.classes)
      if (!std::binary_search(found.classes.rows.begin(), found.classes.rows.end(), id))
        return true;
    return false;
  };
  if (missing()) {
    options.max_dim = 3;
    options.zero_length = true;
    found = persistence::diagram_with_classes(path, medusa, direction, type, options);
  }
  ClassCells out;
  for (std::size_t k = 0; k < args.classes.size(); ++k) {
    const std::size_t id = args.classes[k];
    const auto& rows = found.classes.rows;
    const auto at = std::lower_bound(rows.begin(), rows.end(), id);
    if (at == rows.end() || *at != id)
      throw InputError("class " + std::to_string(id) + " is not a class of the " + args.filtration +
                       " diagram of " +
                       (args.type ? "type " + std::to_string(*args.type) : std::string("the whole medusa")) +
                       " in " + path + " (its ids are the first column of `medusa classes`)");
    const auto i = static_cast<std::size_t>(at - rows.begin());
    if (k == 0)
      out.first_birth = found.diagram.pairs[id].birth;
    // A cluster's 0-cycle joins one of its vertices to the older cluster's (docs/MATH.md §7.11): the
    // class's cells are the cluster's alone, as `medusa classes` and the report list them.
    if (found.diagram.pairs[id].dim != 0)
      for (medusa::CellId c : found.classes.cycles[i])
        out.cells.emplace_back(c, static_cast<std::int64_t>(id));
    for (medusa::CellId c : found.classes.clusters[i])
      out.cells.emplace_back(c, static_cast<std::int64_t>(id));
  }
  return out;
}

// K(T+) and the class cells present at T, with their marks. A class cell whose vertices are not all
// present at T cannot be drawn there: it is reported on stderr, never dropped silently.
std::vector<medusa::CellId> cells_at(const medusa::Medusa& medusa, const medusa::ComplexIndex& index,
                                     double t,
                                     const std::vector<std::optional<std::array<double, 3>>>& positions,
                                     const ClassCells* classes, ClassMarks& marks) {
  std::vector<medusa::CellId> cells = index.at_time(t);
  marks.cell_class.assign(cells.size(), -1);
  if (classes == nullptr)
    return cells;
  std::map<medusa::CellId, std::size_t> slot;
  for (std::size_t i = 0; i < cells.size(); ++i)
    slot.emplace(cells[i], i);
  std::size_t absent = 0;
  for (const auto& [id, class_id] : classes->cells) {
    const medusa::Cell& c = medusa.cell(id);
    if (c.dim() > 3 || std::any_of(c.vertices.begin(), c.vertices.end(), [&](kinetic::VertexId v) {
          return !positions[static_cast<std::size_t>(v)];
        })) {
      ++absent;
      continue;
    }
    for (kinetic::VertexId v : c.vertices)
      marks.vertex_class.emplace(v, class_id);
    const auto [it, added] = slot.emplace(id, cells.size());
    if (added) {
      cells.push_back(id);
      marks.cell_class.push_back(class_id);
    } else if (marks.cell_class[it->second] < 0) {
      marks.cell_class[it->second] = class_id;
    }
  }
  if (absent > 0)
    std::cerr << "medusa: warning: " << absent
              << " cell(s) of the class representatives are not drawn at MCS " << format_time(t)
              << ": a CC3D cell of theirs is absent then (or they have dimension 4 or more)\n";
  return cells;
}

std::string counts_line(const medusa::Medusa& medusa, const std::vector<medusa::CellId>& cells) {
  std::array<std::size_t, 4> counts{};
  for (medusa::CellId id : cells)
    ++counts[static_cast<std::size_t>(std::clamp(medusa.cell(id).dim(), 0, 3))];
  return std::to_string(counts[0]) + " vertices, " + std::to_string(counts[1]) + " edges, " +
         std::to_string(counts[2]) + " triangles, " + std::to_string(counts[3]) + " tetrahedra";
}

// A:B:STEP as the times A, A + STEP, ... up to B (B included when it is on the grid).
std::vector<double> time_series(const std::string& text) {
  const auto first = text.find(':'), second = text.find(':', first == std::string::npos ? 0 : first + 1);
  double a = 0, b = 0, step = 0;
  char tail = 0;
  if (first == std::string::npos || second == std::string::npos ||
      std::sscanf(text.c_str(), "%lf:%lf:%lf%c", &a, &b, &step, &tail) != 3 || !(step > 0) || !(b >= a) ||
      !std::isfinite(a) || !std::isfinite(b))
    throw CLI::ValidationError("--times", "'" + text + "' is not A:B:STEP with A <= B and STEP > 0");
  // The count is rounded so that B itself is kept when (B - A) / STEP is an integer up to rounding
  // of the decimal input; these are sampling times, not topological decisions.
  const double n = std::floor((b - a) / step * (1 + 1e-12) + 1e-9);
  if (n > 100000)
    throw CLI::ValidationError("--times", "'" + text + "' asks for more than 100,000 files");
  std::vector<double> times;
  for (std::size_t i = 0; i <= static_cast<std::size_t>(n); ++i)
    times.push_back(a + static_cast<double>(i) * step);
  return times;
}

void write_series(const AtArguments& args, const medusa::Medusa& medusa, const medusa::ComplexIndex& index,
                  const ClassCells* classes) {
  const std::vector<double> times = time_series(args.times);
  const fs::path folder(args.output);
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec || !fs::is_directory(folder))
    throw StoreError("cannot create the folder " + args.output + (ec ? " (" + ec.message() + ")" : ""));
  // Validates every time before writing anything.
  for (double t : times)
    display_positions(medusa, t);
  std::vector<fs::path> written;
  try {
    std::string collection =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n <Collection>\n";
    for (std::size_t i = 0; i < times.size(); ++i) {
      check_interrupted();
      char name[32];
      std::snprintf(name, sizeof name, "at_%05zu.vtu", i);
      const auto positions = display_positions(medusa, times[i]);
      ClassMarks marks;
      const auto cells = cells_at(medusa, index, times[i], positions, classes, marks);
      written.push_back(folder / name);
      write_file_atomically(written.back().string(), [&](std::ostream& out) {
        write_complex_vtu(out, medusa, cells, positions, classes != nullptr ? &marks : nullptr);
      });
      collection += "  <DataSet timestep=\"" + format_time(times[i]) + "\" file=\"" + name + "\"/>\n";
    }
    collection += " </Collection>\n</VTKFile>\n";
    // The collection comes last: a series without it is unfinished.
    written.push_back(folder / "series.pvd");
    write_file_atomically(written.back().string(), [&](std::ostream& out) { out << collection; });
  } catch (const Interrupted&) {
    for (const fs::path& p : written)
      fs::remove(p, ec);
    throw;
  }
  std::cout << "wrote " << times.size() << " files " << (folder / "at_00000.vtu").string() << " ... and "
            << (folder / "series.pvd").string() << " (MCS " << format_time(times.front()) << " to "
            << format_time(times.back()) << ")\n";
}

void at_command(AtArguments& args) {
  if (args.time && !args.times.empty())
    throw CLI::ValidationError("--time", "give --time or --times, not both");
  if (args.times.empty() && !args.time && args.classes.empty())
    throw CLI::ValidationError("--time", "--time is required (or --times, or --class)");
  if (args.times.empty() && !ends_with(args.output, ".vtk") && !ends_with(args.output, ".csv"))
    throw CLI::ValidationError("--output", "'" + args.output + "' does not end in .vtk or .csv");
  if (args.times.empty() && !args.classes.empty() && !ends_with(args.output, ".vtk"))
    throw CLI::ValidationError("--output",
                               "--class draws classes in a .vtk file, not in '" + args.output + "'");
  if (args.times.empty())
    check_output_path(args.output);
  const medusa::Medusa medusa = medusa::read_store(args.store);
  check_interrupted();
  if (args.type_text)
    args.type = resolve_cell_type(*args.type_text, medusa.input, args.store, false);
  std::optional<ClassCells> classes;
  if (!args.classes.empty())
    classes = class_cells(args.store, medusa, args);
  const medusa::ComplexIndex index(medusa, args.type);
  if (!args.times.empty()) {
    write_series(args, medusa, index, classes ? &*classes : nullptr);
    return;
  }
  const double time = args.time ? *args.time : classes->first_birth;
  // Validates T against the frames before the (batch-approximate) index query.
  const auto positions = display_positions(medusa, time);
  ClassMarks marks;
  const std::vector<medusa::CellId> cells =
      cells_at(medusa, index, time, positions, classes ? &*classes : nullptr, marks);
  const std::string what =
      std::string(args.type ? "type " + std::to_string(*args.type) + " subcomplex of " : "") +
      (time == static_cast<double>(medusa.input.frame_times.back()) ? "K(t_end-)" : "K(t+)") + " at MCS " +
      format_time(time);
  const std::size_t in_complex = index.at_time(time).size();
  std::cout << what << ": " << counts_line(medusa, index.at_time(time)) << "\n";
  if (classes) {
    std::size_t drawn = 0;
    for (std::int64_t c : marks.cell_class)
      drawn += c >= 0;
    // cells_at appends the class cells K(T+) lacks: contacts of a cycle of space-time, present at
    // other times (docs/MATH.md §7.11), drawn with it and said to be so. A contact of K(T+) between
    // the same CC3D cells, made again later, is drawn all the same and is not counted.
    const auto vertices = [&](medusa::CellId id) {
      const auto& v = medusa.cell(id).vertices;
      return std::vector<kinetic::VertexId>(v.begin(), v.end());
    };
    std::set<std::vector<kinetic::VertexId>> now;
    for (std::size_t i = 0; i < in_complex; ++i)
      if (medusa.cell(cells[i]).dim() >= 1)
        now.insert(vertices(cells[i]));
    std::size_t elsewhen = 0;
    for (std::size_t i = in_complex; i < cells.size(); ++i)
      elsewhen += medusa.cell(cells[i]).dim() >= 1 && now.count(vertices(cells[i])) == 0;
    std::cout << "classes: " << drawn << (drawn == 1 ? " simplex" : " simplices")
              << " of their representatives drawn (contacts, triangles, tetrahedra), on "
              << marks.vertex_class.size() << " CC3D cells";
    if (elsewhen > 0)
      std::cout << "; " << elsewhen << " of them " << (elsewhen == 1 ? "is" : "are")
                << " not in the complex at MCS " << format_time(time)
                << " but present at other times (a cycle of space-time: its contacts never all at once)";
    std::cout << "\n";
  }
  if (ends_with(args.output, ".vtk"))
    write_file_atomically(args.output, [&](std::ostream& out) {
      write_complex_vtk(out, medusa, cells, positions, "medusa " + what + " of " + args.store,
                        classes ? &marks : nullptr);
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
  at->add_option("--time", args->time,
                 "time T in MCS; the complex reported is K(T+), K(t_end-) at the end (default with --class: "
                 "the birth of the first class)")
      ->check(CLI::Validator(
          [](std::string& value) {
            // CLI11 reads "" as 0, "0x10" as 16 and "nan" as a number: a time is a decimal MCS.
            static const std::regex decimal(R"(\s*[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?\s*)");
            return std::regex_match(value, decimal) ? std::string()
                                                    : "'" + value + "' is not a decimal time in MCS";
          },
          "TIME"));
  at->add_option("--times", args->times,
                 "A:B:STEP: one .vtu file per time A, A+STEP, ... B in the folder -o, and series.pvd "
                 "listing them for ParaView");
  at->add_option("-o,--output", args->output,
                 "shape.vtk (legacy ASCII unstructured grid, positions interpolated at T) or shape.csv "
                 "(dimension,v0..v3: one simplex per row, CC3D cell ids sorted); a folder with --times")
      ->required();
  at->add_option(
        "--type", args->type_text,
        "only the subcomplex of this cell type, by id or name as `medusa info` lists them (docs/MATH.md "
        "§7.4)")
      ->check(type_validator(false));
  at->add_option("--class", args->classes,
                 "draw this class's representative (its id from `medusa classes`, same --type and "
                 "--filtration; repeatable): cell and point data in_class and class_id")
      ->check(CLI::NonNegativeNumber);
  at->add_option("--filtration", args->filtration, "the diagram of the --class ids: forward or reverse")
      ->check(CLI::IsMember({"forward", "reverse"}))
      ->capture_default_str();
  at->callback([args] { at_command(*args); });
}

} // namespace medusa::cli
