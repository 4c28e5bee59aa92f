#include "medusa/persistence/medusa_diagrams.h"

#include "medusa/persistence/degree_check.h"
#include "medusa/persistence/euler.h"

namespace medusa::persistence {

std::vector<Diagram> compute_medusa_diagrams(const std::vector<complex::Cell>& cells,
                                             const std::vector<int>& vertex_type,
                                             const std::vector<int>& types) {
  std::vector<Diagram> diagrams;
  auto add = [&](const Filtration& f) {
    Diagram d = compute_diagram(cells, f);
    check_euler(d, f);
    check_homology_degrees(d);
    diagrams.push_back(std::move(d));
  };
  for (Direction direction : {Direction::forward, Direction::reverse})
    add(make_filtration(cells, direction));
  for (int type : types)
    for (Direction direction : {Direction::forward, Direction::reverse})
      add(make_type_filtration(cells, vertex_type, type, direction));
  return diagrams;
}

} // namespace medusa::persistence
