#include "matrix_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace medusa::cli {
namespace {

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", x);
  return buffer;
}

std::string label(double d) {
  if (std::isinf(d))
    return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", d);
  return buffer;
}

// White (0) to dark blue (1), linear in each RGB channel.
std::string colour(double fraction) {
  const double f = std::clamp(fraction, 0.0, 1.0);
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", static_cast<int>(std::lround(255 - f * (255 - 8))),
                static_cast<int>(std::lround(255 - f * (255 - 48))),
                static_cast<int>(std::lround(255 - f * (255 - 107))));
  return buffer;
}

// The title runs along the top; the picture is at least as wide as it (about 6.2 px per character at
// font size 11).
double title_width(const std::string& title) { return 8 + 6.2 * static_cast<double>(title.size()); }

// The viewBox lets a page that shrinks the picture (the report does) scale it instead of cutting it off.
void svg_header(std::ostream& out, double width, double height) {
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
      << number(height) << "\" viewBox=\"0 0 " << number(width) << " " << number(height)
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<defs><pattern id=\"hatch\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\">"
         "<rect width=\"6\" height=\"6\" fill=\"#d0d0d0\"/><path d=\"M0,6 L6,0\" stroke=\"#808080\"/>"
         "</pattern></defs>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

} // namespace

std::string xml_escape(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
    case '&': escaped += "&amp;"; break;
    case '<': escaped += "&lt;"; break;
    case '>': escaped += "&gt;"; break;
    case '"': escaped += "&quot;"; break;
    default: escaped += c;
    }
  }
  return escaped;
}

std::vector<std::size_t> leaf_order(const persistence::Dendrogram& dendrogram) {
  const std::size_t n = dendrogram.leaves;
  std::vector<std::size_t> order;
  if (n == 0)
    return order;
  std::function<void(std::size_t)> visit = [&](std::size_t cluster) {
    if (cluster < n) {
      order.push_back(cluster);
      return;
    }
    const persistence::Merge& m = dendrogram.merges[cluster - n];
    visit(m.first);
    visit(m.second);
  };
  visit(n == 1 ? 0 : 2 * n - 2);
  return order;
}

void write_heatmap_svg(std::ostream& out, const persistence::DistanceMatrix& distances,
                       const std::vector<std::string>& names, const std::string& title) {
  const std::size_t n = distances.size;
  std::size_t longest = 1;
  for (const std::string& name : names)
    longest = std::max(longest, name.size());
  const double margin = 12 + 7.0 * static_cast<double>(longest),
               top = 40 + 7.0 * static_cast<double>(longest);
  const double cell = std::clamp(600.0 / static_cast<double>(std::max<std::size_t>(n, 1)), 14.0, 60.0);
  const double side = cell * static_cast<double>(n);
  double largest = 0;
  for (double v : distances.values)
    if (std::isfinite(v))
      largest = std::max(largest, v);

  svg_header(out, std::max(margin + side + 120, title_width(title)), top + std::max(side, 60.0) + 20);
  out << "<text x=\"4\" y=\"16\">" << xml_escape(title) << "</text>\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double y = top + cell * static_cast<double>(i);
    out << "<text x=\"" << number(margin - 4) << "\" y=\"" << number(y + cell / 2 + 4)
        << "\" text-anchor=\"end\">" << xml_escape(names[i]) << "</text>\n";
    const double x = margin + cell * static_cast<double>(i) + cell / 2;
    out << "<text transform=\"translate(" << number(x + 4) << "," << number(top - 4) << ") rotate(-90)\">"
        << xml_escape(names[i]) << "</text>\n";
    for (std::size_t j = 0; j < n; ++j) {
      const double v = distances.at(i, j);
      const std::string fill = std::isinf(v) ? "url(#hatch)" : colour(largest > 0 ? v / largest : 0);
      out << "<rect x=\"" << number(margin + cell * static_cast<double>(j)) << "\" y=\"" << number(y)
          << "\" width=\"" << number(cell) << "\" height=\"" << number(cell) << "\" fill=\"" << fill
          << "\" stroke=\"white\"><title>" << xml_escape(names[i]) << " / " << xml_escape(names[j]) << ": "
          << label(v) << "</title></rect>\n";
      if (cell >= 30)
        out << "<text x=\"" << number(margin + cell * (static_cast<double>(j) + 0.5)) << "\" y=\""
            << number(y + cell / 2 + 4) << "\" text-anchor=\"middle\" fill=\""
            << (std::isfinite(v) && largest > 0 && v / largest > 0.5 ? "white" : "black") << "\">" << label(v)
            << "</text>\n";
    }
  }
  // Colour scale beside the matrix.
  const double bar_x = margin + side + 20, bar_height = std::max(side, 60.0);
  for (int k = 0; k < 20; ++k)
    out << "<rect x=\"" << number(bar_x) << "\" y=\"" << number(top + bar_height * (19 - k) / 20.0)
        << "\" width=\"14\" height=\"" << number(bar_height / 20.0 + 0.5) << "\" fill=\"" << colour(k / 19.0)
        << "\"/>\n";
  out << "<text x=\"" << number(bar_x + 18) << "\" y=\"" << number(top + 10) << "\">" << label(largest)
      << "</text>\n"
      << "<text x=\"" << number(bar_x + 18) << "\" y=\"" << number(top + bar_height) << "\">0</text>\n"
      << "</svg>\n";
}

