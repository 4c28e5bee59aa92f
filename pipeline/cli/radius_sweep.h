// The kinetic stage and the medusa at each of several radii, in parallel, and the Betti numbers of K_t
// at the frames for each (CROCKER data, docs/MATH.md §6.6): what `medusa sweep` computes from a CC3D
// run and `medusa report` from the trajectories kept in a store. Radii are decimal text, stepped in
// exact decimals.
#pragma once

#include "betti_frames.h"
#include "crocker.h"
#include "forward_counts.h"

#include "medusa/io/periodic_domain.h"
#include "medusa/kinetic/trajectories.h"
#include "medusa/medusa/run_info.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace medusa::cli {

constexpr std::size_t max_sweep_radii = 200;

// A positive decimal as an integer count of 10^-decimals.
struct Decimal {
  std::int64_t units = 0;
  int decimals = 0;
};

bool parse_decimal(const std::string& text, Decimal& d);
// units * 10^-decimals as the shortest decimal text ("2.5", "3").
std::string decimal_text(std::int64_t units, int decimals);
// Appends the radii of A:B:STEP (A, B, STEP positive decimals, A <= B) in exact decimal steps to
// `radii` (when not null); returns the reason the range is not valid, or "".
std::string expand_range(const std::string& spec, std::vector<std::string>* radii);
// Why `text` is not a positive decimal radius, or "".
std::string radius_error(const std::string& text);
// The radii in increasing order, each once (compared by exact decimal value); InputError past
// max_sweep_radii.
std::vector<std::string> sorted_radii(const std::vector<std::string>& texts);

struct RadiusResult {
  std::string radius;
  std::vector<TypeSlices> slices;                            // whole complex first, then the types
  std::vector<std::pair<std::string, ForwardCounts>> counts; // per type label, whole complex first
  bool edges = false;
};

// Every radius on a pool of `workers` threads, each with the Betti numbers of K_t at the frames and,
// with `diagrams`, the forward diagrams' counts. `done(radius, finished, total)` is called (under a
// lock) after each radius. The first error (an interrupt first) is rethrown once all have stopped;
// polls for interrupts. With periodic axes in `domain`, on the torus (docs/MATH.md §8; every radius
// must pass periodic::check_periodic_radius).
std::vector<RadiusResult>
sweep_radii(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info,
            const io::PeriodicDomain& domain, const std::vector<std::string>& radii, unsigned workers,
            bool diagrams, const std::function<void(const std::string&, std::size_t, std::size_t)>& done);

// One CROCKER row per radius, frame and type (as `medusa sweep` writes them).
std::vector<CrockerRow> crocker_rows(const std::vector<RadiusResult>& results,
                                     const std::vector<std::int64_t>& frame_times);

} // namespace medusa::cli
