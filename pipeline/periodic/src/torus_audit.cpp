#include "medusa/periodic/torus_audit.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>

namespace medusa::periodic {

namespace {

// Event times reach the observer as doubles; an audit time at least this far (in u) from both ends of
// its interval lies strictly between the exact events.
constexpr double min_gap = 1e-9;

} // namespace

std::vector<std::size_t> betti_numbers_z2(const std::vector<kinetic::Simplex>& complex) {
  int top = 0;
  for (const kinetic::Simplex& s : complex)
    top = std::max(top, s.dim());
  std::vector<std::map<kinetic::Simplex, std::size_t>> index(static_cast<std::size_t>(top) + 1);
  for (const kinetic::Simplex& s : complex)
    index[static_cast<std::size_t>(s.dim())].emplace(s, 0);
  for (auto& level : index) {
    std::size_t i = 0;
    for (auto& kv : level)
      kv.second = i++;
  }
  // rank of the boundary map from degree d to d-1, by column reduction over Z/2.
  std::vector<std::size_t> rank(static_cast<std::size_t>(top) + 2, 0);
  for (std::size_t d = 1; d <= static_cast<std::size_t>(top); ++d) {
    std::unordered_map<std::size_t, std::vector<std::size_t>> by_low;
    for (const auto& kv : index[d]) {
      std::vector<std::size_t> column;
      for (std::size_t i = 0; i < kv.first.size(); ++i)
        column.push_back(index[d - 1].at(kv.first.facet(i)));
      std::sort(column.begin(), column.end());
      while (!column.empty()) {
        auto it = by_low.find(column.back());
        if (it == by_low.end())
          break;
        std::vector<std::size_t> sum;
        std::set_symmetric_difference(column.begin(), column.end(), it->second.begin(), it->second.end(),
                                      std::back_inserter(sum));
        column.swap(sum);
      }
      if (!column.empty()) {
        ++rank[d];
        by_low.emplace(column.back(), std::move(column));
      }
    }
  }
  std::vector<std::size_t> betti;
  for (std::size_t d = 0; d <= static_cast<std::size_t>(top); ++d)
    betti.push_back(index[d].size() - rank[d] - rank[d + 1]);
  return betti;
}

std::string describe(const TorusAuditStatistics& s) {
  std::ostringstream os;
  os << "audit on the torus: " << s.checks << " check" << (s.checks == 1 ? "" : "s") << " passed ("
     << s.periodic_triangulation << " against CGAL's periodic Delaunay triangulation, " << s.tiled_copies
     << " against the Delaunay triangulation of the tiled copies; " << s.compared
     << " equal simplex for simplex, " << s.betti_only
     << " with equal Betti numbers where cospherical cells are triangulated differently), " << s.skipped
     << " skipped (no room between events, or cells in fewer dimensions)";
  return os.str();
}

void TorusAudit::initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) {
  complex_.insert(complex.begin(), complex.end());
  slab_ = t0.slab;
  u_ = t0.u;
  due_ = true;
  next_.initial(t0, complex);
}

void TorusAudit::batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) {
  audit_until(time.slab, time.u);
  for (const kinetic::Step& st : steps) {
    for (const kinetic::Simplex& s : st.left)
      complex_.erase(s);
    complex_.insert(st.entered.begin(), st.entered.end());
  }
  slab_ = time.slab;
  u_ = time.u;
  due_ = ++batches_ % stride_ == 0;
  next_.batch(time, steps);
}

void TorusAudit::frame(std::size_t k, const kinetic::EventTime& time) {
  // Unless a batch at the frame has just audited it, the complex held since the last batch is
  // audited up to the frame.
  if (slab_ < k) {
    audit_until(k, 0.0);
    slab_ = k;
    u_ = 0.0;
  }
  due_ = true;
  next_.frame(k, time);
}

void TorusAudit::finish(const kinetic::EventTime& t_end) {
  audit_until(t_end.slab + 1, 0.0);
  next_.finish(t_end);
}

