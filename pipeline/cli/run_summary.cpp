#include "run_summary.h"

#include "cell_type.h"
#include "class_fates.h"
#include "diagram_selection.h"
#include "position_source.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace medusa::cli {
namespace {

std::string mcs(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", t);
  return buffer;
}

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

const persistence::Diagram* find_diagram(const std::vector<persistence::Diagram>& diagrams, int type,
                                         persistence::Direction direction) {
  for (const persistence::Diagram& d : diagrams)
    if (d.cell_type == type && d.direction == direction)
      return &d;
  return nullptr;
}

void describe_clusters(std::ostream& out, const ClusterFates& c, double t0, double t_end) {
  out << "  clusters: " << c.at_first << " at MCS " << mcs(t0) << ", " << c.at_end << " at MCS " << mcs(t_end)
      << "; ";
  if (c.joins == 0)
    out << "none joined another";
  else
    out << count(c.joins, "join", "joins") << " (a cluster touching another), "
        << (c.joins == 1 ? "at MCS " + mcs(c.all_joined)
                         : "half of them by MCS " + mcs(c.half_joined) + ", all by MCS " + mcs(c.all_joined));
  out << "\n";
  if (c.joined_at_first > 0)
    out << "    (" << c.joined_at_first << " of the clusters at MCS " << mcs(t0)
        << (c.joined_at_first == 1 ? " was" : " were")
        << " already joined to another through cells present at that frame only)\n";
  if (c.separated_again > 0)
    out << "    (" << c.separated_again << " of the clusters at MCS " << mcs(t_end) << " had"
        << " been one cluster with another earlier, by a join or from the start, and split off)\n";
}

// A path as a shell word: quoted unless it is made of characters no shell treats specially.
std::string shell_word(const std::string& path) {
  bool plain = !path.empty();
  for (char c : path)
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ||
                      c == '/' || c == '+' || c == ',' || c == ':');
  if (plain)
    return path;
  std::string quoted = "'";
  for (char c : path)
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// `listing`: the `medusa classes` command of this sub-medusa and degree (empty: none said).
void describe_holes(std::ostream& out, const persistence::HoleFates& h, std::size_t open_at_first,
                    std::size_t open_at_end, const char* one, const char* many, double t0, double t_end,
                    const std::string& listing) {
  out << "  " << many << ": " << h.initial() << " present at MCS " << mcs(t0) << ", " << h.formed()
      << " formed during the run\n";
  // Present at t_0 counts the space-time classes up to t_0, cells present at t_0 alone included; the
  // complex just after t_0 (b_k of `medusa curves --frames-only`) no longer has those cells.
  if (open_at_first != h.initial())
    out << "    (the complex just after MCS " << mcs(t0)
        << ", without the cells present at that frame only, has " << count(open_at_first, one, many) << ")\n";
  if (h.initial() + h.formed() == 0)
    return;
  out << "    filled by cells: " << h.filled_initial << " of those at MCS " << mcs(t0) << ", "
      << h.filled_formed << " formed later\n";
  // Each never-filled count split into still open at the end and broke open (docs/MATH.md §7.12); the
  // first split names the end's time.
  bool named_end = false;
  const auto split = [&](std::size_t still, std::size_t broken) {
    if (still + broken == 0)
      return;
    out << " (" << still << " still open" << (named_end ? "" : " at MCS " + mcs(t_end)) << ", " << broken
        << " broke open)";
    named_end = true;
  };
  out << "    never filled: " << h.never_filled_initial << " of those at MCS " << mcs(t0);
  split(h.still_open_initial, h.broken_open_initial);
  out << ", " << h.never_filled_formed << " formed later";
  split(h.still_open_formed, h.broken_open_formed);
  out << "\n";
  // The classes of the end complex that stay classes of M are the reverse filtration's essential ones
  // born at t_end (docs/MATH.md §7.12), and their representatives are cycles of K(t_end-): rings and
  // shells of cells at the end, where the forward representatives can be cycles of space-time.
  if (h.still_open() > 0 && !listing.empty())
    out << "    the " << h.still_open() << " still open, each with the cells around it at MCS " << mcs(t_end)
        << ": `" << listing << " --filtration reverse`, the rows born at " << mcs(t_end)
        << " with death -inf\n";
  if (open_at_end > h.still_open())
    out << "    (the complex at MCS " << mcs(t_end) << " has " << count(open_at_end, one, many) << "; "
        << open_at_end - h.still_open()
        << " of them bound in space-time, e.g. around a spot that cells filled at another time, and are not "
           "new classes)\n";
}

// H2 of a planar run's medusa is no cavity of the flat tissue: its space-time lives in R^3, where by
// docs/MATH.md §7.6's argument for H3 one dimension down every H2 class is a bubble of space-time (a hole
// that opened inside the tissue and closed again, born when it closes) and none of positive length
// dies (tests/medusa/test_medusa_2d.cpp checks it on the real 2D run).
void describe_planar_bubbles(std::ostream& out, const persistence::Diagram& forward) {
  std::size_t n = 0;
  for (const persistence::PersistencePair& p : forward.pairs)
    n += p.dim == 2 && !p.zero_length ? 1 : 0;
  out << "  " << count(n, "space-time bubble", "space-time bubbles")
      << " (holes that opened inside the tissue and closed again)\n";
}

// `store`: the store's path as the user gave it, for the commands named (empty: none named).
void describe_fates(std::ostream& out, const ClassFates& fates, const persistence::Diagram& forward,
                    int dimension, double t0, double t_end, const std::string& store) {
  const auto listing = [&](int k) {
    if (store.empty())
      return std::string();
    const std::string type =
        forward.cell_type == persistence::all_types ? "all" : std::to_string(forward.cell_type);
    return "medusa classes " + shell_word(store) + " --type " + type + " --dim " + std::to_string(k);
  };
  describe_clusters(out, fates.clusters, t0, t_end);
  describe_holes(out, fates.holes[1], fates.open_at_first[1], fates.open_at_end[1], "loop", "loops", t0,
                 t_end, listing(1));
  if (dimension == 2)
    describe_planar_bubbles(out, forward);
  else
    describe_holes(out, fates.holes[2], fates.open_at_first[2], fates.open_at_end[2], "cavity", "cavities",
                   t0, t_end, listing(2));
}

// Cells shown before "and N more".
constexpr std::size_t cells_shown = 8;

// One line: the class, its first cells, its times, and the commands that list it and draw it
// (docs/MATH.md §7.11). The listing sorts by time seen, where the class is the first filled row; by
// lifetime every never-filled class would come first, thousands of rows on a planar run.
void describe_longest(std::ostream& out, const LongestFilled& c, const std::string& store) {
  out << "  longest-lived filled " << (c.dim == 1 ? "loop" : "cavity") << ": class " << c.id << ", cells ";
  for (std::size_t i = 0; i < std::min(cells_shown, c.cells.size()); ++i)
    out << (i > 0 ? ", " : "") << c.cells[i];
  if (c.cells.size() > cells_shown)
    out << " and " << c.cells.size() - cells_shown << " more";
  out << ", formed at MCS " << mcs(c.birth) << ", filled at MCS " << mcs(c.death);
  if (store.empty()) {
    out << "\n";
    return;
  }
  const std::string type = c.cell_type == persistence::all_types ? "all" : std::to_string(c.cell_type);
  const std::string at_type = c.cell_type == persistence::all_types ? "" : " --type " + type;
  out << " (`medusa classes " << shell_word(store) << " --type " << type << " --dim " << c.dim
      << " --sort seen`, `medusa at " << shell_word(store) << at_type << " --class " << c.id << " -o class"
      << c.id << ".vtk`)\n";
}

} // namespace

