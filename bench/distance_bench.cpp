// Distance benchmark: the pairwise distance matrices of many runs (docs/MATH.md §7.7) computed by
// libpersistence against gudhi.hera, the baseline a Python user would take, on the same diagrams.
// For each homology degree 0..2 and each filtration direction of the whole medusa (the diagrams
// `medusa compare` reads, on its normalised time axis), the bottleneck distance and W_1, W_2
// (ground metric L-infinity) over all pairs of runs. The diagrams are exported to text files and
// bench/hera_baseline.py computes the same distances with Hera in one Python process, launched from
// here; both sets of figures are printed in one table with their ratio and the largest disagreement.
//
// Essential classes: compared by count only (printed) and left out of the distance on both sides
// (ignore_essential here, finite points only for Hera). Diagonal points (birth == death after
// normalisation) are removed from both inputs, as Hera's bottleneck does not accept them; they do
// not change any distance. A pair of runs one of whose diagrams has no finite point is skipped on
// both sides (GUDHI 3.7's Hera does not return on an empty diagram) and counted.
//
// Usage: distance_bench --store run.h5 [--store ...] [--python /usr/bin/python3] [--tmp DIR] [--csv]
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/bottleneck.h"
#include "medusa/persistence/distance_matrix.h"
#include "medusa/persistence/medusa_diagrams.h"
#include "medusa/persistence/points.h"
#include "medusa/persistence/wasserstein.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace medusa;
using namespace medusa::persistence;
using Clock = std::chrono::steady_clock;

constexpr double hera_delta = 0.01; // Hera's relative error for W_p (hera_baseline.py)

struct Group {
  std::string name; // e.g. "H0 forward"
  std::vector<PointDiagram> diagrams;
};

struct Options {
  std::vector<std::string> stores;
  std::string python = "/usr/bin/python3";
  std::string script = MEDUSA_BENCH_DIR "/hera_baseline.py";
  std::string tmp = std::filesystem::temp_directory_path().string();
  bool csv = false;
};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The finite points off the diagonal; the essential births kept for the count.
PointDiagram without_diagonal(const PointDiagram& points) {
  PointDiagram result;
  result.essential = points.essential;
  for (const Point& p : points.finite)
    if (p.birth != p.death)
      result.finite.push_back(p);
  return result;
}

// One group per (degree, direction): the diagram of every run, as `medusa compare` builds it.
std::vector<Group> read_groups(const std::vector<std::string>& stores, std::vector<std::string>& names) {
  std::vector<Group> groups;
  for (int k = 0; k <= 2; ++k)
    for (const char* direction : {"forward", "reverse"})
      groups.push_back({"H" + std::to_string(k) + " " + direction, {}});
  for (const std::string& store : stores) {
    const medusa::Medusa medusa = medusa::read_store(store);
    names.push_back(std::filesystem::path(store).stem().string());
    if (medusa.input.frame_times.size() < 2)
      throw std::runtime_error(store + " has fewer than two frames");
    const double t0 = double(medusa.input.frame_times.front());
    const double t_end = double(medusa.input.frame_times.back());
    std::vector<int> vertex_type;
    for (const kinetic::Trajectory& t : medusa.input.cells)
      vertex_type.push_back(t.type);
    const std::vector<Diagram> diagrams = compute_medusa_diagrams(medusa.cells, vertex_type, {});
    for (int k = 0; k <= 2; ++k)
      for (std::size_t d = 0; d < 2; ++d) {
        const Diagram& diagram = diagrams[d]; // whole forward, whole reverse
        groups[std::size_t(2 * k) + d].diagrams.push_back(
            without_diagonal(normalise_time(to_points(diagram, k), diagram.direction, t0, t_end)));
      }
  }
  return groups;
}

void write_points(const std::string& path, const PointDiagram& points) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out)
    throw std::runtime_error("cannot write " + path);
  for (const Point& p : points.finite)
    std::fprintf(out, "%.17g %.17g\n", p.birth, p.death);
  if (std::fclose(out) != 0)
    throw std::runtime_error("cannot write " + path);
}

