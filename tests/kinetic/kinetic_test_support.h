// Helpers for the kinetic engine tests: trajectories by hand and at random, and an observer that
// replays the event stream and checks it against the engine's own complex after every batch.
#pragma once

#include "medusa/kinetic/kinetic_alpha_complex.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace medusa::kinetic::testing {

// How far a reported event time may be from the exact one: half a step of the 2^-32 MCS grid
// (docs/MATH.md §3.12).
constexpr double reported_time_error = 0x1p-33;

// Replays the stream: K(t0+) then entered/left of every step. After each batch the replayed complex
// must equal the engine's (the stream is complete: libmedusa is built on it).
class ReplayObserver : public Observer {
public:
  explicit ReplayObserver(const KineticAlphaComplex& engine) : engine_(engine) {}

  void initial(const EventTime&, const std::vector<Simplex>& complex) override {
    k_.insert(complex.begin(), complex.end());
  }
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    times.push_back(time.time);
    for (const Step& s : steps) {
      ++step_counts[static_cast<int>(s.kind)];
      if (s.flip && s.flip->in_alpha)
        ++flips_in_alpha;
      for (const Simplex& x : s.left)
        if (k_.erase(x) != 1)
          ++inconsistencies; // left but was not in K
      for (const Simplex& x : s.entered)
        if (!k_.insert(x).second)
          ++inconsistencies; // entered but was in K already
    }
    std::vector<Simplex> engine = engine_.current_complex();
    if (std::vector<Simplex>(k_.begin(), k_.end()) != engine)
      ++mismatches;
    for (const Simplex& x : k_)
      if (x.size() > 1)
        for (std::size_t i = 0; i < x.size(); ++i)
          if (!k_.count(x.facet(i)))
            ++not_closed;
  }

  std::vector<double> times;
  int step_counts[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  int flips_in_alpha = 0, inconsistencies = 0, mismatches = 0, not_closed = 0;
  const std::set<Simplex>& complex() const { return k_; }

private:
  const KineticAlphaComplex& engine_;
  std::set<Simplex> k_;
};

// The replay check, keeping the insertion and deletion steps (their Delaunay changes) in order.
class ArrivalsObserver : public ReplayObserver {
public:
  using ReplayObserver::ReplayObserver;
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    for (const Step& s : steps)
      if (s.kind == StepKind::insertion || s.kind == StepKind::deletion)
        arrivals.push_back(s);
    ReplayObserver::batch(time, steps);
  }
  std::vector<Step> arrivals;
};

// Records the stream as text, one line per batch (slab, frame flag, and every step with its ranks,
// simplices, flip and degenerate groups), with each batch's u apart: two runs that must make the same
// decisions give equal lines, and u equal up to the width of their isolating intervals.
class StreamRecorder : public Observer {
public:
  void initial(const EventTime&, const std::vector<Simplex>& complex) override {
    std::ostringstream os;
    os << "initial";
    put(os, complex);
    lines.push_back(os.str());
    us.push_back(0.0);
  }
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    std::ostringstream os;
    os << "batch " << time.batch << " slab " << time.slab << (time.at_frame ? " frame" : "");
    for (const Step& s : steps) {
      os << " | " << s.rank << ' ' << to_string(s.kind) << " v" << s.vertex << " +";
      put(os, s.entered);
      os << " -";
      put(os, s.left);
      if (s.flip) {
        os << " flip" << (s.flip->in_alpha ? "*" : "");
        for (VertexId v : s.flip->vertices)
          os << ' ' << v;
      }
      for (const DegenerateGroup& g : s.groups) {
        os << " group";
        for (VertexId v : g.vertices)
          os << ' ' << v;
      }
      os << " del-";
      put(os, s.delaunay_removed);
      os << " del+";
      put(os, s.delaunay_created);
    }
    lines.push_back(os.str());
    us.push_back(time.u);
  }
  void frame(std::size_t k, const EventTime& time) override {
    lines.push_back("frame " + std::to_string(k) + " batch " + std::to_string(time.batch));
    us.push_back(time.u);
  }
  void finish(const EventTime& time) override {
    lines.push_back("finish batch " + std::to_string(time.batch));
    us.push_back(time.u);
  }

  std::vector<std::string> lines;
  std::vector<double> us;

