#include "report_html.h"

#include "matrix_svg.h"
#include "report_assets.h"

#include "medusa/core/version.h"

#include <string>

namespace medusa::cli {
namespace {

// A standalone SVG document without its XML declaration, to sit inside the HTML body.
std::string inline_svg(const std::string& svg) {
  const std::size_t start = svg.find("<svg");
  return start == std::string::npos ? svg : svg.substr(start);
}

// JSON inside <script>: "</" would end the element early.
std::string script_safe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    out += json[i];
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/')
      out += "\\";
  }
  return out;
}

void write_figures(std::ostream& out, const std::vector<ReportFigure>& figures, const std::string& kind) {
  for (const ReportFigure& f : figures) {
    out << "<div class=\"figure " << kind << "\">\n<h3>" << xml_escape(f.title) << "</h3>\n";
    for (const std::string& note : f.notes)
      out << "<p class=\"note\">" << xml_escape(note) << "</p>\n";
    out << "<div class=\"pictures\">\n";
    for (const std::string& svg : f.svgs)
      out << inline_svg(svg) << "\n";
    out << "</div>\n</div>\n";
  }
}

} // namespace

void write_report_html(std::ostream& out, const std::vector<ReportRun>& runs,
                       const std::vector<ReportFigure>& comparison, const std::vector<ReportFigure>& crocker,
                       const nlohmann::ordered_json& sweeps) {
  std::string names;
  nlohmann::ordered_json data;
  data["version"] = medusa::version;
  data["runs"] = nlohmann::ordered_json::array();
  data["sweeps"] = sweeps;
  for (const ReportRun& r : runs) {
    names += (names.empty() ? "" : ", ") + r.name;
    data["runs"].push_back(r.data);
  }
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<title>medusa report: " << xml_escape(names) << "</title>\n<style>\n"
      << report_css << report_classes_css << "</style>\n</head>\n<body>\n"
      << "<h1>medusa report</h1>\n<p class=\"sub\">" << xml_escape(names) << " · medusa " << medusa::version
      << "</p>\n"
      << "<section id=\"glance\">\n<h2>"
      << (sweeps.empty() ? "Did the cells sort, and when?" : "Did the cells sort, when, and at which scale?")
      << "</h2>\n"
      << "<p class=\"note\">A cluster is a group of cells of one type linked to each other: two cells are "
         "linked "
         "when their balls of the radius overlap inside their Voronoi regions (about: centres at most twice "
         "the radius apart; docs/MATH.md §4.1). Sorting shows as the clusters of the engulfed type merging "
         "into "
         "one body early in the run. The counts at the first and last frames are those of the complex K_t at "
         "that time; the merges are those of the forward filtration (docs/MATH.md §7.6): a merge is when two "
         "clusters first touched.</p>\n"
      << "<div id=\"headlines\" class=\"cards\"></div>\n<div id=\"glance-charts\" class=\"charts\"></div>\n";
  if (sweeps.empty())
    out << "<p class=\"note\">At which scale? These counts are at one radius. <code>medusa sweep RUN --radii "
           "2:4:0.5</code> in the folder of the store (it writes &lt;run-name&gt;.crocker.csv) and this "
           "report "
           "again add the radii at which each type is one cluster, at the start and at the end.</p>\n";
  out << "</section>\n";
  if (!crocker.empty()) {
    out << "<section id=\"crocker\">\n<h2>At which scale? CROCKER plots of the radius sweeps</h2>\n"
        << "<p class=\"note\">Each panel shows a Betti number of K_t (colour, log scale) over time (x) and "
           "radius (y), from <code>medusa sweep</code> (Topaz, Ziegelmeier &amp; Halverson 2015). Sorting "
           "shows in b0 of the engulfed type as one cluster reached over time at radii where it was "
           "split at the start. Hover a cell for its value. The charts of the clusters against the radius on "
           "the "
           "first screen read off the scale: the clusters of each type at the first frame (dashed) and at "
           "the "
           "last frame (solid).</p>\n";
    write_figures(out, crocker, "crocker-figure");
    out << "</section>\n";
  }
  if (!comparison.empty()) {
    out << "<section id=\"comparison\">\n<h2>How different are the runs?</h2>\n";
    write_figures(out, comparison, "comparison-figure");
    out << "</section>\n";
  }
  out << "<div id=\"details\"></div>\n<div id=\"tooltip\" role=\"tooltip\"></div>\n"
      << "<script type=\"application/json\" id=\"report-data\">"
      << script_safe(data.dump(-1, ' ', true, nlohmann::ordered_json::error_handler_t::replace))
      << "</script>\n<script>\n"
      << report_js << "</script>\n<script>\n"
      << three_js << "\n</script>\n<script>\n"
      << three_orbit_controls_js << "\n</script>\n<script>\n"
      << report_classes_js << "</script>\n</body>\n</html>\n";
}

} // namespace medusa::cli
