#include "medusa/medusa/medusa.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <string>

namespace medusa {

bool Medusa::has_type(const Cell& c, int type) const {
  for (VertexId v : c.vertices)
    if (v < 0 || static_cast<std::size_t>(v) >= input.cells.size() ||
        input.cells[static_cast<std::size_t>(v)].type != type)
      return false;
  return true;
}

std::vector<CellId> Medusa::cells_of_dimension(int k) const {
  std::vector<CellId> out;
  for (const Cell& c : cells)
    if (c.dim() == k)
      out.push_back(c.id);
  return out;
}

void MedusaCollector::run(const RunInfo& info, const kinetic::Trajectories& input) {
  medusa_.run = info;
  medusa_.input = input;
}

void MedusaCollector::finish(const VirtualTime& end) {
  medusa_.end = end;
  std::sort(medusa_.cells.begin(), medusa_.cells.end(),
            [](const Cell& a, const Cell& b) { return a.id < b.id; });
  for (std::size_t i = 0; i < medusa_.cells.size(); ++i)
    if (medusa_.cells[i].id != i)
      throw InternalError("medusa collector: cell ids are not 0.." +
                          std::to_string(medusa_.cells.size() - 1));
}

} // namespace medusa
