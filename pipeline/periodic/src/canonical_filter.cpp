#include "medusa/periodic/canonical_filter.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>

namespace medusa::periodic {

namespace {

using kinetic::Simplex;
using kinetic::Step;
using kinetic::StepKind;
using kinetic::VertexId;

// Which merged step a covering step belongs to (docs/MATH.md §8.5): the copies of one flip share the
// flip group's image on the torus (original ids with offsets relative to the smallest one), the
// copies of one insertion or deletion share the original, and the batch's repairs and its final
// re-evaluation are one step each (the engine makes them one step for the whole covering space).
using StepKey = std::vector<std::int64_t>;

StepKey torus_key(const PeriodicCover& cover, std::int64_t tag, const std::vector<VertexId>& vertices) {
  std::vector<std::array<std::int64_t, 4>> image;
  VertexId smallest = -1;
  std::array<std::int64_t, 3> base{};
  for (VertexId v : vertices) {
    const CoverVertex& c = cover.vertices[static_cast<std::size_t>(v)];
    if (smallest < 0 || c.original < smallest) {
      smallest = c.original;
      base = c.offset;
    }
  }
  for (VertexId v : vertices) {
    const CoverVertex& c = cover.vertices[static_cast<std::size_t>(v)];
    image.push_back({c.original, c.offset[0] - base[0], c.offset[1] - base[1], c.offset[2] - base[2]});
  }
  std::sort(image.begin(), image.end());
  StepKey key{tag};
  for (const auto& e : image)
    key.insert(key.end(), e.begin(), e.end());
  return key;
}

std::string vertex_list(const std::vector<VertexId>& v) {
  std::string s;
  for (VertexId x : v)
    s += (s.empty() ? "" : " ") + std::to_string(x);
  return "[" + s + "]";
}

struct Merged {
  Step step;
  std::set<Simplex> entered, left;
  bool original_vertex = false; // insertion/deletion: the original itself is among the copies
};

} // namespace

std::optional<std::vector<VertexId>> canonical_image(const PeriodicCover& cover,
                                                     const std::vector<VertexId>& vertices) {
  const CoverVertex* smallest = nullptr;
  std::vector<VertexId> image;
  image.reserve(vertices.size());
  for (VertexId v : vertices) {
    const CoverVertex& c = cover.vertices[static_cast<std::size_t>(v)];
    if (c.is_sentinel())
      return std::nullopt;
    if (smallest == nullptr || c.original < smallest->original)
      smallest = &c;
    image.push_back(c.original);
  }
  if (smallest == nullptr || !smallest->is_original())
    return std::nullopt;
  std::sort(image.begin(), image.end());
  if (std::adjacent_find(image.begin(), image.end()) != image.end())
    throw InternalError("periodic cover: simplex " + vertex_list(vertices) +
                        " holds two copies of one cell (docs/MATH.md §8.3)");
  return image;
}

std::optional<Simplex> CanonicalFilter::canonical(const Simplex& s) const {
  const auto image = canonical_image(cover_, std::vector<VertexId>(s.begin(), s.end()));
  if (!image)
    return std::nullopt;
  return Simplex::from_range(image->begin(), image->end());
}

void CanonicalFilter::initial(const kinetic::EventTime& t0, const std::vector<Simplex>& complex) {
  std::vector<Simplex> out;
  for (const Simplex& s : complex)
    if (auto c = canonical(s))
      out.push_back(*c);
  std::sort(out.begin(), out.end());
  batch_ = t0.batch;
  next_.initial(t0, out);
}

void CanonicalFilter::batch(const kinetic::EventTime& time, const std::vector<Step>& steps) {
  std::map<StepKey, std::size_t> index;
  std::vector<Merged> merged;
  for (const Step& st : steps) {
    StepKey key;
    switch (st.kind) {
    case StepKind::flip23:
    case StepKind::flip32:
    case StepKind::flip22:
      if (st.flip && std::none_of(st.flip->vertices.begin(), st.flip->vertices.end(), [&](VertexId v) {
            return cover_.vertices[static_cast<std::size_t>(v)].is_sentinel();
          })) {
        key = torus_key(cover_, 0, st.flip->vertices);
        break;
      }
      [[fallthrough]];
    case StepKind::hull_flip:
    case StepKind::radius:
      key = {1, static_cast<std::int64_t>(st.rank)}; // never merged
      break;
    case StepKind::insertion:
    case StepKind::deletion:
      key = {st.kind == StepKind::insertion ? 2 : 3,
             cover_.vertices[static_cast<std::size_t>(st.vertex)].original};
      break;
    case StepKind::repair: key = {4}; break;
    case StepKind::settle: key = {5}; break;
    }
    auto [it, fresh] = index.try_emplace(key, merged.size());
    if (fresh) {
      merged.emplace_back();
      merged.back().step.kind = st.kind;
      if (st.vertex >= 0)
        merged.back().step.vertex = cover_.vertices[static_cast<std::size_t>(st.vertex)].original;
    }
    Merged& m = merged[it->second];
    if (st.vertex >= 0 && static_cast<std::size_t>(st.vertex) < cover_.originals)
      m.original_vertex = true;
    for (const Simplex& s : st.entered)
      if (auto c = canonical(s))
        m.entered.insert(*c);
    for (const Simplex& s : st.left)
      if (auto c = canonical(s))
        m.left.insert(*c);
    if (st.flip && st.flip->in_alpha)
      if (auto image = canonical_image(cover_, st.flip->vertices)) {
        if (m.step.flip && m.step.flip->vertices != *image)
          throw InternalError("periodic cover: two canonical flip groups " +
                              vertex_list(m.step.flip->vertices) + " and " + vertex_list(*image) +
                              " in one merged step");
        m.step.flip = kinetic::FlipGroup{*image, true};
      }
    for (const kinetic::DegenerateGroup& g : st.groups)
      if (auto image = canonical_image(cover_, g.vertices))
        m.step.groups.push_back(kinetic::DegenerateGroup{*image});
  }

  std::vector<Step> out;
  for (Merged& m : merged) {
    if (m.entered.empty() && m.left.empty() && !m.step.flip && m.step.groups.empty())
      continue;
    const bool moves_a_cell = m.step.kind == StepKind::insertion || m.step.kind == StepKind::deletion;
    // A copy entering or leaving the cover at a frame while its original stays is far from every
    // original (docs/MATH.md §8.4): it cannot change a canonical simplex.
    if (moves_a_cell && !m.original_vertex)
      throw InternalError("periodic cover: a copy of cell vertex " + std::to_string(m.step.vertex) +
                          " entering or leaving at batch " + std::to_string(time.batch) +
                          " changes the complex on the torus (docs/MATH.md §8.4)");
    // A simplex both entering and leaving in one merged step entered and left at different ranks of
    // the covering batch; the merged step keeps the net change only when that is consistent.
    for (const Simplex& s : m.entered)
      if (m.left.count(s))
        throw InternalError("periodic cover: simplex enters and leaves within one merged step at batch " +
                            std::to_string(time.batch) + " (docs/MATH.md §8.5)");
    m.step.entered.assign(m.entered.begin(), m.entered.end());
    m.step.left.assign(m.left.begin(), m.left.end());
    std::sort(m.step.groups.begin(), m.step.groups.end(),
              [](const kinetic::DegenerateGroup& a, const kinetic::DegenerateGroup& b) {
                return a.vertices < b.vertices;
              });
    m.step.groups.erase(std::unique(m.step.groups.begin(), m.step.groups.end(),
                                    [](const kinetic::DegenerateGroup& a, const kinetic::DegenerateGroup& b) {
                                      return a.vertices == b.vertices;
                                    }),
                        m.step.groups.end());
    m.step.rank = out.size() + 1;
    out.push_back(std::move(m.step));
  }
  if (out.empty()) {
    ++dropped_;
    return;
  }
  ++passed_;
  kinetic::EventTime t = time;
  t.batch = ++batch_;
  next_.batch(t, out);
}

void CanonicalFilter::frame(std::size_t k, const kinetic::EventTime& time) {
  kinetic::EventTime t = time;
  t.batch = batch_;
  next_.frame(k, t);
}

void CanonicalFilter::finish(const kinetic::EventTime& t_end) {
  kinetic::EventTime t = t_end;
  t.batch = batch_ + 1;
  next_.finish(t);
}

} // namespace medusa::periodic
