// Reader of CompuCell3D cell-centre CSV files (plain or gzip): one row per cell per saved MCS
// (docs/MATH.md §1.2). Real header: mcs,cell_id,cluster_id,type_id,type_name,xCOM,yCOM,zCOM,volume.
#pragma once

#include "medusa/io/cell_sample.h"
#include "medusa/io/centroid.h"

#include <cstdint>
#include <string>
#include <vector>

namespace medusa::io {

// Column names. The first six are required; an empty optional name means "do not use".
struct CsvColumns {
  std::string mcs = "mcs";
  std::string cell_id = "cell_id";
  std::string type = "type_id";
  std::string x = "xCOM";
  std::string y = "yCOM";
  std::string z = "zCOM";
  std::string volume = "volume";       // optional
  std::string type_name = "type_name"; // optional
};

struct CsvOptions {
  CsvColumns columns;
  std::int64_t scale = 1000000; // grid scale S = 10^m (docs/MATH.md §1.1)
  // Centres with more decimals than the grid holds are rounded to it, ties to even (policy R,
  // docs/MATH.md §1.2) and counted in CsvContents::rounding; otherwise they are InputErrors.
  bool round = false;
  std::string round_option = "--round-csv"; // named where a centre is refused for its decimals
};

struct CsvContents {
  std::vector<CellSample> samples;     // in file order; source index 0 = the file
  std::vector<std::string> type_names; // index = type id; "" where the file names none
  bool has_volume = false;
  SnapReport rounding; // snapped: CsvOptions::round was in force
};

// Reads every row. Row order does not matter. Throws a one-line InputError naming file, line and
// (when known) cell for: an unreadable or truncated file, a missing column, a wrong number of fields,
// a non-numeric / NaN value, an over-precise one unless rounding was asked for, a duplicate (MCS, cell), a
// cell that changes type, a type id with two names, a non-positive cell id or type.
CsvContents read_csv(const std::string& path, const CsvOptions& options = {});

} // namespace medusa::io
