#include "svg_plot.h"

#include "diagram_selection.h"
#include "matrix_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace medusa::cli {
namespace {

constexpr double page_width = 1200, margin = 20, column_gap = 40, title_height = 50, axis_height = 34,
                 legend_height = 58, row_gap = 16, inset = 46;
const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
const char* const degree_names[] = {"H0 clusters", "H1 loops", "H2 cavities", "H3 4D bubbles"};

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  return buffer;
}

std::string value(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string tick_label(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

std::vector<double> ticks(double lo, double hi);

// One panel: a diagram's classes of one degree.
struct Panel {
  const persistence::Diagram* diagram = nullptr;
  std::string name; // "type 1 (Condensing), forward": the diagram_name
  int degree = 0;
  std::vector<std::size_t> drawn; // finite pairs drawn, by birth then death
  std::size_t finite = 0, essential = 0;
};

// The degrees shown as columns: those with a class of positive length in some diagram (H0-H2 for a
// run, one degree when the diagrams were selected by --dim), but H3 only with a finite class: in the
// forward filtration H3 classes are all essential (docs/MATH.md §7.6), counted in the header instead.
std::vector<int> degrees_of(const std::vector<persistence::Diagram>& diagrams) {
  std::vector<bool> shown(4, false);
  for (const persistence::Diagram& d : diagrams)
    for (const persistence::PersistencePair& p : d.pairs)
      if (!p.zero_length && p.dim >= 0 && p.dim <= 3 && (p.dim < 3 || !p.essential))
        shown[static_cast<std::size_t>(p.dim)] = true;
  std::vector<int> degrees;
  for (int k = 0; k <= 3; ++k)
    if (shown[static_cast<std::size_t>(k)])
      degrees.push_back(k);
  if (degrees.empty())
    degrees.push_back(0);
  return degrees;
}

// Essential classes of degrees without a column, which no panel counts.
std::size_t essential_beyond(const std::vector<persistence::Diagram>& diagrams,
                             const std::vector<int>& degrees) {
  std::size_t n = 0;
  for (const persistence::Diagram& d : diagrams)
    for (const persistence::PersistencePair& p : d.pairs)
      n += p.essential && std::find(degrees.begin(), degrees.end(), p.dim) == degrees.end() ? 1 : 0;
  return n;
}

// The time range a panel shows: the whole run, or, when its classes all lie within less than a third of
// it (the type-1 clusters of a sorting run join within the first tens of MCS of thousands), the
// range of tick steps that holds them, so that they can be seen.
std::pair<double, double> panel_range(const Panel& p, double t0, double t_end) {
  if (p.drawn.empty() || !(t_end > t0))
    return {t0, t_end};
  double lo = t_end, hi = t0;
  for (std::size_t i : p.drawn) {
    const persistence::PersistencePair& q = p.diagram->pairs[i];
    lo = std::min(lo, std::min(q.birth, q.death));
    hi = std::max(hi, std::max(q.birth, q.death));
  }
  lo = std::max(lo, t0);
  hi = std::min(hi, t_end);
  if (hi - lo >= (t_end - t0) / 3)
    return {t0, t_end};
  const std::vector<double> step = ticks(lo, hi > lo ? hi : lo + 1);
  const double s = step.size() > 1 ? step[1] - step[0] : 1.0;
  return {std::max(t0, std::floor(lo / s) * s),
          std::min(t_end, std::ceil(hi / s) * s > lo ? std::ceil(hi / s) * s : lo + s)};
}

std::string diagram_name(const persistence::Diagram& d, const TypeNames& names) {
  return type_label_title(names, type_label(d.cell_type)) + ", " + direction_name(d.direction);
}

// Finite positive-length pairs of degree k (max_bars > 0: the max_bars longest, ties by position),
// sorted by birth, then death; and the counts.
Panel make_panel(const persistence::Diagram& d, const TypeNames& names, int k, std::size_t max_bars) {
  Panel panel;
  panel.diagram = &d;
  panel.name = diagram_name(d, names);
  panel.degree = k;
  const auto& pairs = d.pairs;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const persistence::PersistencePair& p = pairs[i];
    if (p.dim != k || p.zero_length)
      continue;
    if (p.essential) {
      ++panel.essential;
      continue;
    }
    ++panel.finite;
    panel.drawn.push_back(i);
  }
  if (max_bars > 0 && panel.drawn.size() > max_bars) {
    const auto longer = [&](std::size_t a, std::size_t b) {
      const double la = std::abs(pairs[a].death - pairs[a].birth),
                   lb = std::abs(pairs[b].death - pairs[b].birth);
      return la != lb ? la > lb : a < b;
    };
    std::nth_element(panel.drawn.begin(), panel.drawn.begin() + static_cast<std::ptrdiff_t>(max_bars),
                     panel.drawn.end(), longer);
    panel.drawn.resize(max_bars);
  }
  const auto earlier = [&](std::size_t a, std::size_t b) {
    const double ba = std::min(pairs[a].birth, pairs[a].death), bb = std::min(pairs[b].birth, pairs[b].death);
    if (ba != bb)
      return ba < bb;
    const double da = std::max(pairs[a].birth, pairs[a].death), db = std::max(pairs[b].birth, pairs[b].death);
    return da != db ? da < db : a < b;
  };
  std::sort(panel.drawn.begin(), panel.drawn.end(), earlier);
  return panel;
}

// Tick values: 1, 2 or 5 times a power of ten, about five across [lo, hi].
std::vector<double> ticks(double lo, double hi) {
  const double span = hi - lo;
  if (!(span > 0))
    return {lo};
  const double raw = span / 5, power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double f : {1.0, 2.0, 5.0, 10.0})
    if (f * power >= raw) {
      step = f * power;
      break;
    }
  std::vector<double> out;
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
    out.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return out;
}