std::string fixed(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  return buffer;
}

const char* const metrics[] = {"bottleneck", "w1", "w2"};

// Our distance of the finite parts; the certified relative error of an approximate W_p goes to `error`.
double our_distance(const std::string& metric, const PointDiagram& a, const PointDiagram& b, double& error) {
  if (metric == "bottleneck")
    return bottleneck_distance(a, b, true).finite;
  WassersteinOptions options;
  options.p = metric == "w1" ? 1.0 : 2.0;
  options.ignore_essential = true;
  const DistanceResult r = wasserstein_distance(a, b, options);
  error = r.exact ? 0.0 : r.relative_error;
  return r.finite;
}

struct Ours {
  DistanceMatrix matrix;
  double seconds = 0;
  double relative_error = 0; // largest certified relative error of an approximate W_p
};

// The matrix as the library computes it, pairs with an empty diagram skipped (as on Hera's side).
Ours our_matrix(const std::string& metric, const std::vector<PointDiagram>& diagrams, unsigned workers) {
  Ours ours;
  std::mutex mutex;
  const DiagramMetric distance = [&](const PointDiagram& a, const PointDiagram& b) {
    if (a.finite.empty() || b.finite.empty())
      return 0.0;
    double error = 0;
    const double d = our_distance(metric, a, b, error);
    if (error > 0) {
      const std::lock_guard<std::mutex> lock(mutex);
      ours.relative_error = std::max(ours.relative_error, error);
    }
    return d;
  };
  const auto start = Clock::now();
  ours.matrix = distance_matrix(diagrams, distance, workers);
  ours.seconds = seconds_since(start);
  return ours;
}

std::size_t essential_mismatches(const std::vector<PointDiagram>& diagrams) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < diagrams.size(); ++i)
    for (std::size_t j = i + 1; j < diagrams.size(); ++j)
      n += diagrams[i].essential.size() != diagrams[j].essential.size();
  return n;
}