void describe_forward_diagram(std::ostream& out, const medusa::Medusa& medusa,
                              const std::vector<persistence::Diagram>& diagrams,
                              const persistence::Diagram& forward) {
  const kinetic::Trajectories& input = medusa.input;
  const persistence::Diagram* reverse =
      find_diagram(diagrams, forward.cell_type, persistence::Direction::reverse);
  if (reverse == nullptr)
    throw InternalError("run summary: no reverse diagram for type " + type_label(forward.cell_type));
  describe_fates(out, class_fates(medusa, forward, *reverse), forward, input.dimension,
                 static_cast<double>(input.frame_times.front()),
                 static_cast<double>(input.frame_times.back()), std::string());
}

std::vector<std::string> write_run_summary(std::ostream& out, const medusa::Medusa& medusa,
                                           const kinetic::KineticStatistics& stats,
                                           const std::vector<persistence::Diagram>& diagrams,
                                           const std::vector<FatesFromCells>& from_cells,
                                           const std::string& radius_text, const std::string& radius_note,
                                           const std::vector<LongestFilled>& longest,
                                           const std::string& store) {
  const kinetic::Trajectories& input = medusa.input;
  const double t0 = input.frame_times.empty() ? 0.0 : static_cast<double>(input.frame_times.front());
  const double t_end = input.frame_times.empty() ? 0.0 : static_cast<double>(input.frame_times.back());
  out << "cells: " << input.cells.size() << " trajectories, frames: " << input.frames() << " (MCS " << mcs(t0)
      << " to " << mcs(t_end) << "), dimension " << input.dimension << "\n"
      << "radius: " << radius_text << " lattice units"
      << (radius_note.empty() ? "" : " (" + radius_note + ")")
      << "; two cells touch when their centres are closer than twice that\n";
  // Which of a folder's inputs was read: a folder can hold both snapshots and a CSV.
  const std::vector<std::string>& files = medusa.run.source_files;
  if (files.size() == 1)
    out << "read: " << files.front() << "\n";
  else if (files.size() > 1)
    out << "read: " << files.size() << " snapshots, " << files.front() << " to " << files.back() << "\n";
  if (positions_from_vtk(medusa.run))
    out << "positions: " << describe_positions(medusa.run) << "\n";
  out << "events: " << stats.flips() << " flips (";
  // A planar run flips 2-2, a 3D run 2-3 and 3-2 (the hull flips of either are counted apart).
  if (input.dimension == 2)
    out << stats.flips22 << " 2-2, ";
  else
    out << stats.flips23 << " 2-3, " << stats.flips32 << " 3-2, ";
  out << stats.hull_flips << " hull), " << stats.radius_events << " radius events, " << stats.insertions
      << " insertions, " << stats.deletions << " deletions\n"
      << "medusa cells:";
  const int top = input.dimension + 1; // space-time cells go one dimension above space
  for (int k = 0; k <= top; ++k)
    out << " dim " << k << ": " << medusa.cells_of_dimension(k).size() << (k < top ? "," : "\n");

  std::vector<std::string> warnings;
  if (medusa.cells_of_dimension(1).empty())
    warnings.push_back("radius " + radius_text +
                       " gives no contact between any two cells at any time (two cells touch when their "
                       "centres are closer than twice the radius): every cell stays a cluster of its own; "
                       "--radius auto, the default, takes the radius of a ball of the median cell volume "
                       "(docs/MATH.md §7.10)");
  std::size_t leaving = 0;
  for (const persistence::Diagram& d : diagrams) {
    if (d.direction != persistence::Direction::forward)
      continue;
    const persistence::Diagram* reverse =
        find_diagram(diagrams, d.cell_type, persistence::Direction::reverse);
    if (reverse == nullptr)
      throw InternalError("run summary: no reverse diagram for type " + type_label(d.cell_type));
    const auto cells = std::find_if(from_cells.begin(), from_cells.end(),
                                    [&](const FatesFromCells& f) { return f.cell_type == d.cell_type; });
    if (cells == from_cells.end())
      throw InternalError("run summary: no fates from the cells of type " + type_label(d.cell_type));
    const ClassFates fates = class_fates(medusa, *cells, d, *reverse);
    std::string label = "all cells";
    if (d.cell_type != persistence::all_types) {
      label = cell_type_title(input, d.cell_type);
      if (fates.clusters.at_first == 1 && fates.clusters.joins == 0 && !medusa.cells_of_dimension(1).empty())
        warnings.push_back(label + " is one cluster from MCS " + mcs(t0) +
                           " on and no cluster joins it: at radius " + radius_text +
                           " its cells already touch at the first frame, so no merging can show "
                           "(a smaller radius, e.g. --radius auto, docs/MATH.md §7.10)");
    } else {
      leaving = fates.cells_leaving_at_first;
    }
    out << label << ":\n";
    describe_fates(out, fates, d, input.dimension, t0, t_end, store);
    // A planar run's H2 classes are space-time bubbles, none of which is filled (docs/MATH.md §7.6).
    for (const LongestFilled& c : longest)
      if (c.cell_type == d.cell_type && (c.dim == 1 || input.dimension == 3))
        describe_longest(out, c, store);
  }
  out << "Counts at MCS " << mcs(t0) << " and MCS " << mcs(t_end)
      << " are those of the complex at that frame (b0, b1, b2 of `medusa curves --frames-only`). Joins, "
         "filled and never-filled "
      << (input.dimension == 2 ? "loops" : "loops and cavities")
      << " come from the forward filtration (docs/MATH.md §7.6, §7.12): one that broke open without being "
         "filled "
         "stays a class of the space-time medusa (README, Reading the summary). The last join is when "
         "every cluster has touched another in space-time, not when the type became one cluster at every "
         "frame: a piece can split off and touch again later (`medusa report` gives the frame from which "
         "a type is one cluster to the end).\n"
      << "Times between frames come from linear interpolation of the cell centres between frames "
         "(docs/MATH.md §2.2).\n";
  if (leaving > 0)
    out << count(leaving, "cell", "cells") << " present at MCS " << mcs(t0)
        << " only left the complex at that instant: the clusters at MCS " << mcs(t0)
        << " are those just after; the loops and cavities present at MCS " << mcs(t0)
        << " are classes of the space-time medusa, which holds those cells, and the count just after is "
           "given beside them where it differs (docs/MATH.md §0, §2.4).\n";
  return warnings;
}

} // namespace medusa::cli
