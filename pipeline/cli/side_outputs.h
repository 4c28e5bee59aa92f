// The side outputs `medusa run` writes next to a store (<stem>.diagrams.csv, <stem>.barcode.svg,
// <stem>.diagram.svg)
// carry the store's run id (docs/FORMAT.md, "One result per run"); a reader checks it.
#pragma once

#include <string>

namespace medusa::cli {

// `<stem>` of a store path: the path without a final ".h5".
std::string output_stem(const std::string& output);

// StoreError when a side output beside `store` exists but carries another run id than `run_id` (or
// none): the files are from two runs, as after a kill while a run's outputs were being renamed into
// place. Nothing to check for a store without a run id.
void check_side_outputs(const std::string& store, const std::string& run_id);

} // namespace medusa::cli
