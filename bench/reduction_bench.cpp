// Reduction benchmark: the forward filtration of a medusa reduced by libpersistence in memory
// (make_filtration, then reduce: the PHAT boundary matrix built from the filtration and reduced with
// compact_pivot_column + twist_reduction, docs/MATH.md §7.5) against PHAT's own `phat` command on the same
// boundary matrix saved in PHAT's binary format, and against what that command does (load_binary +
// compute_persistence_pairs) run in this process. Checks that the three give the same pairs, then
// prints times, peak memory and the ratios ours / phat.
//
// Usage: reduction_bench --store run.h5 [--store other.h5 ...] [--per-type] [--repeat N]
//                        [--phat /usr/bin/phat] [--tmp DIR] [--csv]
// Stores are written by `medusa run` (bench/run_persistence_benches.sh builds the ones of
// bench/README.md). Times are the minimum over the repeats; memory is the peak resident set above
// the resident set before the step (reset through /proc/self/clear_refs), and for the `phat` child
// its own maximum resident set (wait4).
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/boundary_matrix.h"
#include "medusa/persistence/filtration.h"

#include <fcntl.h>
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace medusa;
using namespace medusa::persistence;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A field of /proc/self/status in KiB (VmRSS, VmHWM).
long status_kib(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(field);
  while (std::getline(in, line))
    if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
      return std::atol(line.c_str() + n + 1);
  return -1;
}

// Starts a memory measurement: returns freed memory to the system and resets the peak resident set
// to the current one, so that VmHWM afterwards is the peak of the measured step alone.
long start_memory() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  return status_kib("VmRSS");
}

double mib(long kib) { return double(kib) / 1024.0; }

struct Measure {
  double seconds = 1e300; // minimum over the repeats
  long peak_kib = 0;      // of the first repeat
};

// Runs `step` `repeat` times, keeping the minimum time and the memory peak of the first run.
Measure measure(int repeat, const std::function<void()>& step) {
  Measure m;
  for (int r = 0; r < repeat; ++r) {
    const long before = start_memory();
    const auto start = Clock::now();
    step();
    m.seconds = std::min(m.seconds, seconds_since(start));
    if (r == 0)
      m.peak_kib = status_kib("VmHWM") - before;
  }
  return m;
}

