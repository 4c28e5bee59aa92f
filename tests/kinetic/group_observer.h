// An observer for the degenerate-group tests (docs/MATH.md §5.4, §6.3), 3D and planar: besides the replay
// checks of ReplayObserver, records the repair steps (when, and the top simplices they remove and
// create), their degenerate groups and every simplex that enters or leaves K in a step.
#pragma once

#include "kinetic_test_support.h"

#include <algorithm>
#include <set>
#include <vector>

namespace medusa::kinetic::testing {

class GroupObserver : public ReplayObserver {
public:
  using ReplayObserver::ReplayObserver;
  void batch(const EventTime& time, const std::vector<Step>& steps) override {
    ReplayObserver::batch(time, steps);
    for (const Step& s : steps) {
      if (s.kind == StepKind::repair) {
        ++repairs;
        repair_at_frame = time.at_frame;
        repair_u = time.u;
        repair_time = time.time;
        created.insert(s.delaunay_created.begin(), s.delaunay_created.end());
        removed.insert(s.delaunay_removed.begin(), s.delaunay_removed.end());
      }
      for (const DegenerateGroup& g : s.groups) {
        groups.insert(g.vertices);
        sorted = sorted && std::is_sorted(g.vertices.begin(), g.vertices.end());
        only_in_repairs = only_in_repairs && s.kind == StepKind::repair;
      }
      for (const auto* list : {&s.entered, &s.left})
        for (const Simplex& x : *list)
          touched.insert(x);
    }
    batch_times.push_back(time.time);
  }
  int repairs = 0;
  bool repair_at_frame = false, sorted = true, only_in_repairs = true;
  double repair_u = -1, repair_time = -1;
  std::set<std::vector<VertexId>> groups;
  std::set<Simplex> created, removed, touched;
  std::vector<double> batch_times;
};

// Options with rho^2 = rho2 (grid units) and the audit on.
inline KineticOptions with_radius(long rho2) {
  KineticOptions o;
  o.rho2.num = rho2;
  o.audit = true;
  return o;
}

} // namespace medusa::kinetic::testing
