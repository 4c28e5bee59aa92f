// Reads an HDF5 store back into memory and validates it (docs/FORMAT.md).
#pragma once

#include "medusa/medusa/medusa.h"

#include <string>

namespace medusa {

// Loads the store at `path`. Throws StoreError naming the store when it cannot be opened, is not a
// medusa store, has another format version, is incomplete (no `complete` attribute: a killed writer),
// is truncated or corrupted (HDF5 checksums), or is inconsistent (see validate_medusa). Never returns
// partial or unchecked data.
struct StoreReadOptions {
  // Read /events (the batch and frame records). They grow with the number of events, and a caller
  // that needs only the cells (the diagrams of `medusa run`) can leave them out: Medusa::batches and
  // Medusa::frames stay empty, and /events is neither read nor checked.
  bool events = true;
  // false (with events): of the batch records only those frame_batch needs, the frame batches and
  // the last batch of each slab, a few per frame where a run has one per event time (45 million, 1.7
  // GB, at a million cells). Medusa::batches then holds those only: enough for frame_batch,
  // cells_at_frame and the summary of `medusa run`, not for what walks the event times (signatures,
  // curves, the report).
  bool every_batch = true;
};

Medusa read_store(const std::string& path, const StoreReadOptions& options = {});

// Store errors are one plain sentence; with details on (the CLI's --verbose) they also carry the HDF5
// library's own error stack, for a bug report.
void set_store_error_details(bool on);

// Checks the structure of a medusa: ids 0..N-1; sorted vertex tuples of known vertices; one facet per
// vertex, facet i the tuple without vertex i, whose lifetime contains the cell's (docs/MATH.md §6.4); d d = 0
// over Z/2; instant kinds have birth == death and regular cells birth < death; cells of one simplex
// have disjoint lifetimes; batches increase; nothing dies after the end. Throws StoreError("store
// <name>: ...") at the first violation.
void validate_medusa(const Medusa& medusa, const std::string& name);

} // namespace medusa
