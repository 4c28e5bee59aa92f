// Builds the alpha medusa from the kinetic event stream (docs/MATH.md §6.2-§6.5).
#pragma once

#include "medusa/kinetic/flat_simplex_map.h"
#include "medusa/kinetic/observer.h"
#include "medusa/medusa/cell.h"
#include "medusa/medusa/cell_sink.h"

#include <cstdint>
#include <map>
#include <vector>

namespace medusa {

// Turns the event stream into medusa cells and sends each cell to the sink as soon as it finishes.
// Memory holds only the active complex (one entry per simplex of the current K) and the instant
// cells of the current step (docs/MATH.md §6.5). An inconsistent stream (a facet that is not present, a
// simplex entering twice, a face leaving before its coface) throws InternalError: the stream comes
// from libkinetic, so this is a bug there.
class MedusaBuilder : public kinetic::Observer {
public:
  explicit MedusaBuilder(CellSink& sink) : sink_(sink) {}

  // Passes the run metadata and the input trajectories on to the sink (the store records them).
  void set_run(const RunInfo& info, const kinetic::Trajectories& input);

  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override;
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override;
  void frame(std::size_t k, const kinetic::EventTime& time) override;
  void finish(const kinetic::EventTime& t_end) override;

  std::size_t active_cells() const { return active_.size(); }
  std::uint64_t cells_created() const { return next_id_; }

private:
  // A simplex of K: its cell's id (below max_cell_count, so 32 bits), its birth and its count of
  // active cofaces. Its facet ids are not kept: a simplex leaves K only after its cofaces, so at its
  // death its facets are still active and their ids are read from their own records.
  struct Active {
    std::uint32_t id = 0;
    std::uint32_t cofaces = 0; // active cofaces: a simplex cannot leave while one remains
    VirtualTime birth;
  };
  using InstantMap = std::map<std::vector<VertexId>, CellId>;

  void check_order(const kinetic::EventTime& time, const char* what);
  void birth(const kinetic::Simplex& s, const VirtualTime& when);
  void death(const kinetic::Simplex& s, const VirtualTime& when);
  void step(const kinetic::Step& step, const VirtualTime& when);
  CellFacets facets_of(const std::vector<VertexId>& vertices, const InstantMap& instant,
                       const VirtualTime& when) const;

  CellSink& sink_;
  // Open addressing (flat_simplex_map.h): every birth and death looks up the simplex and its facets,
  // one cache miss each, where a node-based map costs two and an allocation per simplex.
  kinetic::FlatSimplexMap<Active> active_;
  CellId next_id_ = 0;
  bool started_ = false;
  bool finished_ = false;
  std::uint64_t last_batch_ = 0;
};

} // namespace medusa
