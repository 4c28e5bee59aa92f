// Piecewise constant curves over time as a standalone SVG: a row per group of curves, each curve a
// step line in a plot of its own (the value holds from its sample time until the next sample, docs/MATH.md
// §6.6).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

struct Curve {
  std::string name;
  std::vector<double> times; // increasing
  std::vector<double> values;
};

struct CurvePanel {
  std::string title;
  std::vector<Curve> curves;
};

// One row per panel, one plot per curve of the panel, side by side: each curve has its own vertical
// range (b0 ~ 1-10 beside b1 ~ 400 would lie flat on a shared one) and its own time axis [t0, t_end] (MCS).
void write_curves_svg(std::ostream& out, const std::vector<CurvePanel>& panels, double t0, double t_end);

} // namespace medusa::cli
