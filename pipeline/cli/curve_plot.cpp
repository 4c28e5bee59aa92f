#include "curve_plot.h"

#include "matrix_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace medusa::cli {
namespace {

constexpr double width = 1200, margin = 20, left = 44, gap = 30, panel_height = 200, row_gap = 50, top = 40;
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

// Tick values: 0 and 1, 2 or 5 times a power of ten, about four across [lo, hi].
std::vector<double> value_ticks(double lo, double hi) {
  const double span = hi - lo;
  if (!(span > 0))
    return {lo};
  const double raw = span / 4, power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double f : {1.0, 2.0, 5.0, 10.0})
    if (f * power >= raw) {
      step = f * power;
      break;
    }
  if (step < 1 && lo == 0 && hi >= 1)
    step = 1; // counts are integers
  std::vector<double> marks;
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
    marks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return marks;
}

// "b1" -> "b1 loops": what each count of K_t is (docs/MATH.md §6.6).
std::string curve_label(const std::string& name) {
  static const std::pair<const char*, const char*> words[] = {
      {"b0", "clusters"}, {"b1", "loops"},     {"b2", "cavities"},  {"f0", "vertices"},
      {"f1", "edges"},    {"f2", "triangles"}, {"f3", "tetrahedra"}};
  for (const auto& [key, word] : words)
    if (name == key)
      return name + " " + word;
  return name;
}

} // namespace

void write_curves_svg(std::ostream& out, const std::vector<CurvePanel>& panels, double t0, double t_end) {
  std::size_t columns = 1;
  for (const CurvePanel& panel : panels)
    columns = std::max(columns, panel.curves.size());
  const double span = t_end > t0 ? t_end - t0 : 1.0;
  const double cell =
      (width - 2 * margin - static_cast<double>(columns - 1) * gap) / static_cast<double>(columns);
  const double plot = cell - left;
  const double height = top + static_cast<double>(panels.size()) * (panel_height + row_gap) + margin;

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
      << number(height) << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << number(margin) << "\" y=\"" << number(margin + 4)
      << "\" fill=\"#444\">Each curve in its own panel, with its own vertical range; time in MCS.</text>\n";
  double y0 = top;
  for (const CurvePanel& panel : panels) {
    out << "<text x=\"" << number(margin) << "\" y=\"" << number(y0 + 12) << "\" font-weight=\"bold\">"
        << xml_escape(panel.title) << "</text>\n";
    for (std::size_t k = 0; k < panel.curves.size(); ++k) {
      const Curve& c = panel.curves[k];
      const char* colour = colours[k % (sizeof colours / sizeof colours[0])];
      const double x0 = margin + static_cast<double>(k) * (cell + gap) + left, x1 = x0 + plot;
      const double plot_top = y0 + 50, bottom = y0 + panel_height;
      double lo = 0, hi = 0;
      for (double v : c.values)
        hi = std::max(hi, v);
      const std::vector<double> marks = value_ticks(lo, hi > lo ? hi : 1);
      const double scale_top = std::max(hi > lo ? hi : 1.0, marks.back());
      auto x_of = [&](double t) { return x0 + plot * (std::clamp(t, t0, t0 + span) - t0) / span; };
      auto y_of = [&](double v) { return bottom - (bottom - plot_top) * (v - lo) / (scale_top - lo); };
      out << "<g class=\"curve\" data-name=\"" << xml_escape(c.name) << "\" data-max=\"" << tick(hi)
          << "\">\n"
          << "<text x=\"" << number(x0) << "\" y=\"" << number(y0 + 28) << "\" fill=\"" << colour << "\">"
          << xml_escape(curve_label(c.name)) << (c.values.empty() ? "" : ":") << "</text>\n";
      // The values on a line of their own: a type's name beside them ran past a third of the page.
      if (!c.values.empty())
        out << "<text x=\"" << number(x0) << "\" y=\"" << number(y0 + 41) << "\" fill=\"" << colour << "\">"
            << tick(c.values.front()) << " at MCS " << tick(t0) << ", " << tick(c.values.back()) << " at MCS "
            << tick(t_end) << "</text>\n";
      out << "<rect x=\"" << number(x0) << "\" y=\"" << number(plot_top) << "\" width=\"" << number(plot)
          << "\" height=\"" << number(bottom - plot_top) << "\" fill=\"none\" stroke=\"#ddd\"/>\n";
      for (double v : marks)
        out << "<line x1=\"" << number(x0 - 3) << "\" y1=\"" << number(y_of(v)) << "\" x2=\"" << number(x0)
            << "\" y2=\"" << number(y_of(v)) << "\" stroke=\"black\"/>\n"
            << "<text x=\"" << number(x0 - 5) << "\" y=\"" << number(y_of(v) + 4) << "\" text-anchor=\"end\">"
            << tick(v) << "</text>\n";
      out << "<line x1=\"" << number(x0) << "\" y1=\"" << number(bottom) << "\" x2=\"" << number(x1)
          << "\" y2=\"" << number(bottom) << "\" stroke=\"black\"/>\n";
      for (double t : value_ticks(t0, t0 + span))
        out << "<line x1=\"" << number(x_of(t)) << "\" y1=\"" << number(bottom) << "\" x2=\""
            << number(x_of(t)) << "\" y2=\"" << number(bottom + 4) << "\" stroke=\"black\"/>\n"
            << "<text x=\"" << number(x_of(t)) << "\" y=\"" << number(bottom + 15)
            << "\" text-anchor=\"middle\">" << tick(t) << "</text>\n";
      out << "<text x=\"" << number(x1) << "\" y=\"" << number(bottom + 28)
          << "\" text-anchor=\"end\">MCS</text>\n";
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
      out << "</g>\n";
    }
    y0 += panel_height + row_gap;
  }
  out << "</svg>\n";
}

} // namespace medusa::cli
