// The engine of 3D runs: every part of engine/ instantiated with KineticTraits3.
#include "engine/audit.h"
#include "engine/cells.h"
#include "engine/certificates.h"
#include "engine/collisions.h"
#include "engine/degenerate_groups.h"
#include "engine/event_loop.h"
#include "engine/flips.h"
#include "engine/frames.h"
#include "engine/local_updates.h"
#include "engine/membership.h"
#include "engine/run.h"
#include "engine/static_rebuild.h"

namespace medusa::kinetic::detail {

template class Engine<KineticTraits3>;

} // namespace medusa::kinetic::detail