private:
  static void put(std::ostream& os, const std::vector<Simplex>& simplices) {
    for (const Simplex& x : simplices)
      os << x;
  }
};

// Keeps every batch of the stream whole, with its time.
class BatchRecorder : public Observer {
public:
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    batches.emplace_back(time, steps);
  }
  std::vector<std::pair<EventTime, std::vector<Step>>> batches;
};

// Feeds two observers the same stream.
class TeeObserver : public Observer {
public:
  TeeObserver(Observer& a, Observer& b) : a_(a), b_(b) {}
  void initial(const EventTime& t0, const std::vector<Simplex>& k) override {
    a_.initial(t0, k);
    b_.initial(t0, k);
  }
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    a_.batch(time, steps);
    b_.batch(time, steps);
  }
  void frame(std::size_t k, const EventTime& time) override {
    a_.frame(k, time);
    b_.frame(k, time);
  }
  void finish(const EventTime& time) override {
    a_.finish(time);
    b_.finish(time);
  }

private:
  Observer &a_, &b_;
};

// One run of the engine with its stream replayed (ReplayObserver), logged by batch (Log: each test
// file's own summary of a batch) and recorded step by step (BatchRecorder).
template <class Log> struct RecordedRun {
  KineticAlphaComplex engine;
  ReplayObserver replay;
  Log log;
  BatchRecorder steps;
  RecordedRun(const Trajectories& t, const KineticOptions& options) : engine(t, options), replay(engine) {
    TeeObserver both(log, steps);
    TeeObserver all(replay, both);
    engine.run(all);
  }
};

// The image of a run under x -> k x + offset (k > 0), with rho^2 scaled by k^2: a similarity, so the
// Delaunay triangulation, the alpha complex and every event's slab parameter u* are the same
// (docs/MATH.md §1: the certificates are homogeneous in the coordinate differences).
inline void apply_similarity(Trajectories& t, KineticOptions& options, std::int64_t k,
                             const GridPoint& offset) {
  for (Trajectory& c : t.cells)
    for (GridPoint& p : c.positions)
      for (int a = 0; a < 3; ++a)
        p[a] = k * p[a] + offset[a];
  options.rho2.num *= mpz_class(k) * k;
}

// n cells doing independent random walks on the integer grid, over `frames` frames.
inline Trajectories random_walk(std::uint64_t seed, int n, int frames, int box, int step) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> start(0, box), d(-step, step);
  Trajectories t;
  t.scale = 1;
  for (int k = 0; k < frames; ++k)
    t.frame_times.push_back(100 * k);
  std::set<GridPoint> used;
  for (int i = 0; i < n; ++i) {
    Trajectory c;
    c.cell_id = i + 1;
    c.type = 1 + i % 2;
    GridPoint p;
    do
      p = {start(rng), start(rng), start(rng)};
    while (!used.insert(p).second);
    for (int k = 0; k < frames; ++k) {
      c.positions.push_back(p);
      for (auto& x : p)
        x += d(rng);
    }
    t.cells.push_back(c);
  }
  return t;
}

// Whether two cells moving linearly from a0 to a1 and from b0 to b1 meet at some u in (0, 1].
inline bool meet(const GridPoint& a0, const GridPoint& a1, const GridPoint& b0, const GridPoint& b1) {
  // a0 + u (a1 - a0) = b0 + u (b1 - b0) in every coordinate: u d = -e with d, e per coordinate.
  long num = 0, den = 0; // the common u = num / den once fixed
  for (int i = 0; i < 3; ++i) {
    long e = a0[i] - b0[i], d = (a1[i] - a0[i]) - (b1[i] - b0[i]);
    if (d == 0) {
      if (e != 0)
        return false;
      continue;
    }
    if (den == 0) {
      num = -e;
      den = d;
    } else if (num * d != -e * den) {
      return false;
    }
  }
  if (den == 0)
    return true; // identical motion from the same start
  if (den < 0) {
    num = -num;
    den = -den;
  }
  return num > 0 && num <= den;
}

