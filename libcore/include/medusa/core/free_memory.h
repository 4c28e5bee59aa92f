// Returning the heap's free pages to the system between the large phases of a run (the kinetic
// stage, each whole-medusa reduction), so that the next phase, possibly on another thread's heap,
// reuses them instead of adding to the peak.
#pragma once

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace medusa {

// glibc's malloc_trim; nothing elsewhere.
inline void release_free_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

} // namespace medusa