// "1469 filled, 566 never filled (counted, not drawn)": forward H0 classes join, H1 and H2 classes are
// filled; reverse diagrams and H3 in neutral words.
std::string counts_text(const Panel& p, std::size_t max_bars, bool bars) {
  const bool forward = p.diagram->direction == persistence::Direction::forward;
  std::string finite = "finite", essential = "essential";
  if (forward && p.degree == 0) {
    finite = "joined";
    essential = "never joined";
  } else if (forward && p.degree <= 2) {
    finite = "filled";
    essential = "never filled";
  }
  std::string text = std::to_string(p.finite) + " " + finite;
  if (bars && max_bars > 0 && p.drawn.size() < p.finite)
    text += " (the " + std::to_string(max_bars) + " longest drawn)";
  text += "\n" + std::to_string(p.essential) + " " + essential;
  if (p.essential > 0)
    text += " (counted, not drawn)";
  return text;
}

void write_header(std::ostream& out, double height, const std::vector<int>& degrees, std::string what,
                  std::size_t beyond, const std::string& run_id, const std::string& note = "") {
  // The note and the classes of other degrees get a line of their own: the caption alone fills most
  // of the page's width.
  std::string beyond_text = beyond == 0 ? std::string()
                                        : "Other degrees (H3, 4D bubbles): no finite class; " +
                                              std::to_string(beyond) + " essential in all (not drawn).";
  if (!note.empty())
    beyond_text = note + (beyond_text.empty() ? "" : " ") + beyond_text;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(page_width) << "\" height=\""
      << number(height) << "\" font-family=\"sans-serif\" font-size=\"11\""
      << (run_id.empty() ? std::string() : " data-medusa-run=\"" + run_id + "\"") << ">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  double x = margin;
  for (const int k : degrees) {
    out << "<rect x=\"" << number(x) << "\" y=\"" << number(margin) << "\" width=\"14\" height=\"10\" fill=\""
        << colours[k] << "\"/>\n"
        << "<text x=\"" << number(x + 18) << "\" y=\"" << number(margin + 9) << "\">" << degree_names[k]
        << "</text>\n";
    x += 140;
  }
  out << "<text x=\"" << number(margin) << "\" y=\"" << number(margin + 28) << "\" fill=\"#444\">" << what
      << "</text>\n";
  if (!beyond_text.empty())
    out << "<text x=\"" << number(margin) << "\" y=\"" << number(margin + 42) << "\" fill=\"#444\">"
        << beyond_text << "</text>\n";
}

