#include "medusa/kinetic/observer.h"

namespace medusa::kinetic {

const char* to_string(StepKind kind) {
  switch (kind) {
  case StepKind::radius: return "radius";
  case StepKind::flip23: return "flip23";
  case StepKind::flip32: return "flip32";
  case StepKind::flip22: return "flip22";
  case StepKind::hull_flip: return "hull_flip";
  case StepKind::insertion: return "insertion";
  case StepKind::deletion: return "deletion";
  case StepKind::repair: return "repair";
  case StepKind::settle: return "settle";
  }
  return "unknown";
}

} // namespace medusa::kinetic
