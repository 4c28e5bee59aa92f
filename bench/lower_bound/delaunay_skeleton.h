// A lower bound for kinetic_bench: the leanest kinetic Delaunay triangulation we know how to write on
// the same certificate arithmetic as libkinetic, timed on the same frames.
//
// What it keeps of the engine's work (docs/MATH.md §2.3, §3): every facet's in-sphere certificate enclosed
// from doubles, at every frame for every facet and after every flip for the new ones, and either
// proven to keep its sign over the rest of the slab or its first failure isolated (one
// Bernstein-Descartes search, root_isolation.h) and narrowed to 2^-24 as the engine narrows it; a
// binary heap of failure times; flips on CGAL's triangulation data structure (flip_flippable), the
// flip's kind decided by orientations at the event. Certificates live in the cells: a queue entry
// names a cell, a facet and the stamps of the two cells, and a flip restamps the cells it rewrites,
// so no table is ever looked up.
//
// In the plane, given the radius, it maintains the fixed-radius alpha complex too (docs/MATH.md §4): each
// frontier simplex's radius certificate (4.4) in the faces, rebuilt at every frame and settled or
// queued as the in-circle ones; shortness and membership through 2-2 flips (Proposition 4.5: the
// new simplices are in K iff the new triangles are short) and radius events (Lemma 4.1, Gabriel
// status tested at the event: 4.2); its final alpha complex must equal CGAL's exact Alpha_shape_2.
// A radius certificate found already failed when it is created (a crossing inside the isolating
// interval of the event that created it) is taken at once, as the engine takes one. It also does two
// more parts of the engine's job there: the collision test of docs/MATH.md §2.5 on every edge at a frame and
// every edge a flip creates, and the output stream (a record per flip and per simplex entering or
// leaving K, kept for the slab).
//
// What it leaves out, so that its time is a lower bound for any engine doing the engine's job with
// this arithmetic: in 3D, the alpha complex (no radius certificates, no membership); degeneracies (it stops
// at the first certificate doubles cannot settle or the first failure that is not a plain flip, so a
// CC3D run's lattice start stops it at once); exact event order (failure times are ordered on the
// left ends of their enclosures, narrowed to 2^-24, and a flip and its new certificates are
// evaluated at the right end: the engine's tightening of each event time to the last bit is left
// out too, and two failures closer than 2^-24 may be taken in the wrong order, which can also stop
// it); the hull (four far static points enclose the cells, so the hull never changes); insertions and
// deletions; in 3D, collisions and the output stream. It runs in 3D
// (2-3 and 3-2 flips on Triangulation_data_structure_3) and in the plane (2-2 flips on
// Triangulation_data_structure_2, the in-circle certificate), on runs whose cells are present at every frame,
// and checks at the end (with SkeletonOptions::check_frames, at every frame, untimed) that its triangulation
// equals CGAL's static one: only a run that ends equal counts.
#pragma once

#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/kinetic/trajectories.h"

#include <cstddef>
#include <string>
#include <vector>

namespace medusa::bench {

struct SkeletonRun {
  std::vector<double> slab_seconds;     // per slab: its frame's certificate rebuild and its events
  double rebuild_seconds = 0.0;         // the certificate rebuilds at frames alone, summed
  std::size_t flips23 = 0, flips32 = 0; // in the plane: flips23 counts the 2-2 flips
  std::size_t stale = 0;                // queue entries of certificates a flip had retired
  std::size_t certificates = 0;         // in-sphere (in-circle) certificates built
  std::size_t isolated = 0;             // of them, with a failure time isolated in the slab
  std::size_t tight = 0;  // recomputed in interval arithmetic where the doubles left a sign open
  bool completed = false; // false: stopped at a degenerate configuration (verdict says which)
  bool verified = false;  // at the last frame: the triangulation equals CGAL's static one (and the
                          // alpha layer's state passes the same checks as check_frames's)
  std::string verdict;    // why not, when not
  // The planar alpha layer (run with a radius in 2D): the fixed-radius alpha complex on top.
  bool alpha = false;
  std::size_t radius_certificates = 0; // built, at frames and after events
  std::size_t radius_isolated = 0;     // of them, with a failure time isolated in the slab
  std::size_t radius_events = 0;       // frontier simplices turning short or long
  std::size_t alpha_changes = 0;       // simplices entering or leaving the alpha complex
  bool alpha_verified = false;         // verified, with the alpha layer (CGAL's exact Alpha_shape_2)
};

// False (and `why`) when the run is not one the skeleton handles: every cell at every frame.
bool skeleton_applies(const kinetic::Trajectories& t, std::string& why);

struct SkeletonOptions {
  const kinetic::SquaredRadius* rho2 = nullptr; // in the plane: maintain the fixed-radius alpha complex too
  bool check_frames = false; // compare with CGAL at every frame (untimed), not only at the end
};

SkeletonRun run_delaunay_skeleton(const kinetic::Trajectories& t, const SkeletonOptions& options = {});

} // namespace medusa::bench
