// What a batch of simultaneous events still has to resolve (docs/MATH.md §5.2), as one part with its
// own invariants: the failed Delaunay certificates, resolved in canonical order (by facet, then id);
// the failed radius certificates and the touches, in the order found; whether a static repair is
// due; and the time each certificate of the batch fired at. Which failure is flippable, and what
// resolving one does, is the engine's; this part only keeps the work list.
//
// Invariants (first_violation): every Delaunay failure held is a live Delaunay certificate on its
// facet (retiring one withdraws it; the audit checks it as each batch resolves its failures); and
// between batches, where the audit looks, nothing is left.
#pragma once

#include "certificate_pool.h"
#include "medusa/kinetic/simplex.h"

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

class BatchAgenda {
public:
  using Entry = std::pair<int, std::uint32_t>; // a certificate id and its version when it fired

  // ---- Delaunay failures, in canonical order

  void fail_delaunay(const Simplex& facet, int id) { delaunay_.insert({facet, id}); }
  // The certificate retires (Engine::kill_cert): its failure, if held, goes with it.
  void withdraw_delaunay(const Simplex& facet, int id) { delaunay_.erase({facet, id}); }
  // Every certificate retires at once (Engine::retire_all_certs).
  void withdraw_all_delaunay() { delaunay_.clear(); }
  bool delaunay_failed(const Simplex& facet, int id) const { return delaunay_.count({facet, id}) != 0; }
  bool has_delaunay() const { return !delaunay_.empty(); }
  // The first failure in canonical order that `accept` takes, withdrawn; none when `accept` takes
  // none, or as soon as a repair is due (`accept` may find one). Entries that are not live in `pool`
  // are dropped: a defence only, since while the invariant holds every entry is live.
  template <class Accept>
  std::optional<std::pair<Simplex, int>> take_first_delaunay(const CertificatePool& pool, Accept&& accept) {
    for (auto it = delaunay_.begin(); it != delaunay_.end();) {
      const auto [facet, id] = *it;
      if (!live(pool, facet, id)) {
        it = delaunay_.erase(it);
        continue;
      }
      if (accept(facet, id)) {
        delaunay_.erase(it);
        return std::make_pair(facet, id);
      }
      if (repair_due_)
        break;
      ++it;
    }
    return std::nullopt;
  }

  // ---- radius failures and touches, in the order found

  void fail_radius(int id, std::uint32_t version) { radius_.emplace_back(id, version); }
  bool has_radius() const { return !radius_.empty(); }
  void drop_radius() { radius_.clear(); }
  // Moves the radius failures into `into` (cleared first; the two buffers swap, so neither is
  // reallocated per round), so that failures found while resolving them are held for the next round.
  void take_radius(std::vector<Entry>& into) { take(radius_, into); }

  // A radius certificate touching rho without crossing it (Engine::resolve_touches).
  void touch(int id, std::uint32_t version) { touches_.emplace_back(id, version); }
  void take_touches(std::vector<Entry>& into) { take(touches_, into); }
  // A hull orientation touching zero (Engine::resolve_hull_touches).
  void hull_touch(int id, std::uint32_t version) { hull_touches_.emplace_back(id, version); }
  void take_hull_touches(std::vector<Entry>& into) { take(hull_touches_, into); }

  // ---- static repairs

  // Requested when a hull ridge is found folded at now around a simplex that is not flat
  // (Engine::hull_ridge_folded_at_now), a hull flip would add a top simplex flat at now without
  // turning there (Engine::flippable), or a hull touch meets a hull facet whose cells are collinear
  // (Engine::resolve_hull_touches): the triangulation may not be embedded just after now, where
  // elementary flips chosen on local certificates can make it worse, so the batch repairs first.

  void request_repair() { repair_due_ = true; }
  bool repair_due() const { return repair_due_; }
  void start_repair() { repair_due_ = false; }

  // ---- the times the batch's certificates fired at

  // Each equal to now, but as the root of that certificate's own polynomial. A failure is resolved
  // with now set to it, so that the certificates built there recognise their own root
  // (Engine::sign_after_own_root) whichever of the batch's equal times was popped first: on a
  // periodic run the copies of one event are such a batch (docs/MATH.md §8.6).

  void fired(int id, const SlabTime& u) { fired_.insert_or_assign(id, u); }
  // The time certificate id fired at in this batch, or nullptr.
  const SlabTime* fired_time(int id) const {
    const auto it = fired_.find(id);
    return it == fired_.end() ? nullptr : &it->second;
  }
  void end_batch() { fired_.clear(); }

  // The first of the invariants above that fails, or an empty string; between_batches adds that
  // nothing is left.
  std::string first_violation(const CertificatePool& pool, bool between_batches) const;

private:
  // Is id a live Delaunay certificate on facet in pool.
  static bool live(const CertificatePool& pool, const Simplex& facet, int id);
  static void take(std::vector<Entry>& from, std::vector<Entry>& into) {
    into.clear();
    into.swap(from);
  }

  std::set<std::pair<Simplex, int>> delaunay_;
  std::vector<Entry> radius_, touches_, hull_touches_;
  bool repair_due_ = false;
  std::unordered_map<int, SlabTime> fired_;
};

} // namespace medusa::kinetic::detail
