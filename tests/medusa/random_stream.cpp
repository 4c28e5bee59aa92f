#include "random_stream.h"

#include <algorithm>
#include <random>
#include <set>

namespace medusa::test {

namespace {

using Set = std::set<Simplex>;

struct Generator {
  std::mt19937_64 rng;
  int universe;
  std::set<VertexId> present;
  Set k;

  bool coin(double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }
  template <class C> auto pick(const C& c) {
    auto it = c.begin();
    std::advance(it, std::uniform_int_distribution<std::size_t>(0, c.size() - 1)(rng));
    return *it;
  }

  // Every simplex of dimension 1..3 on the present vertices, not containing `skip`.
  std::vector<Simplex> all_simplices(VertexId skip = -1) const {
    std::vector<VertexId> v;
    for (VertexId x : present)
      if (x != skip)
        v.push_back(x);
    std::vector<Simplex> out;
    const std::size_t n = v.size();
    for (std::uint32_t mask = 1; mask < (1u << n); ++mask) {
      const int bits = __builtin_popcount(mask);
      if (bits < 2 || bits > 4)
        continue;
      std::vector<VertexId> s;
      for (std::size_t i = 0; i < n; ++i)
        if (mask & (1u << i))
          s.push_back(v[i]);
      out.push_back(Simplex::from_range(s.begin(), s.end()));
    }
    return out;
  }

  static bool faces_in(const Simplex& s, const Set& set) {
    if (s.size() == 1)
      return true;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (!set.count(s.facet(i)))
        return false;
    return true;
  }

  static bool is_face(const Simplex& f, const Simplex& s) {
    return std::includes(s.begin(), s.end(), f.begin(), f.end());
  }

  // The star of `s` in `set` (all cofaces including s).
  static Set star(const Simplex& s, const Set& set) {
    Set out;
    for (const Simplex& t : set)
      if (is_face(s, t))
        out.insert(t);
    return out;
  }

  // Adds up to `count` random simplices whose faces are all present, avoiding `forbidden`.
  void grow(Set& set, int count, const Set& forbidden, VertexId skip = -1) {
    for (int i = 0; i < count; ++i) {
      std::vector<Simplex> candidates;
      for (const Simplex& s : all_simplices(skip))
        if (!set.count(s) && !forbidden.count(s) && faces_in(s, set))
          candidates.push_back(s);
      if (candidates.empty())
        return;
      set.insert(pick(candidates));
    }
  }

  // A random up-closed set (union of stars of random simplices of dimension >= 1).
  Set random_stars(const Set& set, int count) {
    std::vector<Simplex> edges_up;
    for (const Simplex& s : set)
      if (s.size() >= 2)
        edges_up.push_back(s);
    Set out;
    for (int i = 0; i < count && !edges_up.empty(); ++i) {
      Set st = star(pick(edges_up), set);
      out.insert(st.begin(), st.end());
    }
    return out;
  }

  static void diff(const Set& before, const Set& after, Step& step) {
    for (const Simplex& s : after)
      if (!before.count(s))
        step.entered.push_back(s);
    for (const Simplex& s : before)
      if (!after.count(s))
        step.left.push_back(s);
  }

  Step radius_step() {
    Step st;
    st.kind = kinetic::StepKind::radius;
    Set next = k;
    Set removed = random_stars(k, std::uniform_int_distribution<int>(0, 2)(rng));
    for (const Simplex& s : removed)
      next.erase(s);
    grow(next, std::uniform_int_distribution<int>(0, 3)(rng), removed);
    diff(k, next, st);
    k = next;
    return st;
  }

  bool flip_step(Step& st) {
    // abcd, abce in K; abc without other cofaces; de not in K.
    std::vector<Simplex> tets;
    for (const Simplex& s : k)
      if (s.size() == 4)
        tets.push_back(s);
    std::shuffle(tets.begin(), tets.end(), rng);
    for (const Simplex& t1 : tets)
      for (const Simplex& t2 : tets) {
        std::vector<VertexId> common;
        std::set_intersection(t1.begin(), t1.end(), t2.begin(), t2.end(), std::back_inserter(common));
        if (common.size() != 3)
          continue;
        const Simplex abc = Simplex::from_range(common.begin(), common.end());
        if (star(abc, k).size() != 3)
          continue;
        VertexId d = -1, e = -1;
        for (VertexId x : t1)
          if (!abc.contains(x))
            d = x;
        for (VertexId x : t2)
          if (!abc.contains(x))
            e = x;
        if (k.count(Simplex{d, e}))
          continue;
        st.kind = coin(0.5) ? kinetic::StepKind::flip23 : kinetic::StepKind::flip32;
        Set next = k;
        next.erase(abc);
        next.erase(t1);
        next.erase(t2);
        const VertexId a = abc[0], b = abc[1], c = abc[2];
        for (const Simplex& s : {Simplex{d, e}, Simplex{d, e, a}, Simplex{d, e, b}, Simplex{d, e, c},
                                 Simplex{d, e, a, b}, Simplex{d, e, b, c}, Simplex{d, e, c, a}})
          next.insert(s);
        diff(k, next, st);
        st.flip = kinetic::FlipGroup{{a, b, c, d, e}, coin(0.8)};
        st.delaunay_removed = {t1, t2};
        k = next;
        return true;
      }
    return false;
  }

