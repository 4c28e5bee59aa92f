#include "svg_plot.h"

#include "diagram_selection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace medusa::cli {
namespace {

constexpr double width = 800, left = 150, right = 20, bar_height = 4, bar_gap = 2, title_height = 22;
const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  return buffer;
}

} // namespace

void write_barcode_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams, double t0,
                       double t_end) {
  const double span = t_end > t0 ? t_end - t0 : 1.0;
  const double plot = width - left - right;
  auto x_of = [&](double t) {
    if (std::isinf(t))
      t = t > 0 ? t_end : t0;
    return left + plot * (std::clamp(t, t0, t0 + span) - t0) / span;
  };
  double height = 40;
  for (const persistence::Diagram& d : diagrams)
    height += title_height + static_cast<double>(d.pairs.size()) * (bar_height + bar_gap) + 10;

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
      << number(height) << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<defs><marker id=\"arrow\" markerWidth=\"6\" markerHeight=\"6\" refX=\"3\" refY=\"3\" "
         "orient=\"auto-start-reverse\"><path d=\"M0,0 L6,3 L0,6 z\"/></marker></defs>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  double y = 10;
  for (const persistence::Diagram& d : diagrams) {
    out << "<text x=\"4\" y=\"" << number(y + 14) << "\">type " << type_label(d.cell_type) << ", "
        << direction_name(d.direction) << " (" << d.pairs.size()
        << " bars; H0 blue, H1 red, H2 green)</text>\n";
    y += title_height;
    std::vector<persistence::PersistencePair> pairs = d.pairs;
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.dim < b.dim; });
    for (const persistence::PersistencePair& p : pairs) {
      const double a = x_of(p.birth), b = x_of(p.death);
      out << "<line x1=\"" << number(a) << "\" y1=\"" << number(y) << "\" x2=\"" << number(b) << "\" y2=\""
          << number(y) << "\" stroke=\"" << colours[std::clamp(p.dim, 0, 3)] << "\" stroke-width=\""
          << number(bar_height) << "\"" << (p.essential ? " marker-end=\"url(#arrow)\"" : "") << "/>\n";
      y += bar_height + bar_gap;
    }
    y += 10;
  }
  out << "<line x1=\"" << number(left) << "\" y1=\"" << number(y) << "\" x2=\"" << number(left + plot)
      << "\" y2=\"" << number(y) << "\" stroke=\"black\"/>\n"
      << "<text x=\"" << number(left) << "\" y=\"" << number(y + 14) << "\">MCS " << number(t0) << "</text>\n"
      << "<text x=\"" << number(left + plot) << "\" y=\"" << number(y + 14) << "\" text-anchor=\"end\">MCS "
      << number(t_end) << "</text>\n"
      << "</svg>\n";
}

} // namespace medusa::cli
