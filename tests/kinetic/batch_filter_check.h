// An independent check of docs/MATH.md §6.2's filter on the event stream: inside every batch, each
// intermediate complex L_r (r = 1..m) must satisfy L_r = { s in L_r : every face of s lies in
// K(t*-) u K(t*+) u U_batch }, i.e. hold no momentary contact. U_batch is taken from the steps: (i)
// simplices with a vertex inserted or deleted in the batch, (ii) subsets of the flip groups reported
// with R_S <= rho (in_alpha; a subset of 6.2's (ii), so the check is if anything stricter), (iii)
// subsets of the degenerate groups. L_r is closed under faces, so testing each member suffices.
#pragma once

#include "medusa/kinetic/observer.h"

#include <algorithm>
#include <set>
#include <vector>

namespace medusa::kinetic::testing {

class BatchFilterCheck : public Observer {
public:
  void initial(const EventTime&, const std::vector<Simplex>& complex) override {
    k_.insert(complex.begin(), complex.end());
  }
  void batch(const EventTime&, const std::vector<Step>& steps) override {
    const std::set<Simplex> before = k_;
    std::vector<std::set<Simplex>> states;
    std::set<VertexId> moved;
    std::vector<std::vector<VertexId>> groups;
    for (const Step& s : steps) {
      for (const Simplex& x : s.left)
        k_.erase(x);
      for (const Simplex& x : s.entered)
        k_.insert(x);
      states.push_back(k_);
      if (s.kind == StepKind::insertion || s.kind == StepKind::deletion)
        moved.insert(s.vertex);
      if (s.flip && s.flip->in_alpha)
        groups.emplace_back(s.flip->vertices.begin(), s.flip->vertices.end());
      for (const DegenerateGroup& g : s.groups)
        groups.push_back(g.vertices);
    }
    auto in_u = [&](const Simplex& x) {
      for (VertexId v : x)
        if (moved.count(v))
          return true;
      for (const auto& g : groups)
        if (std::includes(g.begin(), g.end(), x.begin(), x.end()))
          return true;
      return false;
    };
    for (const std::set<Simplex>& state : states)
      for (const Simplex& x : state)
        if (!before.count(x) && !k_.count(x) && !in_u(x))
          ++momentary;
    ++batches;
    intermediate_ranks += steps.size() > 1 ? steps.size() - 1 : 0;
  }

  int momentary = 0; // simplices of some L_r that the filter of 6.2 would remove
  int batches = 0;
  std::size_t intermediate_ranks = 0;

private:
  std::set<Simplex> k_;
};

} // namespace medusa::kinetic::testing
