#include "svg_plot.h"

#include "diagram_selection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace medusa::cli {
namespace {

constexpr double width = 800, left = 150, right = 20, bar_height = 4, bar_gap = 2, title_height = 22;
const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  return buffer;
}

// The bars drawn for one diagram: all of them, or per degree the max_bars longest (essential bars
// first, then by length; ties keep the diagram's order). Indices, in degree order and then the
// diagram's, so a diagram within the cap is drawn exactly as it is; indices rather than copies, as a
// diagram of a large run holds tens of thousands of pairs.
std::vector<std::size_t> shown_bars(const persistence::Diagram& d, std::size_t max_bars) {
  std::vector<std::size_t> order(d.pairs.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  const auto& pairs = d.pairs;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return pairs[a].dim < pairs[b].dim; });
  if (max_bars == 0)
    return order;
  const auto longer = [&](std::size_t a, std::size_t b) {
    const persistence::PersistencePair &p = pairs[a], &q = pairs[b];
    if (p.essential != q.essential)
      return p.essential;
    const double lp = std::abs(p.death - p.birth), lq = std::abs(q.death - q.birth);
    return lp != lq ? lp > lq : a < b;
  };
  std::vector<std::size_t> kept;
  for (auto first = order.begin(); first != order.end();) {
    const auto last =
        std::find_if(first, order.end(), [&](std::size_t i) { return pairs[i].dim != pairs[*first].dim; });
    std::vector<std::size_t> degree(first, last);
    if (degree.size() > max_bars) {
      std::nth_element(degree.begin(), degree.begin() + static_cast<std::ptrdiff_t>(max_bars), degree.end(),
                       longer);
      degree.resize(max_bars);
      std::sort(degree.begin(), degree.end());
    }
    kept.insert(kept.end(), degree.begin(), degree.end());
    first = last;
  }
  return kept;
}

} // namespace

void write_barcode_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams, double t0,
                       double t_end, std::size_t max_bars, const std::string& run_id) {
  const double span = t_end > t0 ? t_end - t0 : 1.0;
  const double plot = width - left - right;
  auto x_of = [&](double t) {
    if (std::isinf(t))
      t = t > 0 ? t_end : t0;
    return left + plot * (std::clamp(t, t0, t0 + span) - t0) / span;
  };
  std::vector<std::vector<std::size_t>> shown;
  double height = 40;
  for (const persistence::Diagram& d : diagrams) {
    shown.push_back(shown_bars(d, max_bars));
    height += title_height + static_cast<double>(shown.back().size()) * (bar_height + bar_gap) + 10;
  }

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
      << number(height) << "\" font-family=\"sans-serif\" font-size=\"11\""
      << (run_id.empty() ? std::string() : " data-medusa-run=\"" + run_id + "\"") << ">\n"
      << "<defs><marker id=\"arrow\" markerWidth=\"6\" markerHeight=\"6\" refX=\"3\" refY=\"3\" "
         "orient=\"auto-start-reverse\"><path d=\"M0,0 L6,3 L0,6 z\"/></marker></defs>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  double y = 10;
  for (std::size_t k = 0; k < diagrams.size(); ++k) {
    const persistence::Diagram& d = diagrams[k];
    out << "<text x=\"4\" y=\"" << number(y + 14) << "\">type " << type_label(d.cell_type) << ", "
        << direction_name(d.direction) << " (" << d.pairs.size() << " bars";
    if (shown[k].size() < d.pairs.size())
      out << ", the " << max_bars << " longest of each degree shown";
    out << "; H0 blue, H1 red, H2 green)</text>\n";
    y += title_height;
    for (const std::size_t i : shown[k]) {
      const persistence::PersistencePair& p = d.pairs[i];
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
