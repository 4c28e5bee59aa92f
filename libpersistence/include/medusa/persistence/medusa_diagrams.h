// All diagrams of one run in one call: forward and reverse, for the whole medusa and for the
// sub-medusa of each requested cell type (docs/MATH.md §7.2-§7.4), each audited (Euler characteristic,
// homology degrees).
#pragma once

#include "medusa/persistence/diagram.h"
#include "medusa/persistence/representatives.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace medusa::persistence {

// The seconds spent in each phase, summed over the tasks (threads run tasks concurrently, so the
// sum may exceed the wall time): building filtrations, reducing them into audited diagrams, and
// handing each over (DiagramRunOptions::on_diagram, dropping zero-length pairs).
struct DiagramPhaseSeconds {
  double filtrations = 0.0;
  double reduction = 0.0;
  double handed_over = 0.0;
};

// How compute_medusa_diagrams runs and what it hands back besides the diagrams.
struct DiagramRunOptions {
  // Worker threads (1 = sequential in the calling thread).
  unsigned threads = 1;
  // When given, receives the time spent per phase.
  DiagramPhaseSeconds* phases = nullptr;
  // When given, receives for each diagram the representatives of its classes (representatives.h)
  // selected by `representatives`, for the forward diagrams only (the reverse ones get an empty entry).
  std::vector<ClassRepresentatives>* forward_classes = nullptr;
  RepresentativeOptions representatives;
  // When given, called with each diagram as soon as it is made and audited, whole, with the
  // representatives of its classes when forward_classes is given (null otherwise and for reverse
  // diagrams), to store them (DiagramStoreWriter) or read them while every pair is there. One call at
  // a time, in the order the diagrams are finished, which with more than one thread is not theirs.
  // It may take the pairs or the representatives away; what it leaves is returned.
  std::function<void(std::size_t index, Diagram& diagram, ClassRepresentatives* classes)> on_diagram;
  // false: each diagram drops its zero-length pairs as soon as it is made (after on_diagram), so they
  // never all sit in memory at once (they are about half the pairs of a large medusa). The
  // representatives, whose rows are positions among all pairs, go with them: forward_classes then
  // needs on_diagram, and receives empty entries.
  bool zero_length = true;
  // Called every few thousand columns of each reduction, on the thread running it: a caller stops
  // the computation by throwing from it.
  std::function<void()> poll;

  static DiagramRunOptions on_threads(unsigned n) {
    DiagramRunOptions options;
    options.threads = n;
    return options;
  }
};

// The sub-medusas whose diagrams compute_medusa_diagrams makes for `types`, in its order: the whole
// medusa (all_types), then each type of `types`.
std::vector<int> sub_medusa_types(const std::vector<int>& types);

// The group names (diagram_group_name) of the diagrams compute_medusa_diagrams makes for `types`, in
// its order: the names DiagramStoreWriter is given up front.
std::vector<std::string> medusa_diagram_names(const std::vector<int>& types);

// Order: whole forward, whole reverse, then forward and reverse for each type in `types`. Throws
// InternalError when an audit fails (check_euler, check_homology_degrees). The filtrations are
// independent, and so are their reductions (each thread owns its PHAT boundary matrix), so the result
// is the same for every thread count. Each task builds one filtration, reduces it and frees it, so at
// most `threads` filtrations and boundary matrices are in memory at once, and at most one of the whole
// medusa: the two whole-medusa tasks never overlap, the per-type ones fill the other threads meanwhile
// (this bounds the peak memory of `medusa run`). When several filtrations fail, the error of the first
// one in the order above is thrown.
std::vector<Diagram> compute_medusa_diagrams(const std::vector<medusa::Cell>& cells,
                                             const std::vector<int>& vertex_type,
                                             const std::vector<int>& types,
                                             const DiagramRunOptions& options = {});

} // namespace medusa::persistence