  bool insertion_step(Step& st) {
    std::vector<VertexId> absent;
    for (VertexId v = 0; v < universe; ++v)
      if (!present.count(v))
        absent.push_back(v);
    if (absent.empty())
      return false;
    const VertexId p = pick(absent);
    st.kind = kinetic::StepKind::insertion;
    st.vertex = p;
    const Set removed = random_stars(k, std::uniform_int_distribution<int>(0, 2)(rng));
    Set rest;
    for (const Simplex& s : k)
      if (!removed.count(s))
        rest.insert(s);
    // The cone over C must contain tau + p for every facet tau (not removed) of a removed simplex, so
    // that the joins have their facets (docs/MATH.md §6.3).
    std::vector<Simplex> base;
    for (const Simplex& s : removed)
      for (std::size_t i = 0; i < s.size(); ++i)
        if (!removed.count(s.facet(i)))
          base.push_back(s.facet(i));
    for (const Simplex& s : rest)
      if (s.size() <= 3 && coin(0.15))
        base.push_back(s);
    Set next = rest;
    next.insert(Simplex{p});
    for (const Simplex& s : closure(base)) {
      std::vector<VertexId> v(s.begin(), s.end());
      v.push_back(p);
      next.insert(Simplex::from_range(v.begin(), v.end()));
    }
    present.insert(p);
    diff(k, next, st);
    k = next;
    return true;
  }

  bool deletion_step(Step& st) {
    if (present.size() <= 2)
      return false;
    const VertexId p = pick(present);
    st.kind = kinetic::StepKind::deletion;
    st.vertex = p;
    Set next;
    for (const Simplex& s : k)
      if (!s.contains(p))
        next.insert(s);
    // Entering simplices sigma need, for each facet tau, tau entering too or tau + p in K before.
    Set added;
    for (int round = 0; round < 3; ++round) {
      for (const Simplex& s : all_simplices(p)) {
        if (next.count(s) || k.count(s) || !faces_in(s, next))
          continue;
        bool ok = true;
        for (std::size_t i = 0; i < s.size() && ok; ++i) {
          const Simplex tau = s.facet(i);
          std::vector<VertexId> v(tau.begin(), tau.end());
          v.push_back(p);
          ok = added.count(s.facet(i)) || (v.size() <= 4 && k.count(Simplex::from_range(v.begin(), v.end())));
        }
        if (ok && coin(0.5)) {
          next.insert(s);
          added.insert(s);
        }
      }
    }
    present.erase(p);
    diff(k, next, st);
    k = next;
    return true;
  }

  Step repair_step() {
    Step st = radius_step();
    st.kind = kinetic::StepKind::repair;
    std::vector<VertexId> v(present.begin(), present.end());
    std::shuffle(v.begin(), v.end(), rng);
    v.resize(std::min<std::size_t>(v.size(), std::uniform_int_distribution<std::size_t>(4, 6)(rng)));
    std::sort(v.begin(), v.end());
    st.groups.push_back(kinetic::DegenerateGroup{v});
    return st;
  }

  Step random_step() {
    const int what = std::uniform_int_distribution<int>(0, 9)(rng);
    Step st;
    if (what <= 1 && flip_step(st))
      return st;
    if (what == 2 && insertion_step(st))
      return st;
    if (what == 3 && deletion_step(st))
      return st;
    if (what == 4)
      return repair_step();
    return radius_step();
  }
};

} // namespace

Stream random_stream(std::uint64_t seed, const RandomStreamOptions& options) {
  Generator g{std::mt19937_64(seed), options.vertices, {}, {}};
  for (VertexId v = 0; v < options.initial_present; ++v)
    g.present.insert(v);
  for (VertexId v : g.present)
    g.k.insert(Simplex{v});
  g.grow(g.k, 25, {});

  Stream s;
  s.t0 = event_time(0, 0.0, 0, 0.0, true);
  s.initial.assign(g.k.begin(), g.k.end());
  s.frames_after_initial = {0};
  std::size_t batch = 1;
  for (std::size_t slab = 0; slab + 1 < options.frames; ++slab) {
    if (slab > 0) {
      // A frame batch at t_slab: insertions and deletions happen here (docs/MATH.md §5.6).
      RecordedBatch b;
      b.time = event_time(batch++, 10.0 * static_cast<double>(slab), slab, 0.0, true);
      const int steps = std::uniform_int_distribution<int>(1, 3)(g.rng);
      for (int i = 0; i < steps; ++i) {
        Step st;
        if (!(g.coin(0.5) ? g.insertion_step(st) : g.deletion_step(st)))
          st = g.radius_step();
        st.rank = static_cast<std::size_t>(i) + 1;
        b.steps.push_back(std::move(st));
      }
      b.frames_after = {slab};
      s.batches.push_back(std::move(b));
    }
    for (int i = 0; i < options.batches_per_slab; ++i) {
      RecordedBatch b;
      const double u = (i + 1.0) / (options.batches_per_slab + 1.0);
      b.time = event_time(batch++, 10.0 * (static_cast<double>(slab) + u), slab, u, false);
      const int steps = std::uniform_int_distribution<int>(1, 3)(g.rng);
      for (int r = 0; r < steps; ++r) {
        Step st = g.random_step();
        st.rank = static_cast<std::size_t>(r) + 1;
        b.steps.push_back(std::move(st));
      }
      s.batches.push_back(std::move(b));
    }
  }
  s.t_end = event_time(batch, 10.0 * static_cast<double>(options.frames - 1), options.frames - 1, 0.0, true);
  return s;
}

} // namespace medusa::test
