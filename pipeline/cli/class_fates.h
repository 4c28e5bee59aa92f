// What became of the clusters, loops and cavities of one cell type over a run, for the summary of
// `medusa run`: counts of the time slices K_t at the first and last frame (docs/MATH.md §6.6) and of
// the forward and reverse diagrams of the type's sub-medusa (docs/MATH.md §7.2-§7.6, §7.12).
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/open_classes.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace medusa::cli {

struct ClusterFates {
  std::size_t at_first = 0; // b0 of K at the first frame (what `medusa curves` reports there)
  std::size_t at_end = 0;   // b0 of K(t_end-)
  std::size_t joins = 0;  // finite positive-length H0 pairs of the forward diagram: clusters joining another
  double half_joined = 0; // the time by which half of the joins happened (the ceil(n/2)-th death)
  double all_joined = 0;  // the last join
  // Clusters of the first frame already joined in M_{<= t_0} (through cells that left at t_0): at_first
  // minus the forward H0 classes alive after the first frame's batch.
  std::size_t joined_at_first = 0;
  // Clusters of the end that were one cluster with another earlier (they joined, or were one from the
  // start) and split off: b0 of K(t_end-) minus
  // the rank of H0(K(t_end-)) -> H0(M) (reverse essential H0 classes born at t_end).
  std::size_t separated_again = 0;
};

struct ClassFates {
  ClusterFates clusters;
  // Loops (index 1) and cavities (2), each fate split by present at the first frame or formed later
  // (docs/MATH.md §7.12); index 0 unused.
  std::array<persistence::HoleFates, 3> holes;
  // b_k of K(t_end-) (>= still open: an end loop can bound in space-time).
  std::array<std::size_t, 3> open_at_end{};
  // b_k of K at the first frame, just after it: it differs from the classes present at the first frame
  // when cells present at that frame only leave then.
  std::array<std::size_t, 3> open_at_first{};
  // Cells present at the first frame only: they leave the complex at that instant (docs/MATH.md §2.4),
  // so the first frame's complex (the state just after it, §0) no longer has them.
  std::size_t cells_leaving_at_first = 0;
};

// What ClassFates takes from the cells of one sub-medusa alone, without its diagrams: the Betti numbers
// of K at the first and last frames, and the ranks of end_classes_beyond_first (one PHAT reduction of
// the coned sub-medusa, docs/MATH.md §7.12). `medusa run` computes them before its diagrams, so that this
// reduction does not run while the diagrams' pairs are held.
struct FatesFromCells {
  int cell_type = persistence::all_types;
  std::array<std::size_t, 4> betti_first{}, betti_end{}; // b0..b3 of K at the first and last frames
  std::size_t cells_leaving_at_first = 0;
  std::array<std::size_t, 3> end_beyond_first{};
};

// `medusa` must hold its batches (read_store with events); `cell_type` is a type or all_types.
FatesFromCells fates_from_cells(const medusa::Medusa& medusa, int cell_type);

// `forward` and `reverse` are the diagrams of the sub-medusa of `cells` (cell_type all_types for the
// whole medusa), zero-length pairs dropped or not; InternalError if their types differ from it.
ClassFates class_fates(const medusa::Medusa& medusa, const FatesFromCells& cells,
                       const persistence::Diagram& forward, const persistence::Diagram& reverse);

// The clusters of the first frame (`at_first` of them) already joined in M_{<= t_0} to another, through
// cells that left at t_0: at_first minus the forward H0 classes alive after the first frame's batch
// `first_batch` (medusa::frame_batch). InternalError if more classes than clusters are alive.
std::size_t clusters_joined_at_first(const persistence::Diagram& forward, std::uint64_t first_batch,
                                     std::size_t at_first);

// Both steps at once.
ClassFates class_fates(const medusa::Medusa& medusa, const persistence::Diagram& forward,
                       const persistence::Diagram& reverse);

} // namespace medusa::cli