void write_dendrogram_svg(std::ostream& out, const persistence::Dendrogram& dendrogram,
                          const std::vector<std::string>& names, const std::string& title) {
  const std::size_t n = dendrogram.leaves;
  std::size_t longest = 1;
  for (const std::string& name : names)
    longest = std::max(longest, name.size());
  const double left = 60, top = 40, plot_height = 300, step = 40;
  const double plot_width = step * static_cast<double>(std::max<std::size_t>(n, 1));
  const double bottom = top + plot_height;
  double largest = 0;
  bool infinite = false;
  for (const persistence::Merge& m : dendrogram.merges) {
    if (std::isfinite(m.height))
      largest = std::max(largest, m.height);
    else
      infinite = true;
  }
  const double finite_top = infinite ? plot_height * 0.85 : plot_height;
  auto y_of = [&](double h) {
    if (std::isinf(h))
      return top;
    return bottom - (largest > 0 ? finite_top * h / largest : 0.0);
  };

  const std::vector<std::size_t> order = leaf_order(dendrogram);
  std::vector<double> x(n + dendrogram.merges.size()), y(n + dendrogram.merges.size(), bottom);
  for (std::size_t k = 0; k < order.size(); ++k)
    x[order[k]] = left + step * (static_cast<double>(k) + 0.5);

  svg_header(out, std::max(left + plot_width + 20, title_width(title)),
             bottom + 20 + 7.0 * static_cast<double>(longest));
  out << "<text x=\"4\" y=\"16\">" << xml_escape(title) << "</text>\n";
  for (std::size_t k = 0; k < dendrogram.merges.size(); ++k) {
    const persistence::Merge& m = dendrogram.merges[k];
    const std::size_t c = n + k;
    x[c] = (x[m.first] + x[m.second]) / 2;
    y[c] = y_of(m.height);
    out << "<path d=\"M" << number(x[m.first]) << "," << number(y[m.first]) << " V" << number(y[c]) << " H"
        << number(x[m.second]) << " V" << number(y[m.second]) << "\" fill=\"none\" stroke=\"#1f77b4\" "
        << "stroke-width=\"1.5\"><title>" << label(m.height) << "</title></path>\n";
  }
  for (std::size_t k = 0; k < order.size(); ++k)
    out << "<text transform=\"translate(" << number(x[order[k]] + 4) << "," << number(bottom + 6)
        << ") rotate(90)\">" << xml_escape(names[order[k]]) << "</text>\n";
  // Height axis.
  out << "<line x1=\"" << number(left - 10) << "\" y1=\"" << number(bottom) << "\" x2=\"" << number(left - 10)
      << "\" y2=\"" << number(bottom - finite_top) << "\" stroke=\"black\"/>\n"
      << "<text x=\"" << number(left - 14) << "\" y=\"" << number(bottom + 4)
      << "\" text-anchor=\"end\">0</text>\n"
      << "<text x=\"" << number(left - 14) << "\" y=\"" << number(bottom - finite_top + 4)
      << "\" text-anchor=\"end\">" << label(largest) << "</text>\n";
  if (infinite)
    out << "<text x=\"" << number(left - 14) << "\" y=\"" << number(top + 4)
        << "\" text-anchor=\"end\">inf</text>\n";
  out << "</svg>\n";
}

} // namespace medusa::cli
