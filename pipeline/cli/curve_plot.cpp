#include "curve_plot.h"

#include "matrix_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace medusa::cli {
namespace {

constexpr double width = 800, left = 70, right = 150, panel_height = 180, gap = 50, top = 20;
const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  return buffer;
}

std::string tick(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

} // namespace

void write_curves_svg(std::ostream& out, const std::vector<CurvePanel>& panels, double t0, double t_end) {
  const double span = t_end > t0 ? t_end - t0 : 1.0;
  const double plot = width - left - right;
  const double height = top + static_cast<double>(panels.size()) * (panel_height + gap);
  auto x_of = [&](double t) { return left + plot * (std::clamp(t, t0, t0 + span) - t0) / span; };

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
      << number(height) << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  double y0 = top;
  for (const CurvePanel& panel : panels) {
    double largest = 0;
    for (const Curve& c : panel.curves)
      for (double v : c.values)
        largest = std::max(largest, v);
    const double scale_top = largest > 0 ? largest : 1;
    const double bottom = y0 + panel_height;
    auto y_of = [&](double v) { return bottom - (panel_height - 20) * v / scale_top; };
    out << "<text x=\"" << number(left) << "\" y=\"" << number(y0 + 12) << "\">" << xml_escape(panel.title)
        << "</text>\n"
        << "<rect x=\"" << number(left) << "\" y=\"" << number(y0 + 20) << "\" width=\"" << number(plot)
        << "\" height=\"" << number(panel_height - 20) << "\" fill=\"none\" stroke=\"#999\"/>\n"
        << "<text x=\"" << number(left - 4) << "\" y=\"" << number(bottom)
        << "\" text-anchor=\"end\">0</text>\n"
        << "<text x=\"" << number(left - 4) << "\" y=\"" << number(y0 + 24) << "\" text-anchor=\"end\">"
        << tick(largest) << "</text>\n"
        << "<text x=\"" << number(left) << "\" y=\"" << number(bottom + 14) << "\">MCS " << tick(t0)
        << "</text>\n"
        << "<text x=\"" << number(left + plot) << "\" y=\"" << number(bottom + 14)
        << "\" text-anchor=\"end\">MCS " << tick(t_end) << "</text>\n";
    for (std::size_t k = 0; k < panel.curves.size(); ++k) {
      const Curve& c = panel.curves[k];
      const char* colour = colours[k % (sizeof colours / sizeof colours[0])];
      if (!c.times.empty()) {
        out << "<path fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\" d=\"M"
            << number(x_of(c.times.front())) << "," << number(y_of(c.values.front()));
        // A step is drawn only where the value changes, which keeps long runs (tens of thousands of
        // event batches) small.
        for (std::size_t i = 1; i < c.times.size(); ++i)
          if (c.values[i] != c.values[i - 1])
            out << " H" << number(x_of(c.times[i])) << " V" << number(y_of(c.values[i]));
        out << " H" << number(x_of(t_end)) << "\"/>\n";
      }
      const double legend_y = y0 + 34 + 14 * static_cast<double>(k);
      out << "<line x1=\"" << number(left + plot + 10) << "\" y1=\"" << number(legend_y - 4) << "\" x2=\""
          << number(left + plot + 30) << "\" y2=\"" << number(legend_y - 4) << "\" stroke=\"" << colour
          << "\" stroke-width=\"2\"/>\n"
          << "<text x=\"" << number(left + plot + 34) << "\" y=\"" << number(legend_y) << "\">"
          << xml_escape(c.name) << "</text>\n";
    }
    y0 += panel_height + gap;
  }
  out << "</svg>\n";
}

} // namespace medusa::cli
