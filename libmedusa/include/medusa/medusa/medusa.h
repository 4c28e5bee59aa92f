// A whole medusa in memory: what a store holds (docs/FORMAT.md), or what a MedusaCollector gathered
// from the builder.
#pragma once

#include "medusa/kinetic/trajectories.h"
#include "medusa/medusa/cell.h"
#include "medusa/medusa/cell_sink.h"
#include "medusa/medusa/run_info.h"
#include "medusa/medusa/timeline.h"

#include <vector>

namespace medusa {

struct Medusa {
  RunInfo run;
  kinetic::Trajectories input;      // empty (no cells, no frames) when the run was not given
  std::vector<BatchRecord> batches; // increasing batch index
  std::vector<FrameRecord> frames;  // in the order reported
  VirtualTime end;                  // the final virtual time (death of the cells alive at t_end)
  std::vector<Cell> cells;          // cells[i].id == i

  const Cell& cell(CellId id) const { return cells.at(static_cast<std::size_t>(id)); }
  // The boundary of a cell over Z/2: its facet cells, whose lifetimes contain its own (docs/MATH.md §6.4).
  const CellFacets& boundary(CellId id) const { return cell(id).facets; }
  // The ids of the cells of dimension k, increasing.
  std::vector<CellId> cells_of_dimension(int k) const;
  // The type of every vertex of `c` is `type` (docs/MATH.md §7.4); needs the input.
  bool has_type(const Cell& c, int type) const;
};

// Collects the builder's output into a Medusa (cells re-ordered by id at finish).
class MedusaCollector : public CellSink {
public:
  void run(const RunInfo& info, const kinetic::Trajectories& input) override;
  void batch(const BatchRecord& b) override { medusa_.batches.push_back(b); }
  void frame(const FrameRecord& f) override { medusa_.frames.push_back(f); }
  void cell(const Cell& c) override { medusa_.cells.push_back(c); }
  void finish(const VirtualTime& end) override;

  const Medusa& medusa() const { return medusa_; }
  Medusa take() { return std::move(medusa_); }

private:
  Medusa medusa_;
};

} // namespace medusa