// A horizontal time axis from x0 to x1 at height y, with ticks of [t0, t1].
void write_time_axis(std::ostream& out, double x0, double x1, double y, double t0, double t1,
                     const std::function<double(double)>& x_of) {
  out << "<line x1=\"" << number(x0) << "\" y1=\"" << number(y) << "\" x2=\"" << number(x1) << "\" y2=\""
      << number(y) << "\" stroke=\"black\"/>\n";
  for (double t : ticks(t0, t1)) {
    const double x = x_of(t);
    out << "<line x1=\"" << number(x) << "\" y1=\"" << number(y) << "\" x2=\"" << number(x) << "\" y2=\""
        << number(y + 4) << "\" stroke=\"black\"/>\n"
        << "<text x=\"" << number(x) << "\" y=\"" << number(y + 15) << "\" text-anchor=\"middle\">"
        << tick_label(t) << "</text>\n";
  }
  out << "<text x=\"" << number(x1) << "\" y=\"" << number(y + 28) << "\" text-anchor=\"end\">MCS</text>\n";
}

void open_panel(std::ostream& out, const Panel& p, double t0, double t_end) {
  out << "<g class=\"panel\" data-type=\"" << type_label(p.diagram->cell_type) << "\" data-direction=\""
      << direction_name(p.diagram->direction) << "\" data-degree=\"" << p.degree << "\" data-finite=\""
      << p.finite << "\" data-essential=\"" << p.essential << "\" data-drawn=\"" << p.drawn.size()
      << "\" data-t0=\"" << value(t0) << "\" data-t1=\"" << value(t_end) << "\">\n";
}

void write_title(std::ostream& out, const Panel& p, double x, double y, const std::string& counts) {
  const std::size_t cut = counts.find('\n');
  out << "<text x=\"" << number(x) << "\" y=\"" << number(y + 13) << "\" font-weight=\"bold\">"
      << xml_escape(p.name) << ", " << degree_names[p.degree] << "</text>\n"
      << "<text x=\"" << number(x) << "\" y=\"" << number(y + 27) << "\">" << counts.substr(0, cut)
      << "</text>\n"
      << "<text x=\"" << number(x) << "\" y=\"" << number(y + 41) << "\">" << counts.substr(cut + 1)
      << "</text>\n";
}

// A panel of more than max_points finite classes is drawn as a density: a scatter of millions of
// points (a run of a million cells) would be a file of gigabytes that no viewer opens, and the points
// hide one another anyway.
bool binned(const Panel& p, std::size_t max_points) { return max_points > 0 && p.drawn.size() > max_points; }

// The bin of time t among `bins` equal bins of [a, b]; b belongs to the last. Written as the checks
// (tests/pipeline/cli/check_analysis_outputs.py) recompute it from the panel's data-t0 and data-t1.
std::size_t bin_of(double t, double a, double b, std::size_t bins) {
  const double u = (std::clamp(t, a, b) - a) / (b - a);
  return std::min(bins - 1, static_cast<std::size_t>(u * static_cast<double>(bins)));
}

// The square [x0, x0 + side] x [top, top + side] cut into bins of about density_bin_px pixels; each bin
// holding classes one square, its opacity growing with the logarithm of its count. Each square
// carries its count and its bin (data-bx along birth, data-by along death, of data-bins per axis, so
// that a class at (b, d) lies in bin floor((b - t0) / (t1 - t0) * bins), clamped to the last).
void write_density(std::ostream& out, const Panel& p, double x0, double top, double side, double a,
                   double width) {
  constexpr double density_bin_px = 3;
  const auto bins = static_cast<std::size_t>(std::max(1.0, std::round(side / density_bin_px)));
  std::vector<std::size_t> count(bins * bins, 0);
  for (std::size_t i : p.drawn) {
    const persistence::PersistencePair& q = p.diagram->pairs[i];
    ++count[bin_of(q.death, a, a + width, bins) * bins + bin_of(q.birth, a, a + width, bins)];
  }
  const double most = static_cast<double>(*std::max_element(count.begin(), count.end()));
  const double cell = side / static_cast<double>(bins);
  out << "<g class=\"density\" data-bins=\"" << bins << "\">\n";
  for (std::size_t by = 0; by < bins; ++by)
    for (std::size_t bx = 0; bx < bins; ++bx) {
      const std::size_t n = count[by * bins + bx];
      if (n == 0)
        continue;
      const double shade = most > 1 ? 0.2 + 0.8 * std::log(static_cast<double>(n)) / std::log(most) : 0.6;
      out << "<rect class=\"bin\" data-count=\"" << n << "\" data-bx=\"" << bx << "\" data-by=\"" << by
          << "\" x=\"" << number(x0 + cell * static_cast<double>(bx)) << "\" y=\""
          << number(top + side - cell * static_cast<double>(by + 1)) << "\" width=\"" << number(cell)
          << "\" height=\"" << number(cell) << "\" fill=\"" << colours[p.degree] << "\" fill-opacity=\""
          << number(shade) << "\"/>\n";
    }
  out << "</g>\n";
}

} // namespace

