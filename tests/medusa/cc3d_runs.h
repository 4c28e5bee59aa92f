// The real CompuCell3D runs of tests/data/cc3d as trajectories, cut to their first frames, for the
// medusa tests that run the kinetic engine on them.
#pragma once

#include "kinetic_run.h"
#include "medusa/io/run_reader.h"

#include <string>

namespace medusa::test {

// The cell centres of cells.csv.gz of tests/data/cc3d/<name>, first `frames` frames.
inline kinetic::Trajectories read_cc3d(const std::string& name, std::size_t frames) {
  io::RunOptions options;
  options.source = io::RunSource::csv;
  const io::RunData data =
      io::read_csv_run(std::string(MEDUSA_TEST_DATA) + "/cc3d/" + name + "/cells.csv.gz", options);
  return first_frames(data.trajectories, frames);
}

} // namespace medusa::test
