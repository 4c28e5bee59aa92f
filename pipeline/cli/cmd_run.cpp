// `medusa run`: CC3D run -> trajectories -> kinetic alpha complex -> medusa store -> diagrams
// (docs/MATH.md §1-§7), with a plain-words summary on stdout.
#include "atomic_file.h"
#include "commands.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "kinetic_stage.h"
#include "progress_meter.h"
#include "run_input.h"
#include "run_outputs.h"
#include "run_summary.h"
#include "side_outputs.h"
#include "stage_timings.h"
#include "svg_plot.h"
#include "wrapping_summary.h"

#include "medusa/core/error.h"
#include "medusa/core/free_memory.h"
#include "medusa/core/job_pool.h"
#include "medusa/core/version.h"
#include "medusa/io/run_reader.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/async_observer.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/medusa/store_writer.h"
#include "medusa/periodic/canonical_filter.h"
#include "medusa/periodic/periodic_cover.h"
#include "medusa/periodic/torus_audit.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <utility>
#include <vector>

namespace medusa::cli {
namespace {

namespace fs = std::filesystem;

struct RunArguments {
  std::string input;
  std::string output;
  std::string radius = "auto";
  std::string source;
  std::string timings;
  unsigned threads = 0;         // 0: one per hardware thread
  std::size_t audit_stride = 0; // 0: not given (audit, if at all, after every batch)
  bool audit = false, snap = false, exact_vtk = false, round_csv = false, periodic_as_open = false,
       quiet = false, progress = false, force = false;
  bool skip_unreadable_frames = false;
  bool shorten_representatives = false;
};

// --radius: 'auto' or a positive decimal (digits with at most one point, as the exact grid needs:
// docs/MATH.md §1.1); "" when valid, else CLI11's message.
std::string radius_problem(const std::string& value) {
  if (value == "auto")
    return "";
  if (value.size() > 1 && value[0] == '-' && radius_problem(value.substr(1)).empty())
    return "'" + value + "' is not positive: a radius is a length";
  const bool digits_only = value.find_first_not_of("0123456789.") == std::string::npos &&
                           std::count(value.begin(), value.end(), '.') <= 1 &&
                           value.find_first_of("0123456789") != std::string::npos;
  if (!digits_only || value.size() > 40)
    return "'" + value.substr(0, 40) +
           "' is not 'auto' or a decimal number of lattice units such as 3 or 2.5";
  if (value.find_first_of("123456789") == std::string::npos)
    return "'" + value + "' is not positive";
  return "";
}

// --audit-stride: a positive whole number; "" when valid, else CLI11's message.
std::string stride_problem(const std::string& value) {
  const bool digits_only = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
  if (!digits_only || value.size() > 18)
    return "'" + value.substr(0, 40) + "' is not a positive whole number of batches such as 1 or 50";
  if (value.find_first_of("123456789") == std::string::npos)
    return "'" + value + "' is not positive";
  return "";
}

// Forwards the event stream to the builder (through EndAfterLastBatch, which also polls for
// interrupts) and reports progress. It also times the builder (which streams the store) apart from
// the kinetic engine that calls it.
class ProgressObserver : public kinetic::Observer {
public:
  ProgressObserver(kinetic::Observer& next, const kinetic::KineticAlphaComplex& engine, ProgressMeter& meter,
                   std::size_t frames)
      : next_(next), engine_(engine), meter_(meter), frames_(frames) {}
  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override {
    timed([&] { next_.initial(t0, complex); });
    peak_rss_at_frame_.push_back(peak_rss_bytes());
    meter_.update(1, 0);
  }
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override {
    timed([&] { next_.batch(time, steps); });
    meter_.update(frames_reached_, engine_.statistics().events());
  }
  void frame(std::size_t k, const kinetic::EventTime& time) override {
    timed([&] { next_.frame(k, time); });
    frames_reached_ = k + 1;
    peak_rss_at_frame_.push_back(peak_rss_bytes());
    meter_.update(frames_reached_, engine_.statistics().events());
  }
  void finish(const kinetic::EventTime& t_end) override {
    meter_.finish_kinetic(engine_.statistics().events());
    meter_.stage("medusa store: closing");
    timed([&] { next_.finish(t_end); });
    peak_rss_at_frame_.push_back(peak_rss_bytes());
  }
  // Wall seconds spent in the builder and the store writer.
  double builder_seconds() const { return builder_seconds_; }
  // The process's peak RSS when each frame was reached (for checking that memory is flat in frames).
  const std::vector<std::int64_t>& peak_rss_at_frame() const { return peak_rss_at_frame_; }

private:
  // Wall time only, from the steady clock (no system call): a CPU clock read per callback is a
  // system call, and on a loaded machine the process is often descheduled at its return, which
  // would charge other processes' time to the builder.
  template <class F> void timed(const F& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    builder_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  kinetic::Observer& next_;
  const kinetic::KineticAlphaComplex& engine_;
  ProgressMeter& meter_;
  std::size_t frames_;
  std::size_t frames_reached_ = 1;
  double builder_seconds_ = 0.0;
  std::vector<std::int64_t> peak_rss_at_frame_;
};

// The bundled run `medusa run` processes without an argument: the installed copy beside the binary
// (<prefix>/share/medusa/examples/sorting_3d for <prefix>/bin/medusa), else the source tree's (a
// binary in the build tree).
std::string bundled_example() {
  std::vector<fs::path> places;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    places.push_back((self.parent_path() / MEDUSA_EXAMPLES_FROM_BINDIR / "sorting_3d").lexically_normal());
  places.push_back(fs::path(MEDUSA_SOURCE_DIR) / "examples" / "sorting_3d");
  for (const fs::path& p : places)
    if (fs::is_directory(p, ec))
      return p.string();
  throw InputError("no input given and the bundled example is in neither " + places.front().string() +
                   (places.size() > 1 ? " nor " + places.back().string() : std::string()) +
                   "; give a CC3D output folder or cells.csv[.gz]");
}

// The size of the run read, for --timings once its trajectories are gone.
struct InputCounts {
  std::size_t cells = 0;
  std::size_t frames = 0;
};

// What the summary and --timings report about the stages after the kinetic one.
struct StoreFacts {
  std::size_t cells = 0;
  std::size_t diagrams = 0;
};

// What the run prints once its outputs are published.
struct RunResult {
  medusa::Medusa medusa;
  std::vector<persistence::Diagram> diagrams;
  std::vector<FatesFromCells> from_cells; // the summary's counts that need no diagram, per sub-medusa
  std::vector<LongestFilled> longest;     // the summary's longest-lived filled loop and cavity per type
  StoreFacts facts;
};

// Writes `path` (a temporary of RunOutputs) whole; StoreError naming `shown` if it cannot.
void write_temporary(const std::string& path, const std::string& shown,
                     const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out)
    throw StoreError("cannot create " + path + " (for " + shown + ")");
  write(out);
  out.flush();
  if (!out)
    throw StoreError("cannot write " + shown + " (disk full?)");
  out.close();
  if (!out)
    throw StoreError("cannot write " + shown + " (disk full?)");
}

// Diagrams from the stored cells, so that what later commands see is what the summary describes.
// Everything goes to the temporaries of `outputs`; nothing is published here.
RunResult compute_diagrams(const RunOutputs& outputs, const std::string& run_id, unsigned threads,
                           const persistence::RepresentativeOptions& representatives, ProgressMeter& meter,
                           StageTimings& timings) {
  const std::string& store = outputs.store_temporary();
  meter.stage("medusa store: reading back " + outputs.final_name(0));
  StageClock clock;
  // The summary's counts at the first and last frames need the batches that reach them, not the
  // other batch records (one per event time).
  RunResult result;
  medusa::StoreReadOptions frame_batches;
  frame_batches.every_batch = false;
  result.medusa = medusa::read_store(store, frame_batches);
  const medusa::Medusa& medusa = result.medusa;
  timings.add("medusa_store", clock);
  check_interrupted();

  const std::vector<int> vertex_type = vertex_types(medusa);
  const std::vector<int> types = distinct_types(vertex_type);
  // The summary's counts at the first and last frames, and the reduction of each coned sub-medusa that
  // splits its open classes (docs/MATH.md §7.12), come before the diagrams: that reduction is as large
  // as a whole-medusa filtration's, and after the diagrams it would run beside all their pairs.
  // One job per sub-medusa, the whole medusa's alone in memory as in the diagrams below: the cell
  // types' run beside it on the other threads.
  const std::vector<int> sub_medusas = persistence::sub_medusa_types(types);
  meter.stage("first and last frames: complexes and open classes (whole medusa and " +
              std::to_string(types.size()) + " cell types, PHAT)" + " on " +
              std::to_string(std::min<std::size_t>(threads, sub_medusas.size())) + " thread(s)");
  clock = StageClock{};
  result.from_cells.resize(sub_medusas.size());
  const auto whole = [&](std::size_t i) { return sub_medusas[i] == persistence::all_types; };
  medusa::run_jobs(sub_medusas.size(), threads, whole, [&](std::size_t i) {
    result.from_cells[i] = fates_from_cells(medusa, sub_medusas[i]);
    medusa::release_free_memory();
  });
  timings.add("reduction", clock);
  check_interrupted();

  const std::size_t count = 2 * persistence::sub_medusa_types(types).size(); // forward and reverse
  const std::string on = " on " + std::to_string(std::min<std::size_t>(threads, count)) + " thread(s)";
  meter.stage("filtrations and reductions: " + std::to_string(count) + " (whole medusa and " +
              std::to_string(types.size()) + " cell types, forward and reverse, " +
              std::to_string(medusa.cells.size()) + " cells, PHAT)" + on);
  // Each task builds one filtration, reduces it and frees it (at most `threads` in memory, at most one
  // of them of the whole medusa). Each diagram goes into the store as soon as it is made, with the
  // representatives of its classes (forward diagrams, docs/MATH.md §7.11), and the summary takes its
  // longest filled classes from it; then its zero-length pairs and representatives are dropped, so
  // that they never all sit in memory at once. The stages overlap on the threads, so their wall and
  // CPU seconds are the measured totals split in proportion to the tasks' time in each phase.
  clock = StageClock{};
  persistence::DiagramPhaseSeconds phases;
  std::vector<persistence::ClassRepresentatives> classes;
  persistence::DiagramStoreWriter writer(store, persistence::medusa_diagram_names(types));
  std::vector<std::vector<LongestFilled>> longest(count);
  persistence::DiagramRunOptions options;
  options.threads = threads;
  options.phases = &phases;
  options.forward_classes = &classes;
  options.representatives = representatives;
  options.poll = check_interrupted;
  options.zero_length = false;
  options.on_diagram = [&](std::size_t i, persistence::Diagram& d, persistence::ClassRepresentatives* c) {
    writer.write(d, c);
    if (c != nullptr) // class ids are rows of the diagram as stored, zero-length pairs included
      longest[i] = longest_filled_classes(medusa, d, *c);
  };
  result.diagrams = persistence::compute_medusa_diagrams(medusa.cells, vertex_type, types, options);
  std::vector<persistence::Diagram>& diagrams = result.diagrams;
  writer.close();
  for (std::vector<LongestFilled>& l : longest)
    result.longest.insert(result.longest.end(), l.begin(), l.end());
  const double all = phases.filtrations + phases.reduction + phases.handed_over;
  const double wall = clock.wall_seconds(), cpu = clock.cpu_seconds();
  const auto share = [&](double phase) { return all > 0 ? phase / all : 1.0 / 3; };
  timings.add("filtrations", share(phases.filtrations) * wall, share(phases.filtrations) * cpu);
  timings.add("reduction", share(phases.reduction) * wall, share(phases.reduction) * cpu);
  check_interrupted();

  const std::string& csv = outputs.final_name(1);
  const std::string& svg = outputs.final_name(2);
  const std::string& diagram_svg = outputs.final_name(3);
  meter.stage("exports: " + csv + ", " + svg + ", " + diagram_svg + ", summary");
  clock = StageClock{};
  // The diagrams went into the store (group /persistence, docs/FORMAT.md) as they were made.
  timings.add("exports", share(phases.handed_over) * wall, share(phases.handed_over) * cpu);
  const double t0 = static_cast<double>(medusa.input.frame_times.front());
  const double t_end = static_cast<double>(medusa.input.frame_times.back());
  write_temporary(outputs.temporary(1), csv,
                  [&](std::ostream& out) { write_csv(out, diagrams, medusa.input.type_names, run_id); });
  write_temporary(outputs.temporary(2), svg, [&](std::ostream& out) {
    write_barcode_svg(out, diagrams, medusa.input.type_names, t0, t_end, default_max_bars, run_id);
  });
  write_temporary(outputs.temporary(3), diagram_svg, [&](std::ostream& out) {
    write_diagram_svg(out, diagrams, medusa.input.type_names, t0, t_end, default_max_points, run_id);
  });
  check_interrupted();
  timings.add("exports", clock);
  result.facts = {medusa.cells.size(), diagrams.size()};
  return result;
}

// One line for the user after --audit: how many audits of the kinetic structure passed, and when.
std::string describe_audits(const kinetic::KineticStatistics& stats, std::size_t stride) {
  return "audit: " + std::to_string(stats.audits) + " audit" + (stats.audits == 1 ? "" : "s") +
         " of the kinetic structure passed (" + std::to_string(stats.audits_compared_with_cgal) +
         " equal to static CGAL's alpha complex simplex for simplex), at the start, at every frame and "
         "after " +
         (stride == 1 ? std::string("every batch of events")
                      : "every " + std::to_string(stride) + " batches of events");
}

// The machine-readable record of --timings (read by bench/e2e_bench.py).
void write_timings(const RunOutputs& outputs, const std::string& run_id, const RunArguments& args,
                   const InputCounts& input, const std::string& radius, const StageTimings& timings,
                   const kinetic::KineticStatistics& stats,
                   const std::vector<std::int64_t>& peak_rss_at_frame, const StoreFacts& facts,
                   unsigned threads) {
  nlohmann::ordered_json j;
  j["run_id"] = run_id;
  j["input"] = args.input;
  j["cells"] = input.cells;
  j["frames"] = input.frames;
  j["radius"] = radius;
  j["threads"] = threads;
  nlohmann::ordered_json wall = nlohmann::ordered_json::object(), cpu = nlohmann::ordered_json::object();
  for (const std::string& name : stage_names()) {
    wall[name] = timings.wall(name);
    cpu[name] = timings.cpu(name);
  }
  j["stage_seconds"] = wall;
  j["total_seconds"] = timings.total_wall();
  j["stage_cpu_seconds"] = cpu;
  j["total_cpu_seconds"] = timings.total_cpu();
  j["peak_rss_bytes"] = peak_rss_bytes();
  nlohmann::ordered_json rss = nlohmann::ordered_json::object();
  for (const std::string& name : stage_names())
    rss[name] = timings.peak_rss_after(name);
  j["peak_rss_bytes_after_stage"] = rss;
  j["peak_rss_bytes_at_frame"] = peak_rss_at_frame;
  const std::uint64_t events = stats.events();
  const double kinetic_seconds = timings.wall("kinetic");
  j["events"] = events;
  j["events_per_second"] = kinetic_seconds > 0 ? static_cast<double>(events) / kinetic_seconds : 0.0;
  j["event_counts"] = {{"flips23", stats.flips23},
                       {"flips32", stats.flips32},
                       {"flips22", stats.flips22},
                       {"hull_flips", stats.hull_flips},
                       {"radius_events", stats.radius_events},
                       {"insertions", stats.insertions},
                       {"deletions", stats.deletions},
                       {"local_insertions", stats.local_insertions},
                       {"local_deletions", stats.local_deletions},
                       {"batches", stats.batches},
                       {"frame_batches", stats.frame_batches},
                       {"certificates_built", stats.certificates_built},
                       {"static_rebuilds", stats.static_rebuilds},
                       {"repairs_at_algebraic_times", stats.repairs_at_algebraic_times},
                       {"frames_repaired_for_flat_simplices", stats.frames_repaired_for_flat_simplices},
                       {"hull_ridges_folded_at_now", stats.hull_ridges_folded_at_now},
                       {"hull_touches_repaired", stats.hull_touches_repaired},
                       {"hull_flips_refused_touching", stats.hull_flips_refused_touching},
                       {"times_compared_algebraically", stats.times_compared_algebraically},
                       {"times_compared_as_one_polynomial", stats.times_compared_as_one_polynomial}};
  j["kinetic_seconds_per_frame"] = stats.seconds_per_frame;
  // --audit: the engine's audits (one at the start, one at every frame, one after every stride-th
  // batch of events), and those that compared the complex with static CGAL's (docs/ARCHITECTURE.md).
  j["audit"] = {{"on", args.audit},
                {"stride", args.audit ? std::max<std::size_t>(args.audit_stride, 1) : 0},
                {"audits", stats.audits},
                {"compared_with_cgal", stats.audits_compared_with_cgal}};
  std::error_code ec;
  const auto bytes = fs::file_size(outputs.store_temporary(), ec);
  j["store"] = {{"path", outputs.final_name(0)},
                {"bytes", ec ? -1 : static_cast<std::int64_t>(bytes)},
                {"cells", facts.cells},
                {"diagrams", facts.diagrams}};
  write_temporary(outputs.temporary(4), outputs.final_name(4),
                  [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

std::string size_text(const std::string& input) {
  std::error_code ec;
  std::uintmax_t bytes = 0;
  if (fs::is_directory(input, ec)) {
    for (auto it = fs::recursive_directory_iterator(input, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file(ec))
        bytes += it->file_size(ec);
  } else {
    bytes = fs::file_size(input, ec);
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return buffer;
}

void run_command(const RunArguments& args, const std::string& command_line) {
  const std::string input = args.input.empty() ? bundled_example() : args.input;
  std::error_code ec;
  if (!fs::exists(input, ec))
    throw InputError("input " + input + " does not exist");
  const unsigned threads = worker_threads(args.threads);

  // Every output is checked and the store's lock taken before anything is read or written.
  const std::string output = args.output.empty() ? input_stem(input) + ".h5" : args.output;
  check_output_folder(output);
  // A store holds a run's whole analysis: replacing one is asked for, never a side effect.
  const bool replacing = fs::exists(output, ec);
  if (!args.force && replacing)
    throw CLI::ParseError("store " + output + " exists; pass --force to replace it", 2);
  const std::string stem = output_stem(output);
  // What the other commands wrote from the store being replaced, under their default names: left as
  // they are (they may be kept on purpose), but said, since they no longer describe the store.
  std::vector<std::string> stale;
  if (replacing)
    for (const char* suffix : {".curves.csv", ".curves.svg", ".sorting.csv", ".sorting.svg", ".report.html"})
      if (fs::exists(stem + suffix, ec))
        stale.push_back(stem + suffix);
  std::vector<std::string> side = {stem + ".diagrams.csv", stem + ".barcode.svg", stem + ".diagram.svg"};
  if (!args.timings.empty())
    side.push_back(args.timings);
  RunOutputs outputs(output, side, input);
  const std::string run_id = new_run_id();

  ProgressMeter meter(std::cerr,
                      ProgressMeter::choose(args.progress, args.quiet, ::isatty(STDERR_FILENO) != 0));
  StageTimings timings;
  RunArguments resolved = args;
  resolved.input = input;
  io::RunOptions options;
  options.source = choose_source(input, args.source);
  options.snap = !args.exact_vtk;
  options.round_csv = args.round_csv;
  options.allow_periodic_as_open = args.periodic_as_open;
  options.read_periodic = !args.periodic_as_open;
  options.skip_unreadable_frames = args.skip_unreadable_frames;
  meter.stage("reading " + input);
  StageClock clock;
  io::RunData data;
  try {
    data = io::read_run(input, options);
  } catch (const std::bad_alloc&) {
    throw InputError(input + ": out of memory while reading it (" + size_text(input) +
                     " on disk); the input is larger than the memory available, or malformed");
  }
  timings.add("reading", clock);
  outputs.check_not_read(data.sources);
  if (!args.quiet) {
    for (const std::string& w : data.warnings)
      std::cerr << "medusa: warning: " << w << "\n";
    for (const std::string& n : data.notes)
      std::cerr << "medusa: " << n << "\n";
  }

  const auto [radius, radius_note] = resolve_radius(args.radius, data);
  kinetic::KineticOptions kinetic_options;
  kinetic_options.rho2 = kinetic::squared_radius_from_decimal(radius, data.trajectories.scale);
  kinetic_options.audit = args.audit;
  kinetic_options.audit_stride = args.audit_stride > 0 ? args.audit_stride : 1;
  // A periodic run goes through the covering space: the cells and their copies near the seams, with
  // the canonical filter in front of the builder (docs/MATH.md §8). Refused before any output exists.
  std::optional<periodic::PeriodicCover> cover;
  if (data.domain.any() && !args.periodic_as_open) {
    periodic::check_periodic_radius(data.domain, kinetic_options.rho2, radius);
    cover = periodic::cover_trajectories(data.trajectories, data.domain, kinetic_options.rho2);
    cover->trajectories.validate();
    if (!args.quiet)
      std::cerr << "medusa: periodic along " << data.domain.axes() << ": the complex on the torus, with "
                << cover->ghosts()
                << " trajectories of periodic copies of cells near them (docs/MATH.md §8)\n";
  }

  medusa::RunInfo info = run_info(data, radius, command_line);
  info.run_id = run_id;
  if (cover) {
    info.periodic_axes = data.domain.axes();
    info.periodic_lengths = data.domain.period;
  }

  kinetic::KineticStatistics stats;
  std::vector<std::int64_t> peak_rss_at_frame;
  {
    clock = StageClock{};
    kinetic::KineticAlphaComplex engine(cover ? cover->trajectories : data.trajectories, kinetic_options);
    // Finished, the store stays under its temporary name (outputs.store_temporary()) until publish.
    medusa::StoreWriter writer(outputs.final_name(0), medusa::StoreWriter::Publish::later);
    medusa::MedusaBuilder builder(writer);
    builder.set_run(info, data.trajectories);
    // With more than one thread the builder and the store writer run beside the engine, on a thread
    // of their own (AsyncObserver); declared after them, it stops before they are destroyed. The peak
    // memory sampled at each frame then includes the calls still queued for them (a few blocks).
    std::optional<medusa::AsyncObserver> beside;
    if (threads > 1)
      beside.emplace(builder);
    kinetic::Observer& store_side = beside ? static_cast<kinetic::Observer&>(*beside) : builder;
    meter.start_kinetic(data.trajectories.frames());
    EndAfterLastBatch ended(store_side);
    ProgressObserver observer(ended, engine, meter, data.trajectories.frames());
    // With --audit, the complex on the torus is checked against static CGAL as it leaves the
    // canonical filter (docs/MATH.md §8.7), besides the engine's own audit of the covering space.
    std::optional<periodic::TorusAudit> torus_audit;
    if (cover && args.audit)
      torus_audit.emplace(*cover, data.domain, kinetic_options.rho2, data.trajectories.dimension,
                          kinetic_options.audit_stride, observer);
    std::optional<periodic::CanonicalFilter> torus;
    if (cover)
      torus.emplace(*cover, torus_audit ? static_cast<kinetic::Observer&>(*torus_audit) : observer);
    try {
      engine.run(torus ? static_cast<kinetic::Observer&>(*torus) : observer);
    } catch (const GeometryError& e) {
      throw GeometryError(input + ": " + e.what()); // collisions name cells and times, not the file
    }
    // The engine's wall time includes the time spent in the store side's callbacks (with a thread of
    // its own: queueing the calls, and waiting for it at the end), which belongs to the store stage;
    // their CPU time is not measured apart (see ProgressObserver::timed) and stays in the kinetic
    // stage's.
    timings.add("kinetic", clock.wall_seconds() - observer.builder_seconds(), clock.cpu_seconds());
    timings.add("medusa_store", observer.builder_seconds(), 0.0);
    stats = engine.statistics();
    if (args.audit && !args.quiet)
      std::cerr << "medusa: " << describe_audits(stats, kinetic_options.audit_stride) << "\n";
    if (torus_audit && !args.quiet)
      std::cerr << "medusa: " << periodic::describe(torus_audit->statistics()) << "\n";
    peak_rss_at_frame = observer.peak_rss_at_frame();
  }
  // The engine is gone: the stages below (which hold the whole medusa) reuse its memory instead of
  // adding to it, and the freed pages go back to the system so that worker threads' heaps can have
  // them too. Peak memory is then the larger of the two parts, not their sum. The trajectories read
  // (and the covering space's) go too: the stages below read them back from the store with the cells.
  const InputCounts input_counts{data.trajectories.cells.size(), data.trajectories.frames()};
  data.trajectories = kinetic::Trajectories{};
  cover.reset();
  medusa::release_free_memory();

  check_interrupted();
  persistence::RepresentativeOptions representatives;
  representatives.shorten = args.shorten_representatives;
  const RunResult result = compute_diagrams(outputs, run_id, threads, representatives, meter, timings);
  // The summary is composed before the outputs are published (it names them by their final names)
  // and counted in the exports, so that --timings records the whole run's peak memory.
  StageClock clock_summary;
  std::ostringstream summary;
  const std::vector<std::string> warnings =
      write_run_summary(summary, result.medusa, stats, result.diagrams, result.from_cells, radius,
                        radius_note, result.longest, outputs.final_name(0));
  write_wrapping_loops(summary, result.medusa, outputs.store_temporary());
  timings.add("exports", clock_summary);
  if (!args.timings.empty())
    write_timings(outputs, run_id, resolved, input_counts, radius, timings, stats, peak_rss_at_frame,
                  result.facts, threads);
  // The last moment an interrupt undoes the run: after it, the outputs replace the previous ones.
  check_interrupted();
  outputs.publish();
  std::cout << summary.str();
  if (!args.quiet) {
    for (const std::string& w : warnings)
      std::cerr << "medusa: warning: " << w << "\n";
    if (!stale.empty()) {
      std::cerr << "medusa: warning: written from the store this run replaced, and left as they were: ";
      for (std::size_t i = 0; i < stale.size(); ++i)
        std::cerr << (i == 0 ? "" : ", ") << stale[i];
      std::cerr << " (rerun the commands that wrote them)\n";
    }
  }
  std::cout << "wrote " << outputs.final_name(0) << ", " << outputs.final_name(1) << ", "
            << outputs.final_name(2) << ", " << outputs.final_name(3) << "\n";
}

} // namespace

void add_run_command(CLI::App& app, const std::string& command_line) {
  auto args = std::make_shared<RunArguments>();
  CLI::App* run = app.add_subcommand(
      "run", "Compute the alpha medusa of a CompuCell3D run, store it, and write its persistence diagrams");
  run->add_option("input", args->input,
                  "CC3D output folder or cells.csv[.gz] (default: the bundled examples/sorting_3d)");
  run->add_option("-o,--output", args->output,
                  "HDF5 store to write (default: <input-name>.h5 here; a cells.csv[.gz] is named after its "
                  "folder)");
  run->add_flag("--force", args->force,
                "replace the store if it exists (otherwise an existing store is an error)");
  run->add_option(
         "--radius", args->radius,
         "alpha radius rho in lattice units (decimal): cells are balls of radius rho around their "
         "centres, and two cells touch when their centres are closer than 2 rho. 'auto': the radius "
         "of a ball (a disc in 2D) of the median cell volume over all cells and frames (docs/MATH.md "
         "§7.10)")
      ->capture_default_str()
      ->check(CLI::Validator([](std::string& value) { return radius_problem(value); }, "RADIUS"));
  run->add_option("--source", args->source,
                  "positions from 'csv' (cells.csv.gz, CC3D centres; default for a folder that has it) or "
                  "'vtk' (voxel centroids, snapped to the 10^-6 grid as CC3D's centres are rounded; the "
                  "snap is recorded in the store, docs/MATH.md §1.3)")
      ->check(CLI::IsMember({"csv", "vtk"}));
  run->add_flag("--exact-vtk", args->exact_vtk,
                "refuse VTK centroids off the 10^-6 grid instead of snapping them");
  run->add_flag("--round-csv", args->round_csv,
                "round CSV centres with more than 6 decimals to the 10^-6 grid (nearest, ties to even; "
                "recorded in the store, docs/MATH.md §1.2) instead of refusing them");
  run->add_flag("--snap", args->snap,
                "snap VTK centroids to the 10^-6 grid (the default; accepted for older scripts)");
  run->add_flag("--periodic-as-open", args->periodic_as_open,
                "read a periodic run as if its boundaries were open");
  run->add_flag(
      "--skip-unreadable-frames", args->skip_unreadable_frames,
      "go on, with a warning naming each, past LatticeData snapshots that cannot be read (dangling "
      "link, FIFO, folder, no permission, cut short or corrupt) or are missing from the series, and "
      "past CSV frames "
      "missing from the series or incomplete (lacking most of the cells around them, or a last "
      "frame stopping partway: left out), instead of stopping");
  run->add_flag("--shorten-representatives", args->shorten_representatives,
                "store shortened class representatives (degrees 1 and 2: each cycle greedily reduced by "
                "boundaries of cells entered before the class dies; the same class, not necessarily the "
                "shortest cycle, docs/MATH.md §7.13); `medusa classes --shorten` does it for one diagram "
                "on demand");
  run->add_flag("--audit", args->audit,
                "check the kinetic structure against static CGAL computations at the start, at every frame "
                "and after every batch of events (slow; --audit-stride for long runs)");
  run->add_option("--audit-stride", args->audit_stride,
                  "audit after every N-th batch of events only (still at every frame), to audit a long "
                  "run in bounded time; implies --audit")
      ->type_name("N")
      ->check(CLI::Validator([](std::string& value) { return stride_problem(value); }, ""));
  run->add_flag("--progress", args->progress,
                "report progress on stderr (stage; frame k/K, events/s, elapsed and ETA during the kinetic "
                "stage) even when stderr is not a terminal, then one line per update");
  run->add_flag("-q,--quiet", args->quiet, "no warnings and no progress on stderr");
  run->add_option("--threads", args->threads,
                  "worker threads for the filtrations and reductions, and for the store writer beside the "
                  "kinetic engine (0 = one per hardware thread; 1 = sequential); the results do not "
                  "depend on it")
      ->capture_default_str();
  run->add_option(
      "--timings", args->timings,
      "write wall and CPU seconds per stage (reading, kinetic, medusa_store, filtrations, reduction, "
      "exports), peak RSS, kinetic events, the audits of --audit and store size to this JSON file");
  run->callback([args, command_line] {
    if (args->snap && args->exact_vtk)
      throw CLI::ValidationError("--exact-vtk", "contradicts --snap: give one of them");
    if (args->audit_stride > 0)
      args->audit = true;
    run_command(*args, command_line);
  });
}

} // namespace medusa::cli
