#include "medusa/persistence/diagram_text.h"

#include <cstdio>

namespace medusa::persistence {
namespace {

// %.17g round-trips every double and does not depend on the stream's locale or flags.
void put_double(std::ostream& out, double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  out << buffer;
}

} // namespace

void write_diagram_text(std::ostream& out, const Diagram& diagram, const std::vector<medusa::Cell>& cells) {
  out << "# medusa diagram direction=" << (diagram.direction == Direction::forward ? "forward" : "reverse")
      << " cell_type=" << diagram.cell_type << " points=" << diagram.pairs.size() << '\n';
  for (const auto& p : diagram.pairs) {
    out << p.dim << ' ';
    put_double(out, p.birth);
    out << ' ';
    put_double(out, p.death);
    out << ' ' << p.birth_time.batch << ' ' << p.birth_time.rank << ' ' << p.death_time.batch << ' '
        << p.death_time.rank << ' ' << p.birth_index << ' ' << p.death_index << ' ' << p.birth_cell << ' '
        << p.death_cell << ' ' << int(p.essential) << ' ' << int(p.zero_length);
    for (auto v : birth_vertices(p, cells))
      out << ' ' << v;
    out << " |";
    for (auto v : death_vertices(p, cells))
      out << ' ' << v;
    out << '\n';
  }
}

} // namespace medusa::persistence