void TorusAudit::audit_until(std::size_t slab, double u) {
  if (!due_)
    return;
  due_ = false;
  const double hi = slab == slab_ ? u : 1.0;
  if (slab_ + 1 >= cover_.trajectories.frames() || !(hi - u_ > 8 * min_gap)) {
    ++stats_.skipped;
    return;
  }
  // Dyadic times (the static constructions are then fast and exact, torus_alpha_complex.cpp) near
  // the middle and the first third; the second where the first meets an isolated touch of a
  // certificate (a radius reaching rho without crossing it, docs/MATH.md §3.9).
  int bits = 1;
  while (std::ldexp(1.0, -bits) > (hi - u_) / 8)
    ++bits;
  const auto dyadic = [&](double x) {
    return mpq_class(mpz_class(std::floor(std::ldexp(x, bits))), mpz_class(1) << bits);
  };
  if (!audit_at(dyadic(u_ + (hi - u_) / 2), false))
    audit_at(dyadic(u_ + (hi - u_) / 3), true);
}

bool TorusAudit::audit_at(const mpq_class& q, bool last_try) {
  std::vector<TorusPoint> points;
  for (std::size_t i = 0; i < cover_.originals; ++i) {
    const kinetic::Trajectory& c = cover_.trajectories.cells[i];
    if (!(c.first_frame <= slab_ && slab_ < c.last_frame()))
      continue;
    TorusPoint p;
    p.id = static_cast<kinetic::VertexId>(i);
    for (std::size_t a = 0; a < 3; ++a)
      p.position[a] = mpq_class(c.at(slab_)[a]) + q * mpq_class(c.at(slab_ + 1)[a] - c.at(slab_)[a]);
    points.push_back(p);
  }
  if (points.empty()) {
    ++stats_.skipped;
    return true;
  }
  const TorusAlphaComplex expected = torus_alpha_complex(dim_, domain_, points, rho2_);
  if (!expected.full_dimensional) {
    ++stats_.skipped;
    return true;
  }
  const std::vector<kinetic::Simplex> ours(complex_.begin(), complex_.end());
  if (ours == expected.complex) {
    ++stats_.checks;
    ++stats_.compared;
    ++(expected.oracle == TorusOracle::periodic_triangulation ? stats_.periodic_triangulation
                                                              : stats_.tiled_copies);
    return true;
  }
  if (!last_try)
    return false;
  ++stats_.checks;
  ++(expected.oracle == TorusOracle::periodic_triangulation ? stats_.periodic_triangulation
                                                            : stats_.tiled_copies);
  // Cospherical cells (identically so over the slab) may be triangulated differently by CGAL and by
  // the engine (docs/MATH.md §5.3); both complexes then have the homotopy type of the union of balls.
  if (betti_numbers_z2(ours) == betti_numbers_z2(expected.complex)) {
    ++stats_.betti_only;
    return true;
  }
  std::vector<kinetic::Simplex> extra, missing;
  std::set_difference(ours.begin(), ours.end(), expected.complex.begin(), expected.complex.end(),
                      std::back_inserter(extra));
  std::set_difference(expected.complex.begin(), expected.complex.end(), ours.begin(), ours.end(),
                      std::back_inserter(missing));
  const auto cells = [&](const kinetic::Simplex& s) {
    std::string out;
    for (kinetic::VertexId v : s)
      out += (out.empty() ? "" : " ") +
             std::to_string(cover_.trajectories.cells[static_cast<std::size_t>(v)].cell_id);
    return "{" + out + "}";
  };
  std::ostringstream os;
  os << "audit failed on the torus in slab " << slab_ << " at u ~ " << q.get_d()
     << ": the complex differs from "
     << (expected.oracle == TorusOracle::periodic_triangulation
             ? "CGAL's periodic Delaunay triangulation's"
             : "that of CGAL's Delaunay triangulation of the tiled copies")
     << " alpha complex: " << extra.size() << " extra";
  if (!extra.empty())
    os << " (e.g. cells " << cells(extra.front()) << ")";
  os << ", " << missing.size() << " missing";
  if (!missing.empty())
    os << " (e.g. cells " << cells(missing.front()) << ")";
  throw InternalError(os.str());
}

} // namespace medusa::periodic
