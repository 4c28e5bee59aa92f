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

// The verdicts as plain HTML for a viewer without JavaScript (a mail client, a file preview), where
// report.js draws nothing: the answer must not depend on it.
void write_static_verdicts(std::ostream& out, const std::vector<ReportRun>& runs) {
  out << "<noscript>\n<div class=\"cards\">\n";
  for (const ReportRun& r : runs) {
    const std::string verdict = r.data.value("verdict", std::string());
    const std::size_t colon = verdict.find(':');
    const bool sorts = verdict.rfind("sorts", 0) == 0;
    out << "<div class=\"run-card\"><p class=\"verdict " << (sorts ? "sorts" : "no-sort") << "\"><b>"
        << xml_escape(r.name + " " + verdict.substr(0, colon)) << ":</b>"
        << xml_escape(colon == std::string::npos ? "" : verdict.substr(colon + 1)) << "</p>";
    for (const std::string& w : r.data.at("facts").value("input_warnings", std::vector<std::string>()))
      out << "<p class=\"input-warning\"><b>Input warning: </b>" << xml_escape(w) << "</p>";
    out << "</div>\n";
  }
  out << "</div>\n<p class=\"note\">JavaScript is off: the verdicts above and the pictures drawn in "
         "the page (radius sweeps, distances) show; the charts over time, the lines per type, the "
         "barcodes and the classes need JavaScript.</p>\n</noscript>\n";
}

} // namespace

void write_report_html(std::ostream& out, const std::vector<ReportRun>& runs,
                       const std::vector<ReportFigure>& comparison, const std::vector<ReportFigure>& crocker,
                       const nlohmann::ordered_json& sweeps, const nlohmann::ordered_json& scale) {
  std::string names;
  nlohmann::ordered_json data;
  data["version"] = medusa::version;
  data["runs"] = nlohmann::ordered_json::array();
  data["sweeps"] = sweeps;
  data["scale"] = scale;
  for (const ReportRun& r : runs) {
    names += (names.empty() ? "" : ", ") + r.name;
    data["runs"].push_back(r.data);
  }
  const std::string mixed = mixed_dimensions_note(runs);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<title>medusa report: " << xml_escape(names) << "</title>\n<style>\n"
      << report_css << report_classes_css << "</style>\n</head>\n<body>\n"
      << "<h1>medusa report</h1>\n<p class=\"sub\">" << xml_escape(names) << " · medusa " << medusa::version
      << "</p>\n"
      << "<section id=\"glance\">\n<h2>Did the cells sort, when, and at which radius?</h2>\n"
      << "<p class=\"criterion\">A <b>cluster</b> is a group of cells of one type linked to each other: two "
         "cells are linked when their balls of the radius overlap inside their Voronoi regions (about: "
         "centres at most twice the radius apart; docs/MATH.md §4.1). Clusters at a frame are those of the "
         "complex K_t at that frame (b0). A <b>join</b> is a cluster first touching another (the forward "
         "filtration, docs/MATH.md §7.6); times between frames come from linear interpolation of the cell "
         "centres. <b>Criterion</b> for &ldquo;sorts&rdquo;: a cell type that is in several clusters at the "
         "first frame is one cluster at every frame from some frame to the last; no other threshold "
         "enters. When no type gathers, the answer says how far each got: its clusters at the first and "
         "the last frame, and its heterotypic contacts. Under each type, the classical measures of the same "
         "complexes (docs/MATH.md §6.9): "
         "<b>heterotypic contacts</b>, the fraction of its links that join cells of different types, and "
         "<b>same-type neighbours</b>, the mean fraction of a cell's linked neighbours of its own type; "
         "sorting lowers the first and raises the second, whether or not a type ends in one cluster. "
         "The <b>largest cluster</b> says how many of the type's cells it holds: a type nearly one cluster "
         "at the first frame gathers with little sorting.</p>\n"
      << (mixed.empty() ? ""
                        : "<p class=\"note\" id=\"mixed-dimensions\">Note: " + xml_escape(mixed) + ".</p>\n")
      << "<div id=\"headlines\" class=\"cards\"></div>\n";
  write_static_verdicts(out, runs);
  out << "<div id=\"radius-answer\"></div>\n"
      << "<div id=\"glance-charts\" class=\"charts\"></div>\n";
  const bool explained = scale.contains("notes") && !scale["notes"].empty();
  if (crocker.empty() && explained)
    out << "<p class=\"note\">At which radius? No radius sweep is shown (the note above says why): these "
           "counts are at one radius.</p>\n";
  else if (crocker.empty())
    out << "<p class=\"note\">At which radius? No radius sweep was computed (<code>--no-sweep</code>, or on "
           "a periodic run no swept radius with 4 x radius below the shortest period, docs/MATH.md §8.3): "
           "these counts are at one radius. <code>medusa report</code> without <code>--no-sweep</code> (with "
           "<code>--sweep-radii</code> small enough for the period), or <code>medusa sweep RUN --radii "
           "2:4:0.25</code> in the folder of the store, adds the radii.</p>\n";
  out << "</section>\n";
  if (!crocker.empty()) {
    out << "<section id=\"crocker\">\n<h2>At which radius? CROCKER plots of the radius sweeps</h2>\n"
        << "<p class=\"note\">Each panel shows a Betti number b of K_t over time (x) and radius (y), as "
           "<code>medusa sweep</code> computes it (Topaz, Ziegelmeier &amp; Halverson 2015). Colour: log(1 + "
           "b), "
           "so that b = 0 has a colour too (the darkest; the legend is labelled in b). Sorting shows in b0 "
           "of the engulfed type as one cluster reached over time at radii where it was split at the start. "
           "Hover a cell for its value.</p>\n";
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
