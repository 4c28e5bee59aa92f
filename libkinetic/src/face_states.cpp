#include "face_states.h"

#include <sstream>
#include <unordered_set>

namespace medusa::kinetic::detail {

namespace {

std::string named(const char* what, const Simplex& s) {
  std::ostringstream os;
  os << "simplex " << s << ' ' << what;
  return os.str();
}

} // namespace

template <int D>
std::string FaceStates::first_violation(const CellTriangulation<D>& cells,
                                        const std::vector<char>& alive) const {
  const auto short_facet = [&](const Simplex& x) { return is_short(x); };
  std::unordered_set<Simplex, SimplexHash> del_faces;
  std::string violation;
  std::vector<Simplex> tops;
  cells.for_each_cell([&](CellIndex c) { tops.push_back(cells.top(c)); });
  for (const Simplex& t : tops)
    for_each_face(t, [&](const Simplex& s) {
      if (!violation.empty() || s.size() == 1 || !del_faces.insert(s).second)
        return;
      const Face* f = find(s);
      if (f == nullptr) {
        violation = named("of Del is not recorded", s);
        return;
      }
      const CellIndex start = cells.cell_containing(s);
      int containing = 0;
      std::vector<Simplex> cofaces;
      if (start != no_cell) {
        cells.for_each_cell_containing_from(start, s, [&](CellIndex) { ++containing; });
        cells.finite_cofaces_from(start, s, cofaces);
      }
      if (f->tops != containing) {
        violation = named("of Del has a wrong count of top simplices", s);
        return;
      }
      int short_cofaces = 0, k_cofaces = 0;
      for (const Simplex& c : cofaces) {
        short_cofaces += is_short(c);
        k_cofaces += in_k(c, alive);
      }
      if (f->short_cofaces != short_cofaces || f->k_cofaces != k_cofaces) {
        violation = named("has wrong counts of short cofaces or cofaces in K", s);
        return;
      }
      if (f->in_k && !f->is_short) {
        violation = named("is in K but long", s);
        return;
      }
      for (std::size_t i = 0; f->in_k && i < s.size(); ++i)
        if (!in_k(s.facet(i), alive)) {
          violation = named("is in K without its facets (K is not a complex)", s);
          return;
        }
      if ((f->cert >= 0) != in_frontier(s, *f, short_facet))
        violation = named(f->cert >= 0 ? "has a radius certificate outside the frontier"
                                       : "is on the frontier without a radius certificate",
                          s);
    });
  if (violation.empty() && del_faces.size() != size())
    violation = "a simplex not in Del is still recorded";
  return violation;
}

template std::string FaceStates::first_violation(const CellTriangulation<2>&, const std::vector<char>&) const;
template std::string FaceStates::first_violation(const CellTriangulation<3>&, const std::vector<char>&) const;

} // namespace medusa::kinetic::detail
