// `medusa classes`: every persistence class of one diagram with the CompuCell3D cells that make it
// (docs/MATH.md §7.11).
#include "atomic_file.h"
#include "cell_type.h"
#include "commands.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "ring_fate.h"

#include "medusa/core/error.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/class_records.h"
#include "medusa/persistence/class_winding.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace medusa::cli {
namespace {

struct ClassesArguments {
  std::string store;
  std::string type = "all";
  std::optional<int> dim;
  std::string filtration = "forward";
  std::size_t top = 0;
  std::string sort = "lifetime";
  std::string format = "table";
  std::string output;
  bool zero_length = false;
  bool shorten = false;
};

// Cells shown per list in the table before "...".
constexpr std::size_t table_list_limit = 12;

std::string joined(const std::vector<std::int64_t>& ids, const char* separator, std::size_t limit = 0) {
  std::ostringstream out;
  const std::size_t shown = limit > 0 ? std::min(limit, ids.size()) : ids.size();
  for (std::size_t i = 0; i < shown; ++i)
    out << (i > 0 ? separator : "") << ids[i];
  if (shown < ids.size())
    out << separator << "...(+" << ids.size() - shown << ")";
  return out.str();
}

std::string short_time(double t) {
  if (std::isinf(t))
    return t > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", t);
  return buffer;
}

// Sorts the records by `key` and returns, of the forward filtration, each sorted record's time seen in
// the tissue (time_seen); of the reverse filtration, nothing (there it is the lifetime).
std::vector<double> sort_records(std::vector<persistence::ClassRecord>& records, const std::string& key,
                                 bool forward, const medusa::Medusa& medusa) {
  // Birth and death in filtration order: increasing time forward, decreasing in reverse; an essential
  // class's death comes last. Essential loops and cavities of the forward filtration, all of infinite
  // lifetime, by how long their ring stayed whole (ring_whole_for).
  const double sign = forward ? 1.0 : -1.0;
  std::map<std::size_t, double> whole;
  if (forward)
    for (const persistence::ClassRecord& r : records)
      if (r.essential)
        whole[r.id] =
            essential_order(medusa, r.dim, persistence::CellLists::List(r.cycle), r.birth_cell, r.birth);
  const auto whole_for = [&](const persistence::ClassRecord& r) {
    const auto it = whole.find(r.id);
    return it == whole.end() ? 0.0 : it->second;
  };
  const double t_end =
      medusa.input.frame_times.empty() ? 0.0 : static_cast<double>(medusa.input.frame_times.back());
  // A class's time seen in the tissue (time_seen); of the reverse filtration, its lifetime.
  const auto seen = [&](const persistence::ClassRecord& r) {
    return forward ? time_seen(r.essential, r.lifetime(), whole_for(r), r.birth, t_end) : r.lifetime();
  };
  std::stable_sort(records.begin(), records.end(),
                   [&](const persistence::ClassRecord& a, const persistence::ClassRecord& b) {
                     if (key == "seen")
                       return seen(a) != seen(b) ? seen(a) > seen(b) : a.lifetime() > b.lifetime();
                     if (key == "lifetime")
                       return a.lifetime() != b.lifetime() ? a.lifetime() > b.lifetime()
                                                           : whole_for(a) > whole_for(b);
                     if (key == "birth")
                       return sign * a.birth < sign * b.birth;
                     return sign * a.death < sign * b.death;
                   });
  std::vector<double> seen_times;
  if (forward)
    for (const persistence::ClassRecord& r : records)
      seen_times.push_back(seen(r));
  return seen_times;
}

// A time seen in the tissue as the table writes it: a never-filled loop or cavity whose contacts were
// never all present at once was not seen.
std::string seen_text(double seen) { return never_whole(seen) ? "never whole" : short_time(seen); }

// On a periodic run, per record: the axes its loop wraps around ("x", "x,y"; "-" for none), else empty.
using Wraps = std::vector<std::string>;

Wraps wrapping_axes(const medusa::Medusa& medusa, const persistence::DiagramWithClasses& classes,
                    const std::vector<persistence::ClassRecord>& records) {
  Wraps wraps;
  if (medusa.run.periodic_axes.empty())
    return wraps;
  const std::vector<std::string> axes = persistence::class_wrapping_axes(medusa, classes);
  std::map<std::size_t, std::string> by_row;
  for (std::size_t i = 0; i < classes.classes.size(); ++i)
    by_row[classes.classes.rows[i]] = axes[i];
  for (const persistence::ClassRecord& r : records) {
    const std::string& a = by_row[r.id];
    wraps.push_back(a.empty() ? "-" : a);
  }
  return wraps;
}

void write_table(std::ostream& out, const std::vector<persistence::ClassRecord>& records,
                 const std::vector<double>& seen, const Wraps& wraps) {
  out << "id\tdim\tbirth\tdeath\tlifetime\t" << (seen.empty() ? "" : "seen\t")
      << "birth cells\tdeath cells\tsimplices\tcells\trepresentative" << (wraps.empty() ? "" : "\twraps")
      << "\n";
  for (std::size_t i = 0; i < records.size(); ++i) {
    const persistence::ClassRecord& r = records[i];
    out << r.id << '\t' << r.dim << '\t' << short_time(r.birth) << '\t' << short_time(r.death) << '\t'
        << short_time(r.lifetime()) << '\t' << (seen.empty() ? "" : seen_text(seen[i]) + '\t')
        << joined(r.birth_cells, " ") << '\t' << (r.essential ? "-" : joined(r.death_cells, " ")) << '\t'
        << r.simplices.size() << '\t' << r.cells.size() << '\t' << joined(r.cells, " ", table_list_limit)
        << (wraps.empty() ? "" : "\t" + wraps[i]) << '\n';
  }
}

void write_classes_csv(std::ostream& out, const std::vector<persistence::ClassRecord>& records,
                       const std::vector<double>& seen, const Wraps& wraps) {
  out << "id,dimension,birth,death,lifetime,birth_kind,death_kind,birth_cells,death_cells,cell_count,cells,"
         "simplex_count,simplices"
      << (seen.empty() ? "" : ",seen") << (wraps.empty() ? "" : ",wraps") << "\n";
  for (std::size_t i = 0; i < records.size(); ++i) {
    const persistence::ClassRecord& r = records[i];
    std::string simplices;
    for (const auto& s : r.simplices)
      simplices += (simplices.empty() ? "" : ";") + joined(s, " ");
    out << r.id << ',' << r.dim << ',' << format_time(r.birth) << ',' << format_time(r.death) << ','
        << format_time(r.lifetime()) << ',' << persistence::cell_kind_name(r.birth_kind) << ','
        << (r.essential ? "" : persistence::cell_kind_name(r.death_kind)) << ',' << joined(r.birth_cells, " ")
        << ',' << joined(r.death_cells, " ") << ',' << r.cells.size() << ',' << joined(r.cells, " ") << ','
        << r.simplices.size() << ',' << simplices;
    if (!seen.empty())
      out << ',' << (never_whole(seen[i]) ? "" : format_time(seen[i]));
    if (!wraps.empty())
      out << ",\"" << (wraps[i] == "-" ? "" : wraps[i]) << '"';
    out << '\n';
  }
}

nlohmann::json time_json(double t) {
  return std::isinf(t) ? nlohmann::json(format_time(t)) : nlohmann::json(t);
}

void write_classes_json(std::ostream& out, const medusa::Medusa& medusa,
                        const std::vector<persistence::ClassRecord>& records, const std::vector<double>& seen,
                        const Wraps& wraps, int cell_type, persistence::Direction direction, bool shortened) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const persistence::ClassRecord& r = records[i];
    nlohmann::json death_kind =
        r.essential ? nlohmann::json(nullptr) : nlohmann::json(persistence::cell_kind_name(r.death_kind));
    list.push_back(
        {{"id", r.id},
         {"dimension", r.dim},
         {"birth", time_json(r.birth)},
         {"death", time_json(r.death)},
         {"lifetime", time_json(r.lifetime())},
         {"essential", r.essential},
         {"birth_kind", persistence::cell_kind_name(r.birth_kind)},
         {"death_kind", death_kind},
         {"birth_cells", r.birth_cells},
         {"death_cells", r.death_cells},
         {"cells", r.cells},
         {"medusa_birth_cell", r.birth_cell},
         {"medusa_death_cell", r.essential ? nlohmann::json(nullptr) : nlohmann::json(r.death_cell)},
         {"medusa_cycle", r.cycle},
         {"simplices", r.simplices}});
    // What became of an essential loop's or cavity's cells in time running forward (ring_fate.h).
    if (direction == persistence::Direction::forward && r.essential && r.dim >= 1) {
      const RingFate fate =
          ring_fate(medusa, persistence::CellLists::List(r.cycle), medusa.cell(r.birth_cell).birth);
      list.back()["ring"] = {{"state", ring_state_name(fate.state)},
                             {"broke_at", fate.state == RingFate::State::broke ? nlohmann::json(fate.broke_at)
                                                                               : nlohmann::json(nullptr)}};
    }
    if (!seen.empty()) // null: never a ring or shell at one time
      list.back()["seen"] = never_whole(seen[i]) ? nlohmann::json(nullptr) : time_json(seen[i]);
    if (!wraps.empty()) // the axes the loop wraps around, on a periodic run (docs/MATH.md §8.8)
      list.back()["wraps"] = wraps[i] == "-" ? "" : wraps[i];
  }
  out << nlohmann::json{{"type", type_label(cell_type)},
                        {"direction", direction_name(direction)},
                        {"shortened", shortened},
                        {"classes", list}}
             .dump(1)
      << '\n';
}