void write_barcode_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
                       const TypeNames& names, double t0, double t_end, std::size_t max_bars,
                       const std::string& run_id) {
  const std::vector<int> degrees = degrees_of(diagrams);
  const auto columns = static_cast<double>(degrees.size());
  const double panel_width = (page_width - 2 * margin - (columns - 1) * column_gap) / columns;
  const double span = t_end > t0 ? t_end - t0 : 1.0;
  std::vector<std::vector<Panel>> rows;
  std::vector<double> plot_heights;
  for (const persistence::Diagram& d : diagrams) {
    rows.emplace_back();
    double tallest = 30;
    for (const int k : degrees) {
      rows.back().push_back(make_panel(d, names, k, max_bars));
      tallest =
          std::max(tallest, std::min(360.0, 2.0 * static_cast<double>(rows.back().back().drawn.size())));
    }
    plot_heights.push_back(tallest);
  }
  double height = margin + legend_height;
  for (double h : plot_heights)
    height += title_height + h + axis_height + row_gap;
  write_header(
      out, height + margin, degrees,
      "Barcodes: each finite class a bar from its birth to its death (MCS), sorted by birth; classes "
      "that never die are counted in the titles.",
      essential_beyond(diagrams, degrees), run_id);
  double y = margin + legend_height;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double h = plot_heights[r];
    for (std::size_t c = 0; c < degrees.size(); ++c) {
      const Panel& p = rows[r][c];
      const double x0 = margin + static_cast<double>(c) * (panel_width + column_gap), x1 = x0 + panel_width;
      const auto [a, b] = panel_range(p, t0, t_end);
      const double width = b > a ? b - a : span;
      const auto x_of = [&, a = a](double t) {
        return x0 + (x1 - x0) * (std::clamp(t, a, a + width) - a) / width;
      };
      open_panel(out, p, a, a + width);
      write_title(out, p, x0, y, counts_text(p, max_bars, true));
      const double top = y + title_height;
      out << "<rect x=\"" << number(x0) << "\" y=\"" << number(top) << "\" width=\"" << number(panel_width)
          << "\" height=\"" << number(h) << "\" fill=\"none\" stroke=\"#ddd\"/>\n";
      if (p.drawn.empty())
        out << "<text x=\"" << number(x0 + 6) << "\" y=\"" << number(top + 18)
            << "\" fill=\"#888\">no finite "
            << "class</text>\n";
      const double step = p.drawn.empty() ? 0 : h / static_cast<double>(p.drawn.size());
      const double thickness = std::clamp(0.8 * step, 0.4, 4.0);
      for (std::size_t i = 0; i < p.drawn.size(); ++i) {
        const persistence::PersistencePair& q = p.diagram->pairs[p.drawn[i]];
        const double yy = top + step * (static_cast<double>(i) + 0.5);
        out << "<line class=\"bar\" data-birth=\"" << value(q.birth) << "\" data-death=\"" << value(q.death)
            << "\" x1=\"" << number(x_of(std::min(q.birth, q.death))) << "\" y1=\"" << number(yy)
            << "\" x2=\"" << number(x_of(std::max(q.birth, q.death))) << "\" y2=\"" << number(yy)
            << "\" stroke=\"" << colours[p.degree] << "\" stroke-width=\"" << number(thickness) << "\"/>\n";
      }
      write_time_axis(out, x0, x1, top + h, a, a + width, x_of);
      out << "</g>\n";
    }
    y += title_height + h + axis_height + row_gap;
  }
  out << "</svg>\n";
}