// The planar analogue: n cells walking in the plane z = 0, a run of dimension 2. Steps that would
// make two cells meet (at a frame or inside a slab) are drawn again, so dense walks on a coarse grid
// stay collision-free (docs/MATH.md §2.5).
inline Trajectories random_walk_2d(std::uint64_t seed, int n, int frames, int box, int step) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> start(0, box), d(-step, step);
  Trajectories t;
  t.dimension = 2;
  t.scale = 1;
  for (int k = 0; k < frames; ++k)
    t.frame_times.push_back(100 * k);
  std::set<GridPoint> used;
  for (int i = 0; i < n; ++i) {
    Trajectory c;
    c.cell_id = i + 1;
    c.type = 1 + i % 2;
    GridPoint p;
    do
      p = {start(rng), start(rng), 0};
    while (!used.insert(p).second);
    c.positions.push_back(p);
    t.cells.push_back(c);
  }
  for (int k = 1; k < frames; ++k)
    for (int i = 0; i < n; ++i) {
      const GridPoint from = t.cells[i].positions.back();
      for (;;) {
        GridPoint to{from[0] + d(rng), from[1] + d(rng), 0};
        bool clash = false;
        for (int j = 0; j < n && !clash; ++j) {
          if (j == i)
            continue;
          const auto& q = t.cells[j].positions;
          const GridPoint& q0 = q[k - 1];
          const GridPoint& q1 = j < i ? q[k] : q[k - 1]; // cells not yet moved: assume they stay
          clash = meet(from, to, q0, q1);
        }
        if (!clash) {
          t.cells[i].positions.push_back(to);
          break;
        }
      }
    }
  return t;
}

