// CROCKER data (Topaz, Ziegelmeier & Halverson 2015): the Betti numbers b0, b1, b2 of K_t over time and
// alpha radius, per cell type. `medusa sweep` writes them as CSV and SVG heat maps; `medusa report`
// reads the CSV back and shows the heat maps.
#pragma once

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

struct CrockerRow {
  std::string radius; // decimal text, as given to the kinetic stage
  double time = 0;    // frame time (MCS)
  std::string type;   // "all" or the type id
  std::array<std::size_t, 3> betti{};
};

// Header `radius,time,type,b0,b1,b2`, one row per radius, frame and type.
void write_crocker_csv(std::ostream& out, const std::vector<CrockerRow>& rows);
// Reads what write_crocker_csv wrote; InputError naming the file and line otherwise.
std::vector<CrockerRow> read_crocker_csv(const std::string& path);

// One panel per type and degree (x = MCS, y = radius, colour = log(1 + Betti number), so 0 has one, with a
// colour legend per panel); degrees up to `max_degree` (1 for planar runs: they have no cavities).
// Each cell has a <title> with its radius, time and value. `title` heads the picture.
void write_crocker_svg(std::ostream& out, const std::vector<CrockerRow>& rows, const std::string& title,
                       int max_degree = 2);

} // namespace medusa::cli
