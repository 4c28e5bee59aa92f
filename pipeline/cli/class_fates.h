// What became of the clusters, loops and cavities of one cell type over a run, for the summary of
// `medusa run`: counts of the time slices K_t at the first and last frame (docs/MATH.md §6.6) and of
// the forward and reverse diagrams of the type's sub-medusa (docs/MATH.md §7.2-§7.6).
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/diagram.h"

#include <array>
#include <cstddef>

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
  // Clusters of the end that touched another one earlier and separated again: b0 of K(t_end-) minus
  // the rank of H0(K(t_end-)) -> H0(M) (reverse essential H0 classes born at t_end).
  std::size_t separated_again = 0;
};

// Loops (k = 1) or cavities (k = 2): the positive-length classes of the forward diagram, by whether
// they were present at the first frame (born at or before its batch: the initial layout's) or formed
// later, and by fate. A class that dies was filled; one that never dies is a class of the whole
// medusa, and it is still open at the end when the end complex carries it (the essential classes of
// the reverse diagram born at t_end span the image of H_k(K(t_end-)) in H_k(M)), otherwise it broke
// open without being filled.
struct HoleFates {
  std::size_t initial = 0, formed = 0;               // present at the first frame / formed during the run
  std::size_t filled_initial = 0, filled_formed = 0; // finite pairs
  std::size_t never_filled_initial = 0, never_filled_formed = 0; // essential classes
  std::size_t still_open = 0;  // never filled and carried by the end complex (rank of the image)
  std::size_t broken_open = 0; // never filled - still_open
  std::size_t open_at_end = 0; // b_k of K(t_end-) (>= still_open: an end loop can bound the past)
};

struct ClassFates {
  ClusterFates clusters;
  std::array<HoleFates, 3> holes; // index 1 loops, 2 cavities (0 unused)
  // Cells present at the first frame only: they leave the complex at that instant (docs/MATH.md §2.4),
  // so the first frame's complex (the state just after it, §0) no longer has them.
  std::size_t cells_leaving_at_first = 0;
};

// `medusa` must hold its batches (read_store with events). `forward` and `reverse` are the diagrams
// of the same sub-medusa (cell_type all_types for the whole medusa), zero-length pairs dropped or not.
ClassFates class_fates(const medusa::Medusa& medusa, const persistence::Diagram& forward,
                       const persistence::Diagram& reverse);

} // namespace medusa::cli