void classes_command(const ClassesArguments& args) {
  const bool to_stdout = args.output.empty() || args.output == "-";
  if (!to_stdout)
    check_output_path(args.output);
  medusa::StoreReadOptions cells_only;
  cells_only.events = false;
  const medusa::Medusa medusa = medusa::read_store(args.store, cells_only);
  const int cell_type = resolve_cell_type(args.type, medusa.input, args.store);
  const auto direction =
      args.filtration == "forward" ? persistence::Direction::forward : persistence::Direction::reverse;
  persistence::RepresentativeOptions options;
  options.max_dim = args.dim ? *args.dim : 2;
  options.zero_length = args.zero_length;
  options.shorten = args.shorten;
  const persistence::DiagramWithClasses classes =
      persistence::diagram_with_classes(args.store, medusa, direction, cell_type, options);
  std::vector<persistence::ClassRecord> records;
  for (persistence::ClassRecord& r : persistence::class_records(medusa, classes))
    if (!args.dim || r.dim == *args.dim)
      records.push_back(std::move(r));
  std::vector<double> seen =
      sort_records(records, args.sort, direction == persistence::Direction::forward, medusa);
  if (args.top > 0 && records.size() > args.top) {
    records.resize(args.top);
    seen.resize(std::min(seen.size(), args.top));
  }
  const Wraps wraps = wrapping_axes(medusa, classes, records);
  auto write = [&](std::ostream& out) {
    if (args.format == "csv")
      write_classes_csv(out, records, seen, wraps);
    else if (args.format == "json")
      write_classes_json(out, medusa, records, seen, wraps, cell_type, direction,
                         classes.classes.options.shorten);
    else
      write_table(out, records, seen, wraps);
  };
  if (to_stdout)
    write(std::cout);
  else
    write_file_atomically(args.output, write);
}

} // namespace