void run(const Options& o) {
  std::vector<std::string> names;
  const std::vector<Group> groups = read_groups(o.stores, names);
  const std::string dir = o.tmp + "/distance_bench." + std::to_string(getpid());
  std::filesystem::create_directories(dir);
  const std::string manifest = dir + "/manifest.tsv", output = dir + "/hera.json";
  {
    std::ofstream m(manifest);
    for (std::size_t g = 0; g < groups.size(); ++g) {
      std::vector<std::string> files;
      for (std::size_t r = 0; r < groups[g].diagrams.size(); ++r) {
        files.push_back(dir + "/g" + std::to_string(g) + "_" + names[r] + ".txt");
        write_points(files.back(), groups[g].diagrams[r]);
      }
      for (const char* metric : metrics) {
        m << groups[g].name << '\t' << metric;
        for (const std::string& f : files)
          m << '\t' << f;
        m << '\n';
      }
    }
  }
  const auto python_start = Clock::now();
  const std::string command = o.python + " " + o.script + " " + manifest + " " + output;
  if (std::system(command.c_str()) != 0)
    throw std::runtime_error("the Hera baseline failed: " + command);
  const double python_wall = seconds_since(python_start);
  nlohmann::json hera;
  std::ifstream(output) >> hera;
  std::filesystem::remove_all(dir);

  if (o.csv)
    std::printf("group,metric,pairs,skipped,essential_count_differs,max_points,ours_1_thread_s,"
                "ours_2_threads_s,hera_s,ratio,max_relative_difference\n");
  else
    std::printf(
        "%zu runs, %zu pairs per matrix; essential classes compared by count only; time "
        "normalised t -> (t - t0) / (t_end - t0)\n%-12s %-10s %6s %5s %6s %6s %10s %10s %10s %7s %9s\n",
        o.stores.size(), o.stores.size() * (o.stores.size() - 1) / 2, "diagrams", "metric", "pairs", "skip",
        "ess!=", "maxpts", "ours 1t s", "ours 2t s", "hera s", "ratio", "max diff");
  double total_ours1 = 0, total_ours2 = 0, total_hera = 0, worst = 0;
  std::size_t index = 0;
  for (const Group& group : groups) {
    std::size_t max_points = 0;
    for (const PointDiagram& d : group.diagrams)
      max_points = std::max(max_points, d.finite.size());
    for (const char* metric : metrics) {
      const nlohmann::json& h = hera.at(index++);
      if (h.at("group") != group.name || h.at("metric") != metric)
        throw std::runtime_error("the Hera output is out of order at " + group.name + " " + metric);
      const Ours one = our_matrix(metric, group.diagrams, 1);
      const Ours two = our_matrix(metric, group.diagrams, 2);
      // Both sides are exact for the bottleneck distance; for W_p each is within its certified
      // factor of the optimum, so their ratio lies in [1 / (1 + hera_delta), 1 + ours].
      double max_difference = 0;
      const double allowed = std::string(metric) == "bottleneck" ? 1e-12 : hera_delta + one.relative_error;
      for (const nlohmann::json& pair : h.at("pairs")) {
        const double value = pair.at(2), mine = one.matrix.at(pair.at(0), pair.at(1));
        const double difference = std::abs(mine - value) / std::max(value, 1e-300);
        max_difference = std::max(max_difference, difference);
        if (difference > allowed && std::abs(mine - value) > 1e-15)
          throw std::runtime_error(group.name + " " + metric + ": ours " + std::to_string(mine) + ", Hera " +
                                   std::to_string(value) + " for runs " + names[pair.at(0)] + ", " +
                                   names[pair.at(1)]);
      }
      const std::size_t all = group.diagrams.size() * (group.diagrams.size() - 1) / 2;
      const std::size_t computed = h.at("pairs").size();
      const double hera_seconds = h.at("seconds");
      total_ours1 += one.seconds;
      total_ours2 += two.seconds;
      total_hera += hera_seconds;
      if (computed > 0)
        worst = std::max(worst, one.seconds / hera_seconds);
      // A matrix whose every pair was skipped measures nothing: no ratio.
      const std::string ratio = computed == 0 ? "-" : fixed(one.seconds / hera_seconds);
      if (o.csv)
        std::printf("%s,%s,%zu,%zu,%zu,%zu,%.6f,%.6f,%.6f,%s,%.3g\n", group.name.c_str(), metric, computed,
                    all - computed, essential_mismatches(group.diagrams), max_points, one.seconds,
                    two.seconds, hera_seconds, ratio.c_str(), max_difference);
      else
        std::printf("%-12s %-10s %6zu %5zu %6zu %6zu %10.4f %10.4f %10.4f %7s %9.2g\n", group.name.c_str(),
                    metric, computed, all - computed, essential_mismatches(group.diagrams), max_points,
                    one.seconds, two.seconds, hera_seconds, ratio.c_str(), max_difference);
    }
  }
  if (!o.csv)
    std::printf("total: ours %.3f s on 1 thread (%.3f s on 2), Hera %.3f s (python process %.1f s wall); "
                "ratio %.2f, worst matrix %.2f (target <= 2)\n",
                total_ours1, total_ours2, total_hera, python_wall, total_ours1 / total_hera, worst);
}

void usage() {
  std::fprintf(stderr,
               "usage: distance_bench --store run.h5 --store ... [--python PATH] [--tmp DIR] [--csv]\n");
  std::exit(2);
}

} // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc)
        usage();
      return argv[++i];
    };
    if (a == "--store")
      o.stores.push_back(value());
    else if (a == "--python")
      o.python = value();
    else if (a == "--tmp")
      o.tmp = value();
    else if (a == "--csv")
      o.csv = true;
    else
      usage();
  }
  if (o.stores.size() < 2)
    usage();
  try {
    run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "distance_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
