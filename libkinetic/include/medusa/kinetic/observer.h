// The event stream of the kinetic alpha complex (docs/MATH.md §5.2, §5.6, §6.2).
//
// libmedusa is built on this stream alone, so it is complete: starting from the initial complex and
// applying, batch by batch and rank by rank, `entered` and `left` of every step reproduces the alpha
// complex K at every moment. Inside a batch (all events at one exact time t*) the steps are the ranks
// r = 1..m+1 of docs/MATH.md §6.2; after step r the complex is L_r, and after the last step it is K(t*+).
#pragma once

#include "medusa/kinetic/simplex.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace medusa::kinetic {

// The exact position of a batch in the event order. Batches are numbered 0, 1, 2, ... in strictly
// increasing exact time; batch 0 is t_0. Equal exact times are one batch, so (batch, rank) orders
// events without comparing doubles.
struct EventTime {
  std::size_t batch = 0;
  std::size_t slab = 0;  // slab k: t in [t_k, t_{k+1}]
  double u = 0.0;        // double approximation of the slab parameter u* in [0, 1]
  double time = 0.0;     // double approximation of t* = t_k + u* (t_{k+1} - t_k)
  bool at_frame = false; // u* = 0 exactly: a frame batch (docs/MATH.md §5.6), or the final time
};

enum class StepKind {
  radius,    // radius events: frontier simplices changing shortness
  flip23,    // finite 2-3 flip
  flip32,    // finite 3-2 flip
  hull_flip, // flip through the infinite vertex (never changes K in the generic case)
  insertion, // a cell appears at a frame (mitosis)
  deletion,  // a cell disappears at a frame (death)
  repair,    // static repair of a degenerate configuration (docs/MATH.md §5.4)
  settle,    // the final re-evaluation of a batch (rank m+1, docs/MATH.md §5.2 step 4)
  flip22     // finite 2-2 flip of a planar run (the 2D analogue of flip23 / flip32)
};

const char* to_string(StepKind kind);

// The points of a finite flip: five for a 2-3 / 3-2 flip, four for a planar 2-2 flip. `in_alpha` is
// the rule of docs/MATH.md §6.3: R_S <= rho (the circumsphere, or circumcircle, of the group) and the old
// top simplices are in L_{r-1}; then the simplex of the group (a 4-simplex, or a 3-simplex in 2D) is
// an instant medusa cell.
struct FlipGroup {
  std::vector<VertexId> vertices; // sorted
  bool in_alpha = false;
};

// A non-simplicial Delaunay face found by a static repair (>= 5 cospherical or >= 4 concyclic
// coplanar points) with g(P) <= rho^2: every subset of its vertices in neither L_{r-1} nor L_r is an
// instant medusa cell at this rank (docs/MATH.md §6.3).
struct DegenerateGroup {
  std::vector<VertexId> vertices; // sorted
};

// One elementary step of a batch.
struct Step {
  std::size_t rank = 0;
  StepKind kind = StepKind::settle;
  std::vector<Simplex> entered;          // L_r \ L_{r-1}, in increasing dimension
  std::vector<Simplex> left;             // L_{r-1} \ L_r, in increasing dimension
  std::optional<FlipGroup> flip;         // for flip23 / flip32 / flip22
  std::vector<DegenerateGroup> groups;   // for repair
  VertexId vertex = -1;                  // the inserted or deleted vertex
  std::vector<Simplex> delaunay_removed; // finite top simplices (tetrahedra, triangles in 2D) removed
  std::vector<Simplex> delaunay_created; // finite top simplices created by the step
};

// Receives the stream. All callbacks have empty defaults, so an observer overrides what it needs.
class Observer {
public:
  virtual ~Observer() = default;
  // K(t_0+), in increasing dimension; batch 0.
  virtual void initial(const EventTime& /*t0*/, const std::vector<Simplex>& /*complex*/) {}
  // One batch (never empty) with its steps in rank order.
  virtual void batch(const EventTime& /*time*/, const std::vector<Step>& /*steps*/) {}
  // Inner frame k (0 < k < last) reached, after its frame batch if any. Frame 0 is reported by
  // initial() (and a deletion batch at t_0 for cells present at t_0 only), the last by finish().
  virtual void frame(std::size_t /*k*/, const EventTime& /*time*/) {}
  // The run ended at t_end; the complex is K(t_end-).
  virtual void finish(const EventTime& /*t_end*/) {}
};

} // namespace medusa::kinetic
