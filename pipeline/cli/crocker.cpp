#include "crocker.h"

#include "diagram_export.h"
#include "matrix_svg.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace medusa::cli {
namespace {

// Radii are decimal text; they are ordered by value (a double suffices to order the few radii of a
// sweep, and nothing topological depends on it).
bool radius_less(const std::string& a, const std::string& b) { return std::stod(a) < std::stod(b); }

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

// A perceptually ordered ramp (viridis at five stops), s in [0, 1].
std::string ramp(double s) {
  static const double stops[5][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  s = std::clamp(s, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(s));
  const double f = s - i;
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x",
                static_cast<int>(std::lround(stops[i][0] + f * (stops[i + 1][0] - stops[i][0]))),
                static_cast<int>(std::lround(stops[i][1] + f * (stops[i + 1][1] - stops[i][1]))),
                static_cast<int>(std::lround(stops[i][2] + f * (stops[i + 1][2] - stops[i][2]))));
  return buffer;
}

// Betti numbers span 0 to hundreds at small radii; a log scale keeps 1, 2, 3 apart.
double scaled(std::size_t value, std::size_t max) {
  return max == 0 ? 0.0 : std::log1p(static_cast<double>(value)) / std::log1p(static_cast<double>(max));
}

// About five ticks at round values (1, 2 or 5 times a power of ten apart) from t0 to t1.
std::vector<double> round_ticks(double t0, double t1) {
  if (!(t1 > t0))
    return {t0};
  const double raw = (t1 - t0) / 5, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * magnitude;
  for (const double m : {1.0, 2.0, 5.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  std::vector<double> ticks;
  for (double k = std::ceil(t0 / step); k * step <= t1 + 1e-9 * step; k += 1)
    ticks.push_back(k * step);
  return ticks;
}

} // namespace

void write_crocker_csv(std::ostream& out, const std::vector<CrockerRow>& rows) {
  out << "radius,time,type,b0,b1,b2\n";
  for (const CrockerRow& r : rows)
    out << r.radius << ',' << format_time(r.time) << ',' << r.type << ',' << r.betti[0] << ',' << r.betti[1]
        << ',' << r.betti[2] << '\n';
}

std::vector<CrockerRow> read_crocker_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError("cannot read " + path);
  std::string line;
  std::size_t number_of_line = 1;
  if (!std::getline(in, line) || line != "radius,time,type,b0,b1,b2")
    throw InputError(path + ": line 1 is not the header radius,time,type,b0,b1,b2");
  std::vector<CrockerRow> rows;
  while (std::getline(in, line)) {
    ++number_of_line;
    if (line.empty())
      continue;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');)
      fields.push_back(f);
    try {
      if (fields.size() != 6)
        throw std::invalid_argument("fields");
      CrockerRow r;
      r.radius = fields[0];
      (void)std::stod(r.radius);
      r.time = std::stod(fields[1]);
      r.type = fields[2];
      for (std::size_t k = 0; k < 3; ++k) {
        if (fields[3 + k].empty() || fields[3 + k].find_first_not_of("0123456789") != std::string::npos)
          throw std::invalid_argument("betti");
        r.betti[k] = std::stoull(fields[3 + k]);
      }
      rows.push_back(std::move(r));
    } catch (const std::exception&) {
      throw InputError(path + ": line " + std::to_string(number_of_line) +
                       " is not radius,time,type,b0,b1,b2: " + line);
    }
  }
  if (rows.empty())
    throw InputError(path + ": no rows");
  return rows;
}

void write_crocker_svg(std::ostream& out, const std::vector<CrockerRow>& rows, const std::string& title,
                       int max_degree) {
  std::vector<std::string> types, radii;
  std::vector<double> times;
  for (const CrockerRow& r : rows) {
    if (std::find(types.begin(), types.end(), r.type) == types.end())
      types.push_back(r.type);
    if (std::find(radii.begin(), radii.end(), r.radius) == radii.end())
      radii.push_back(r.radius);
    times.push_back(r.time);
  }
  std::sort(radii.begin(), radii.end(), radius_less);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::map<std::tuple<std::string, std::string, double>, const CrockerRow*> at;
  for (const CrockerRow& r : rows)
    at[{r.type, r.radius, r.time}] = &r;

  const int degrees = max_degree + 1;
  const double panel_w = 300, panel_h = std::clamp(16.0 * radii.size(), 80.0, 240.0);
  const double left = 60, top = 50, gap_x = 110, gap_y = 70;
  const double width = left + degrees * (panel_w + gap_x);
  const double height = top + types.size() * (panel_h + gap_y) + 10;
  const double t0 = times.empty() ? 0 : times.front(), t1 = times.empty() ? 1 : times.back();
  // A frame's column runs to the next frame; the last one as wide as the one before it.
  auto column_end = [&](std::size_t i) {
    return i + 1 < times.size() ? times[i + 1]
                                : (times.size() > 1 ? 2 * times[i] - times[i - 1] : times[i] + 1);
  };
  const double span = times.empty() ? 1 : column_end(times.size() - 1) - t0;
  const char* const names[] = {"b0 (clusters)", "b1 (loops)", "b2 (cavities)"};

  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"crocker\" width=\"" << width << "\" height=\""
      << height << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" << xml_escape(title)
      << "</text>\n";
  for (std::size_t ti = 0; ti < types.size(); ++ti)
    for (int k = 0; k < degrees; ++k) {
      const double x0 = left + k * (panel_w + gap_x), y0 = top + ti * (panel_h + gap_y);
      std::size_t max = 0;
      for (const CrockerRow& r : rows)
        if (r.type == types[ti])
          max = std::max(max, r.betti[static_cast<std::size_t>(k)]);
      out << "<g class=\"crocker-panel\" shape-rendering=\"crispEdges\" data-type=\"" << xml_escape(types[ti])
          << "\" data-degree=\"" << k << "\">\n<text x=\"" << x0 << "\" y=\"" << y0 - 8
          << "\" font-weight=\"bold\">"
          << (types[ti] == "all" ? "all cells" : "type " + xml_escape(types[ti])) << ": " << names[k]
          << "</text>\n";
      const double row_h = panel_h / std::max<std::size_t>(1, radii.size());
      for (std::size_t ri = 0; ri < radii.size(); ++ri) {
        // Largest radius on top, like a y axis.
        const double y = y0 + (radii.size() - 1 - ri) * row_h;
        for (std::size_t i = 0; i < times.size(); ++i) {
          const auto it = at.find({types[ti], radii[ri], times[i]});
          const double x = x0 + (times[i] - t0) / span * panel_w;
          const double w = (column_end(i) - times[i]) / span * panel_w;
          if (it == at.end()) {
            out << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << w << "\" height=\"" << row_h
                << "\" fill=\"#ddd\"><title>radius " << radii[ri] << ", MCS " << number(times[i])
                << ": no value</title></rect>\n";
            continue;
          }
          const std::size_t v = it->second->betti[static_cast<std::size_t>(k)];
          out << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << w + 0.3 << "\" height=\""
              << row_h + 0.3 << "\" fill=\"" << ramp(scaled(v, max)) << "\"><title>radius " << radii[ri]
              << ", MCS " << number(times[i]) << ": b" << k << " = " << v << "</title></rect>\n";
        }
        // Radius labels: every one when they fit, else about ten.
        const std::size_t every = std::max<std::size_t>(1, radii.size() / 10);
        if (ri % every == 0 || ri + 1 == radii.size())
          out << "<text x=\"" << x0 - 4 << "\" y=\"" << y + row_h / 2 + 4 << "\" text-anchor=\"end\">"
              << radii[ri] << "</text>\n";
      }
      out << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << panel_w << "\" height=\"" << panel_h
          << "\" fill=\"none\" stroke=\"#333\"/>\n";
      for (const double t : round_ticks(t0, t1)) {
        const double x = x0 + (t - t0) / span * panel_w;
        out << "<line x1=\"" << x << "\" x2=\"" << x << "\" y1=\"" << y0 + panel_h << "\" y2=\""
            << y0 + panel_h + 4 << "\" stroke=\"#333\"/><text x=\"" << x << "\" y=\"" << y0 + panel_h + 16
            << "\" text-anchor=\"middle\">" << number(t) << "</text>\n";
      }
      out << "<text x=\"" << x0 + panel_w / 2 << "\" y=\"" << y0 + panel_h + 30
          << "\" text-anchor=\"middle\">MCS</text>\n"
          << "<text transform=\"translate(" << x0 - 40 << ',' << y0 + panel_h / 2
          << ") rotate(-90)\" text-anchor=\"middle\">radius</text>\n";
      // Colour legend: the ramp with the values at its ends and middle (log scale).
      const double lx = x0 + panel_w + 12, lw = 12;
      for (int s = 0; s < 32; ++s)
        out << "<rect x=\"" << lx << "\" y=\"" << y0 + panel_h * (1 - (s + 1) / 32.0) << "\" width=\"" << lw
            << "\" height=\"" << panel_h / 32.0 + 0.3 << "\" fill=\"" << ramp(s / 31.0) << "\"/>\n";
      const std::size_t mid =
          max == 0 ? 0 : static_cast<std::size_t>(std::lround(std::expm1(std::log1p(max) / 2)));
      for (const std::size_t v : {std::size_t{0}, mid, max}) {
        const double y = y0 + panel_h * (1 - scaled(v, max));
        out << "<text x=\"" << lx + lw + 4 << "\" y=\"" << y + 4 << "\">" << v << "</text>\n";
      }
      out << "<text x=\"" << lx << "\" y=\"" << y0 + panel_h + 16
          << "\" font-size=\"9\">log(1 + b)</text>\n</g>\n";
    }
  out << "</svg>\n";
}

} // namespace medusa::cli