void add_classes_command(CLI::App& app) {
  auto args = std::make_shared<ClassesArguments>();
  CLI::App* classes = app.add_subcommand(
      "classes", "List the persistence classes of one diagram with the CompuCell3D cells that make each one");
  classes->add_option("store", args->store, "HDF5 store written by `medusa run`")->required();
  classes
      ->add_option(
          "--type", args->type,
          "the sub-medusa of this cell type, by id or name as `medusa info` lists them (docs/MATH.md "
          "§7.4), or 'all' for the whole medusa")
      ->check(type_validator())
      ->capture_default_str();
  classes->add_option("--dim", args->dim, "only this homology degree (default: 0, 1 and 2)")
      ->check(CLI::Range(0, 3));
  classes->add_option("--filtration", args->filtration, "forward or reverse (docs/MATH.md §7.2, §7.3)")
      ->check(CLI::IsMember({"forward", "reverse"}))
      ->capture_default_str();
  classes->add_option("--top", args->top, "only the first N classes in the sort order (0: all)")
      ->capture_default_str();
  classes
      ->add_option(
          "--sort", args->sort,
          "lifetime (longest first, essential classes first; among the loops and cavities never filled, "
          "those whose ring or shell stayed whole longest), seen (how long each was seen in the tissue, "
          "longest first: a filled one's lifetime, a never-filled loop's or cavity's time until its ring or "
          "shell broke open or the run ended; the order of the report's tables), birth or death (in "
          "filtration order)")
      ->check(CLI::IsMember({"lifetime", "seen", "birth", "death"}))
      ->capture_default_str();
  classes
      ->add_option(
          "--format", args->format,
          "table (tab-separated: the counts of simplices and of CC3D cells of the representative, long lists "
          "cut; of the forward filtration, the time each class was seen in the tissue as --sort seen "
          "orders them), csv or json (with every cell and the "
          "representative's simplices as CompuCell3D cell ids)")
      ->check(CLI::IsMember({"table", "csv", "json"}))
      ->capture_default_str();
  classes->add_option("-o,--output", args->output, "output file (default: stdout)");
  classes->add_flag("--zero-length", args->zero_length,
                    "also the zero-length classes (birth and death in the same batch)");
  classes->add_flag("--shorten", args->shorten,
                    "shorter representatives of degrees 1 and 2: each cycle greedily reduced by boundaries "
                    "of cells entered before the class dies, as long as it gets shorter; the same class, "
                    "not necessarily the shortest cycle (docs/MATH.md §7.13)");
  classes->footer(
      "A class's representative is a cycle of medusa cells born with it (docs/MATH.md §7.11): "
      "for degree 0 the cells of the cluster that merged (for the cluster that never merges, every "
      "cell that was part of it up to the end, those born later and those that died included), for "
      "degrees 1 and 2 the cells on the loop or the shell. Stored by `medusa run` for the forward diagrams "
      "(degrees 0-2); "
      "computed on demand for the others. A store written with `medusa run --shorten-representatives` holds "
      "shortened cycles and lists them with or without --shorten.");
  classes->callback([args] { classes_command(*args); });
}

} // namespace medusa::cli
