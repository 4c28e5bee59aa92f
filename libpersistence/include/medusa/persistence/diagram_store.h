// Persistence diagrams stored next to the medusa they come from: the `/persistence` group of a
// medusa store (docs/FORMAT.md, "Persistence diagrams").
#pragma once

#include "medusa/persistence/diagram.h"
#include "medusa/persistence/representatives.h"

#include <memory>
#include <string>
#include <vector>

namespace medusa::persistence {

// Name of a diagram's subgroup: `<direction>_<type>`, e.g. `forward_all`, `reverse_type1`.
std::string diagram_group_name(const Diagram& diagram);

// Adds (or replaces) the group `/persistence` of the complete medusa store at `store_path`, one
// subgroup per diagram. Written safely: the store is copied to `<store_path>.tmp-<pid>`, the copy is
// changed and closed, then renamed over the original, so a crash leaves the original intact. Throws
// StoreError naming the store when it cannot be read or written, is not a complete medusa store, or
// two diagrams have the same group name. The class representatives of diagram i, if any, are in
// `*classes[i]` (subgroup `classes` of its group; class_store.h reads them); a null entry, or a
// diagram beyond the end of `classes`, gets none.
void write_diagrams(const std::string& store_path, const std::vector<Diagram>& diagrams,
                    const std::vector<const ClassRepresentatives*>& classes = {});

// The group `/persistence` written into a store one diagram at a time, as each is made: the caller
// can then drop a diagram's zero-length pairs and representatives as soon as it is stored, where
// they would otherwise all be held until the last diagram is done (`medusa run`: they are most of
// its memory after the kinetic stage). It writes into the file itself, so it is for a store nobody
// else can see yet (`medusa run` writes its store under a temporary name and publishes it with the
// run's other outputs at the end). The diagrams' group names (diagram_group_name) are given up front, in
// their order, which `diagram_order` records whatever order they are written in; the datasets do not depend
// on that order. Throws StoreError as write_diagrams does.
class DiagramStoreWriter {
public:
  DiagramStoreWriter(const std::string& store_path, const std::vector<std::string>& names);
  ~DiagramStoreWriter();
  DiagramStoreWriter(const DiagramStoreWriter&) = delete;
  DiagramStoreWriter& operator=(const DiagramStoreWriter&) = delete;

  // Writes one of the named diagrams, with its representatives if given (StoreError: a name not
  // given up front, or one written already).
  void write(const Diagram& diagram, const ClassRepresentatives* classes = nullptr);
  // Flushes and closes the store (StoreError: a named diagram was not written, or the flush failed).
  // Without it the store is closed with its group incomplete: for a run that failed.
  void close();

private:
  struct Open;
  std::unique_ptr<Open> open_;
};

// Reads `/persistence` back, in the stored order. Each pair has dim, birth, death, birth_cell,
// death_cell, essential and zero_length; the other fields of PersistencePair (virtual times,
// filtration indices, vertices) are not stored and keep their defaults. Throws StoreError when the
// store has no `/persistence` group or it is malformed. With `only` (a group name, diagram_group_name),
// just that diagram, or none when the store lists no such group: a million-cell run's six diagrams
// are gigabytes.
std::vector<Diagram> read_diagrams(const std::string& store_path, const std::string& only = {});

} // namespace medusa::persistence
