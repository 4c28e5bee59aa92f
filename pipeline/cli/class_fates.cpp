#include "class_fates.h"

#include "diagram_selection.h"
#include "interrupt.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/signatures.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace medusa::cli {
namespace {

void check_frames(const medusa::Medusa& medusa) {
  if (medusa.input.frames() == 0 || medusa.batches.empty())
    throw InternalError("class_fates: the medusa has no frames or no batch records");
}

std::optional<int> type_of(int cell_type) {
  return cell_type == persistence::all_types ? std::nullopt : std::optional<int>(cell_type);
}

} // namespace

FatesFromCells fates_from_cells(const medusa::Medusa& medusa, int cell_type) {
  check_frames(medusa);
  const std::optional<int> type = type_of(cell_type);
  const std::size_t last = medusa.input.frames() - 1;
  // The first frame's batch: the initial complex, and at t_0 itself the removal of cells present at
  // that frame only (docs/MATH.md §2.4, §6.2), whose batch has the same time t_0.
  const std::uint64_t first_batch = medusa::frame_batch(medusa, 0);
  FatesFromCells result;
  result.cell_type = cell_type;
  result.betti_first =
      medusa::signature_of(medusa, medusa::cells_at_frame(medusa, 0, type), check_interrupted).betti;
  result.betti_end =
      medusa::signature_of(medusa, medusa::cells_at_frame(medusa, last, type), check_interrupted).betti;
  const std::vector<int> vertex_type = vertex_types(medusa);
  for (const medusa::Cell& c : medusa.cells)
    if (c.dim() == 0 && c.death.batch <= first_batch &&
        (!type || vertex_type.at(static_cast<std::size_t>(c.vertices.front())) == *type))
      ++result.cells_leaving_at_first;
  std::vector<char> member;
  if (type) {
    member.resize(medusa.cells.size());
    for (std::size_t i = 0; i < medusa.cells.size(); ++i)
      member[i] = medusa.has_type(medusa.cells[i], *type) ? 1 : 0;
  }
  result.end_beyond_first = persistence::end_classes_beyond_first(medusa.cells, member, first_batch,
                                                                  medusa.end.batch, check_interrupted);
  return result;
}

std::size_t clusters_joined_at_first(const persistence::Diagram& forward, std::uint64_t first_batch,
                                     std::size_t at_first) {
  std::size_t alive = 0;
  for (const persistence::PersistencePair& p : forward.pairs)
    if (!p.zero_length && p.dim == 0 && p.birth_time.batch <= first_batch &&
        (p.essential || p.death_time.batch > first_batch))
      ++alive;
  if (alive > at_first)
    throw InternalError("class_fates: more H0 classes than clusters just after the first frame");
  return at_first - alive;
}

ClassFates class_fates(const medusa::Medusa& medusa, const FatesFromCells& cells,
                       const persistence::Diagram& forward, const persistence::Diagram& reverse) {
  if (forward.direction != persistence::Direction::forward ||
      reverse.direction != persistence::Direction::reverse || forward.cell_type != reverse.cell_type ||
      forward.cell_type != cells.cell_type)
    throw InternalError("class_fates: needs the forward and reverse diagrams of one sub-medusa");
  check_frames(medusa);
  const std::uint64_t first_batch = medusa::frame_batch(medusa, 0);

  ClassFates fates;
  fates.clusters.at_first = cells.betti_first[0];
  fates.clusters.at_end = cells.betti_end[0];
  fates.cells_leaving_at_first = cells.cells_leaving_at_first;

  std::vector<double> joins;
  for (const persistence::PersistencePair& p : forward.pairs)
    if (!p.zero_length && p.dim == 0 && !p.essential)
      joins.push_back(p.death);
  std::sort(joins.begin(), joins.end());
  fates.clusters.joins = joins.size();
  if (!joins.empty()) {
    fates.clusters.half_joined = joins[(joins.size() + 1) / 2 - 1];
    fates.clusters.all_joined = joins.back();
  }
  // The reverse filtration starts with K(t_end-), the cells that die at the final virtual time
  // (docs/MATH.md §6.2, §7.3): its essential H0 classes born there span the image of H_0(K(t_end-)).
  std::size_t carried = 0;
  for (const persistence::PersistencePair& p : reverse.pairs)
    if (p.essential && p.dim == 0 && p.birth_time.batch == medusa.end.batch)
      ++carried;
  if (carried > fates.clusters.at_end)
    throw InternalError("class_fates: more H0 classes than clusters at the last frame");
  fates.clusters.joined_at_first = clusters_joined_at_first(forward, first_batch, fates.clusters.at_first);
  fates.clusters.separated_again = fates.clusters.at_end - carried;
  fates.holes =
      persistence::hole_fates(forward, reverse, first_batch, medusa.end.batch, cells.end_beyond_first);
  for (std::size_t k = 1; k <= 2; ++k) {
    fates.open_at_end[k] = cells.betti_end[k];
    fates.open_at_first[k] = cells.betti_first[k];
  }
  return fates;
}

ClassFates class_fates(const medusa::Medusa& medusa, const persistence::Diagram& forward,
                       const persistence::Diagram& reverse) {
  if (forward.cell_type != reverse.cell_type)
    throw InternalError("class_fates: needs the forward and reverse diagrams of one sub-medusa");
  return class_fates(medusa, fates_from_cells(medusa, forward.cell_type), forward, reverse);
}

} // namespace medusa::cli
