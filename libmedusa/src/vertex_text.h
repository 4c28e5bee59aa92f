// Text of a vertex tuple for one-line error messages.
#pragma once

#include "medusa/medusa/cell.h"

#include <sstream>
#include <string>
#include <vector>

namespace medusa {

template <class Range> std::string vertex_text(const Range& vertices) {
  std::ostringstream os;
  os << '[';
  bool first = true;
  for (VertexId v : vertices) {
    os << (first ? "" : " ") << v;
    first = false;
  }
  os << ']';
  return os.str();
}

} // namespace medusa