void write_diagram_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
                       const TypeNames& names, double t0, double t_end, std::size_t max_points,
                       const std::string& run_id) {
  const std::vector<int> degrees = degrees_of(diagrams);
  const auto columns = static_cast<double>(degrees.size());
  const double panel_width = (page_width - 2 * margin - (columns - 1) * column_gap) / columns;
  const double side = std::min(panel_width - inset, 300.0);
  const double span = t_end > t0 ? t_end - t0 : 1.0;
  const double row_height = title_height + side + axis_height + row_gap;
  const double height = margin + legend_height + row_height * static_cast<double>(diagrams.size());
  std::vector<std::vector<Panel>> rows;
  bool any_binned = false;
  for (const persistence::Diagram& d : diagrams) {
    rows.emplace_back();
    for (const int k : degrees) {
      rows.back().push_back(make_panel(d, names, k, 0));
      any_binned = any_binned || binned(rows.back().back(), max_points);
    }
  }
  write_header(out, height + margin, degrees,
               "Persistence diagrams: each finite class a point (birth, death) in MCS; the farther above the "
               "diagonal, the longer it lived. Classes that never die are counted in the titles.",
               essential_beyond(diagrams, degrees), run_id,
               any_binned ? "Panels of more than " + std::to_string(max_points) +
                                " classes are shaded squares: the darker, the more classes."
                          : std::string());
  double y = margin + legend_height;
  for (const std::vector<Panel>& row : rows) {
    const persistence::Diagram& d = *row.front().diagram;
    for (std::size_t c = 0; c < degrees.size(); ++c) {
      const int k = degrees[c];
      const Panel& p = row[c];
      const double x0 = margin + static_cast<double>(c) * (panel_width + column_gap) + inset, x1 = x0 + side;
      const double top = y + title_height, bottom = top + side;
      const auto [a, b] = panel_range(p, t0, t_end);
      const double width = b > a ? b - a : span;
      const auto x_of = [&, a = a](double t) {
        return x0 + side * (std::clamp(t, a, a + width) - a) / width;
      };
      const auto y_of = [&, a = a](double t) {
        return bottom - side * (std::clamp(t, a, a + width) - a) / width;
      };
      open_panel(out, p, a, a + width);
      std::string counts = counts_text(p, 0, false);
      if (binned(p, max_points))
        counts.insert(counts.find('\n'), ", shaded by count");
      write_title(out, p, x0 - inset, y, counts);
      out << "<rect x=\"" << number(x0) << "\" y=\"" << number(top) << "\" width=\"" << number(side)
          << "\" height=\"" << number(side) << "\" fill=\"none\" stroke=\"#ddd\"/>\n"
          << "<line class=\"diagonal\" x1=\"" << number(x0) << "\" y1=\"" << number(bottom) << "\" x2=\""
          << number(x1) << "\" y2=\"" << number(top) << "\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n";
      if (binned(p, max_points))
        write_density(out, p, x0, top, side, a, width);
      else
        for (std::size_t i : p.drawn) {
          const persistence::PersistencePair& q = d.pairs[i];
          out << "<circle class=\"point\" data-birth=\"" << value(q.birth) << "\" data-death=\""
              << value(q.death) << "\" cx=\"" << number(x_of(q.birth)) << "\" cy=\"" << number(y_of(q.death))
              << "\" r=\"2.2\" fill=\"" << colours[k] << "\" fill-opacity=\"0.55\"/>\n";
        }
      write_time_axis(out, x0, x1, bottom, a, a + width, x_of);
      // The death axis, on the left.
      out << "<line x1=\"" << number(x0) << "\" y1=\"" << number(top) << "\" x2=\"" << number(x0)
          << "\" y2=\"" << number(bottom) << "\" stroke=\"black\"/>\n";
      for (double t : ticks(a, a + width))
        out << "<text x=\"" << number(x0 - 4) << "\" y=\"" << number(y_of(t) + 4) << "\" text-anchor=\"end\">"
            << tick_label(t) << "</text>\n";
      out << "<text x=\"" << number(x0 + 4) << "\" y=\"" << number(top + 12)
          << "\" fill=\"#444\">death</text>\n"
          << "<text x=\"" << number(x1 - 4) << "\" y=\"" << number(bottom - 6)
          << "\" text-anchor=\"end\" fill=\"#444\">birth</text>\n"
          << "</g>\n";
    }
    y += row_height;
  }
  out << "</svg>\n";
}

} // namespace medusa::cli