// Runs `phat` on `matrix` in a child process with its output discarded; its wall time and maximum
// resident set.
Measure run_phat(const std::string& phat, const std::string& matrix, const std::string& pairs) {
  const auto start = Clock::now();
  const pid_t child = fork();
  if (child < 0)
    throw std::runtime_error("fork failed");
  if (child == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    execl(phat.c_str(), phat.c_str(), "--binary", "--bit_tree_pivot_column", "--twist", matrix.c_str(),
          pairs.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(phat + " failed on " + matrix);
  Measure m;
  m.seconds = seconds_since(start);
  m.peak_kib = usage.ru_maxrss;
  return m;
}

std::vector<IndexPair> sorted_pairs(phat::persistence_pairs& pairs) {
  pairs.sort();
  std::vector<IndexPair> result;
  for (phat::index i = 0; i < pairs.get_num_pairs(); ++i)
    result.emplace_back(pairs.get_pair(i).first, pairs.get_pair(i).second);
  return result;
}

struct Options {
  std::vector<std::string> stores;
  bool per_type = false;
  int repeat = 5;
  std::string phat = "/usr/bin/phat";
  std::string tmp = std::filesystem::temp_directory_path().string();
  bool csv = false;
  Measure phat_idle; // the phat command on a one-column matrix: its own start-up time and memory
};

void print_header(const Options& o) {
  if (o.csv)
    std::printf("case,columns,entries,pairs,filtration_s,ours_reduce_s,ours_total_s,ours_mib,"
                "phat_load_s,phat_reduce_s,phat_inproc_total_s,phat_inproc_mib,phat_cli_s,phat_cli_mib,"
                "phat_cli_above_idle_mib,ratio_reduce,ratio_memory_reduce,ratio_end_to_end,ratio_memory_end_"
                "to_end\n");
}

// One boundary matrix: our path, PHAT in this process, the phat command; same pairs required.
void run_case(const Options& o, const std::string& name, const std::vector<medusa::Cell>& cells,
              const std::vector<int>& vertex_type, int type) {
  const auto filtration_of = [&] {
    return type == all_types ? make_filtration(cells, Direction::forward)
                             : make_type_filtration(cells, vertex_type, type, Direction::forward);
  };
  // Ours, end to end from the cells: the filtration, then reduce (matrix + reduction + sorted pairs).
  std::vector<IndexPair> ours;
  Filtration f;
  const Measure filtration = measure(o.repeat, [&] { f = filtration_of(); });
  const Measure reduction = measure(o.repeat, [&] { ours = reduce(f); });
  Measure together = measure(1, [&] {
    Filtration g = filtration_of();
    ours = reduce(g);
  });
  together.seconds = filtration.seconds + reduction.seconds;
  const std::size_t entries = f.columns.entries();

  const std::string matrix = o.tmp + "/reduction_bench." + std::to_string(getpid()) + ".matrix.bin";
  const std::string pairs_file = o.tmp + "/reduction_bench." + std::to_string(getpid()) + ".pairs.bin";
  write_phat_binary(f, matrix);
  const std::size_t columns = f.size();
  f = Filtration();

  // PHAT in this process, as the phat command does it.
  std::vector<IndexPair> in_process;
  Measure load, compute;
  const Measure phat_total = measure(o.repeat, [&] {
    phat::boundary_matrix<phat::bit_tree_pivot_column> m;
    auto start = Clock::now();
    m.load_binary(matrix);
    load.seconds = std::min(load.seconds, seconds_since(start));
    phat::persistence_pairs pairs;
    start = Clock::now();
    phat::compute_persistence_pairs<phat::twist_reduction>(pairs, m);
    compute.seconds = std::min(compute.seconds, seconds_since(start));
    in_process = sorted_pairs(pairs);
  });

  Measure cli;
  for (int r = 0; r < o.repeat; ++r) {
    const Measure m = run_phat(o.phat, matrix, pairs_file);
    cli.seconds = std::min(cli.seconds, m.seconds);
    cli.peak_kib = std::max(cli.peak_kib, m.peak_kib);
  }
  const std::vector<IndexPair> from_cli = read_phat_binary_pairs(pairs_file);
  std::filesystem::remove(matrix);
  std::filesystem::remove(pairs_file);
  if (ours != in_process || ours != from_cli)
    throw std::runtime_error(name + ": the pairs differ (ours " + std::to_string(ours.size()) + ", PHAT " +
                             std::to_string(in_process.size()) + ", phat command " +
                             std::to_string(from_cli.size()) + ")");

  const double ratio_reduce = reduction.seconds / phat_total.seconds;
  const double ratio_end = together.seconds / cli.seconds;
  // Memory: our matrix + reduction against PHAT's in this process, and our whole path against what
  // the phat command needs above its own start-up resident set.
  const long cli_above_idle = std::max(1L, cli.peak_kib - o.phat_idle.peak_kib);
  const double ratio_memory_reduce = double(reduction.peak_kib) / double(std::max(1L, phat_total.peak_kib));
  const double ratio_memory = double(together.peak_kib) / double(cli_above_idle);
  if (o.csv) {
    std::printf("%s,%zu,%zu,%zu,%.6f,%.6f,%.6f,%.2f,%.6f,%.6f,%.6f,%.2f,%.6f,%.2f,%.2f,%.3f,%.3f,%.3f,%.3f\n",
                name.c_str(), columns, entries, ours.size(), filtration.seconds, reduction.seconds,
                together.seconds, mib(together.peak_kib), load.seconds, compute.seconds, phat_total.seconds,
                mib(phat_total.peak_kib), cli.seconds, mib(cli.peak_kib), mib(cli_above_idle), ratio_reduce,
                ratio_memory_reduce, ratio_end, ratio_memory);
    return;
  }
  std::printf("\n== %s: %zu columns, %zu entries, %zu pairs (identical: ours, PHAT in process, phat "
              "command) ==\n",
              name.c_str(), columns, entries, ours.size());
  std::printf("%-44s %10s %10s\n", "", "seconds", "peak MiB");
  std::printf("%-44s %10.3f %10.1f\n", "ours: make_filtration", filtration.seconds, mib(filtration.peak_kib));
  std::printf("%-44s %10.3f %10.1f\n", "ours: reduce (PHAT matrix from filtration)", reduction.seconds,
              mib(reduction.peak_kib));
  std::printf("%-44s %10.3f %10.1f\n", "ours: cells -> pairs", together.seconds, mib(together.peak_kib));
  std::printf("%-44s %10.3f\n", "PHAT in process: load_binary", load.seconds);
  std::printf("%-44s %10.3f\n", "PHAT in process: compute_persistence_pairs", compute.seconds);
  std::printf("%-44s %10.3f %10.1f\n", "PHAT in process: file -> pairs", phat_total.seconds,
              mib(phat_total.peak_kib));
  std::printf("%-44s %10.3f %10.1f\n", "phat command (child process, max RSS)", cli.seconds,
              mib(cli.peak_kib));
  std::printf("%-44s %10.3f %10.1f\n", "phat command on a one-column matrix", o.phat_idle.seconds,
              mib(o.phat_idle.peak_kib));
  std::printf("ratio reduce / PHAT in process (matrix + reduction): time %.2f, memory %.2f (target <= 1.1)\n",
              ratio_reduce, ratio_memory_reduce);
  std::printf("ratio cells -> pairs / phat command: time %.2f, memory %.2f (against its %.1f MiB above "
              "start-up; target <= 1.1)\n",
              ratio_end, ratio_memory, mib(cli_above_idle));
  std::fflush(stdout);
}

void usage() {
  std::fprintf(stderr, "usage: reduction_bench --store run.h5 [--store ...] [--per-type] [--repeat N] "
                       "[--phat PATH] [--tmp DIR] [--csv]\n");
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
    else if (a == "--per-type")
      o.per_type = true;
    else if (a == "--repeat")
      o.repeat = std::max(1, std::atoi(value().c_str()));
    else if (a == "--phat")
      o.phat = value();
    else if (a == "--tmp")
      o.tmp = value();
    else if (a == "--csv")
      o.csv = true;
    else
      usage();
  }
  if (o.stores.empty())
    usage();
  try {
    const std::string idle = o.tmp + "/reduction_bench." + std::to_string(getpid()) + ".idle.bin";
    {
      std::ofstream out(idle, std::ios::binary);
      const std::int64_t one_vertex[3] = {1, 0, 0}; // one column of dimension 0, empty
      out.write(reinterpret_cast<const char*>(one_vertex), sizeof one_vertex);
    }
    for (int r = 0; r < o.repeat; ++r) {
      const Measure m = run_phat(o.phat, idle, idle + ".pairs");
      o.phat_idle.seconds = std::min(o.phat_idle.seconds, m.seconds);
      o.phat_idle.peak_kib = r == 0 ? m.peak_kib : std::min(o.phat_idle.peak_kib, m.peak_kib);
    }
    std::filesystem::remove(idle);
    std::filesystem::remove(idle + ".pairs");
    print_header(o);
    for (const std::string& store : o.stores) {
      const medusa::Medusa medusa = medusa::read_store(store);
      const std::string stem = std::filesystem::path(store).stem().string();
      std::vector<int> vertex_type;
      for (const kinetic::Trajectory& t : medusa.input.cells)
        vertex_type.push_back(t.type);
      run_case(o, stem + " whole forward", medusa.cells, vertex_type, all_types);
      if (!o.per_type)
        continue;
      std::vector<int> types = vertex_type;
      std::sort(types.begin(), types.end());
      types.erase(std::unique(types.begin(), types.end()), types.end());
      for (int type : types)
        run_case(o, stem + " type " + std::to_string(type) + " forward", medusa.cells, vertex_type, type);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reduction_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