// Twelve cells on rays through the integer points of the circle of radius 5, moving radially at
// different speeds (p_i(u) = c_i (10 + (u - 1/2) k_i), k_i even): all twelve are cocircular (radius
// 50) exactly at u = 1/2 and at no other time, a massively degenerate planar batch.
inline Trajectories cocircular_burst() {
  const std::int64_t c[12][2] = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                                 {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  const std::int64_t k[6] = {2, -4, 6, -2, 4, -6};
  Trajectories t;
  t.dimension = 2;
  t.scale = 1;
  t.frame_times = {0, 100};
  for (int i = 0; i < 12; ++i) {
    const std::int64_t s0 = 10 - k[i % 6] / 2, s1 = 10 + k[i % 6] / 2;
    t.cells.push_back(
        {i + 1, 1 + i % 2, 0, {{c[i][0] * s0, c[i][1] * s0, 0}, {c[i][0] * s1, c[i][1] * s1, 0}}});
  }
  return t;
}

// Certificates built by formula: in-sphere (in-circle), hull orientation, edge, triangle and
// tetrahedron radius (KineticStatistics::built_*).
using FormulaCounts = std::array<std::size_t, 5>;

// Runs the engine on t with rho^2 = rho2 and the audit on, replaying its stream, and returns the
// certificates it built by formula; they must add up to certificates_built.
inline FormulaCounts built_by_formula(const Trajectories& t, long rho2) {
  KineticOptions options;
  options.rho2.num = rho2;
  options.audit = true;
  KineticAlphaComplex engine(t, options);
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(obs.mismatches == 0);
  const KineticStatistics& s = engine.statistics();
  const FormulaCounts counts{s.built_in_sphere, s.built_hull, s.built_radius[0], s.built_radius[1],
                             s.built_radius[2]};
  REQUIRE(counts[0] + counts[1] + counts[2] + counts[3] + counts[4] == s.certificates_built);
  return counts;
}

// Makes about a tenth of the cells start late (a birth: an insertion at a frame) and another tenth
// end early (a death: a deletion at a frame), from rng alone.
inline void add_births_and_deaths(Trajectories& t, std::mt19937_64& rng) {
  for (Trajectory& c : t.cells) {
    const unsigned r = unsigned(rng() % 10);
    if (r == 0 && c.positions.size() > 2) {
      c.first_frame = 1 + rng() % (c.positions.size() - 1);
      c.positions.erase(c.positions.begin(), c.positions.begin() + long(c.first_frame));
    } else if (r == 1 && c.positions.size() > 2) {
      c.positions.resize(1 + rng() % (c.positions.size() - 1));
    }
  }
}

// Cuts about half of the slabs at their middle with a new frame, the motion unchanged: coordinates
// and rho^2 are scaled by 2 and 4 so that the middles are grid points. Degenerate instants at u = 1/2
// of a slab (cells meeting a line or a hull face there) then fall on a frame, where the engine
// rebuilds every certificate (docs/MATH.md §2.3) and resolves them as a frame batch. From rng alone.
inline void add_midpoint_frames(Trajectories& t, KineticOptions& options, std::mt19937_64& rng) {
  std::vector<bool> cut(t.frame_times.size() - 1);
  std::vector<std::int64_t> times;
  std::vector<std::size_t> new_index;
  for (std::size_t k = 0; k < t.frame_times.size(); ++k) {
    new_index.push_back(times.size());
    times.push_back(2 * t.frame_times[k]);
    if (k + 1 < t.frame_times.size() && (cut[k] = rng() % 2 == 0))
      times.push_back(t.frame_times[k] + t.frame_times[k + 1]);
  }
  for (Trajectory& c : t.cells) {
    std::vector<GridPoint> p;
    for (std::size_t f = 0; f < c.positions.size(); ++f) {
      const GridPoint& x = c.positions[f];
      p.push_back({2 * x[0], 2 * x[1], 2 * x[2]});
      if (f + 1 < c.positions.size() && cut[c.first_frame + f]) {
        const GridPoint& y = c.positions[f + 1];
        p.push_back({x[0] + y[0], x[1] + y[1], x[2] + y[2]});
      }
    }
    c.positions = std::move(p);
    c.first_frame = new_index[c.first_frame];
  }
  t.frame_times = std::move(times);
  options.rho2.num *= 4;
}

// A dense walk on a coarse integer lattice, with births and deaths: the stress input behind the
// "dense lattice" regression tests. From the seed alone: 3D (two seeds in three) or planar, up to
// 42 cells (3D) or 67 (2D) in a box a few lattice steps wide (at most a third of its sites taken),
// steps of 0-2, about a tenth of the cells born at a later frame and a tenth dying early, rho between
// 0.5 and 4.4 and an audit stride of 1-6. Many cells are cospherical, coplanar or at exactly rho at
// once, and events coincide with frames. Returns false for a seed whose box is too small for its
// cells (nothing generated).
struct DenseLatticeRun {
  bool two_d = false;
  int n = 0, frames = 0, box = 0, step = 0;
  Trajectories trajectories;
  KineticOptions options;
};
inline bool dense_lattice_run(std::uint64_t seed, DenseLatticeRun& run) {
  std::mt19937_64 rng(seed * 7919);
  run.two_d = rng() % 3 == 0;
  run.n = 8 + int(rng() % (run.two_d ? 60 : 35));
  run.frames = 3 + int(rng() % 6);
  run.box = 3 + int(rng() % 12);
  run.step = int(rng() % 3);
  if (run.two_d && run.n > (2 * run.box + 1) * (2 * run.box + 1) / 3)
    return false;
  if (!run.two_d && run.n > (run.box + 1) * (run.box + 1) * (run.box + 1) / 3)
    return false;
  run.trajectories = run.two_d ? random_walk_2d(seed, run.n, run.frames, run.box * 2, std::max(run.step, 1))
                               : random_walk(seed, run.n, run.frames, run.box, run.step);
  add_births_and_deaths(run.trajectories, rng);
  const int rho_tenths = 5 + int(rng() % 40);
  run.options.rho2.num = rho_tenths * rho_tenths;
  run.options.rho2.den = 100;
  run.options.audit = true;
  run.options.audit_stride = 1 + rng() % 6;
  return true;
}

// Walks clamped to a small lattice box, with about half the cells starting on its faces: the stress
// input for the hull's degeneracies (coplanar and collinear hull cells, cells moving onto and off a
// face, hull facets degenerating inside a slab). From the seed alone, in dimension dim: box side 2-5,
// up to 35 cells (25 in 2D; at most half the sites), 3-6 frames, steps of -1, 0 or 1 per coordinate
// (a quarter of the steps stay), rho between 0.5 and 3.4, the audit after every batch. Returns false
// when the seed gives too few cells or a cell finds no step free of collisions. With births_and_deaths,
// some cells then start late or end early (add_births_and_deaths): insertions and deletions on and
// next to the degenerate hull. With midpoint_frames, about half of the slabs are cut at their middle
// by a frame (add_midpoint_frames).
inline bool hull_box_run(std::uint64_t seed, int dim, DenseLatticeRun& run, bool births_and_deaths = false,
                         bool midpoint_frames = false) {
  std::mt19937_64 rng(seed * 104729 + 7);
  run.two_d = dim == 2;
  run.box = 2 + int(rng() % 4);
  run.n = 6 + int(rng() % (dim == 3 ? 30 : 20));
  run.frames = 3 + int(rng() % 4);
  run.step = 1;
  const int sites = dim == 3 ? (run.box + 1) * (run.box + 1) * (run.box + 1) : (run.box + 1) * (run.box + 1);
  run.n = std::min(run.n, sites / 2);
  if (run.n < dim + 2)
    return false;
  Trajectories& t = run.trajectories;
  t = Trajectories();
  t.dimension = dim;
  t.scale = 1;
  for (int k = 0; k < run.frames; ++k)
    t.frame_times.push_back(100 * k);
  const std::int64_t box = run.box;
  const auto clamp = [&](std::int64_t x) { return std::max<std::int64_t>(0, std::min(box, x)); };
  std::set<GridPoint> used;
  for (int i = 0; i < run.n; ++i) {
    Trajectory c;
    c.cell_id = i + 1;
    c.type = 1 + i % 2;
    GridPoint p;
    do {
      p = {std::int64_t(rng() % (box + 1)), std::int64_t(rng() % (box + 1)),
           dim == 3 ? std::int64_t(rng() % (box + 1)) : 0};
      if (rng() % 2)
        p[rng() % unsigned(dim)] = rng() % 2 ? box : 0; // on a face
    } while (!used.insert(p).second);
    c.positions.push_back(p);
    t.cells.push_back(c);
  }
  for (int k = 1; k < run.frames; ++k)
    for (int i = 0; i < run.n; ++i) {
      const GridPoint from = t.cells[i].positions.back();
      for (int tries = 0;; ++tries) {
        if (tries > 200)
          return false;
        GridPoint to = from;
        for (int d = 0; d < dim; ++d)
          to[d] = clamp(from[d] + int(rng() % 3) - 1);
        if (rng() % 4 == 0)
          to = from;
        bool clash = false;
        for (int j = 0; j < run.n && !clash; ++j) {
          if (j == i)
            continue;
          const auto& q = t.cells[j].positions;
          clash = meet(from, to, q[k - 1], j < i ? q[k] : q[k - 1]);
        }
        if (!clash) {
          t.cells[i].positions.push_back(to);
          break;
        }
      }
    }
  const int rho_tenths = 5 + int(rng() % 30);
  run.options = KineticOptions();
  run.options.rho2.num = rho_tenths * rho_tenths;
  run.options.rho2.den = 100;
  run.options.audit = true;
  run.options.audit_stride = 1;
  if (births_and_deaths) {
    std::mt19937_64 life(seed * 15485863 + 11);
    add_births_and_deaths(t, life);
  }
  if (midpoint_frames) {
    std::mt19937_64 cuts(seed * 32452843 + 5);
    add_midpoint_frames(t, run.options, cuts);
    run.frames = static_cast<int>(t.frame_times.size());
  }
  return true;
}

} // namespace medusa::kinetic::testing
