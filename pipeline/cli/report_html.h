// The self-contained HTML page of `medusa report`: data as JSON, styles, and a small script that
// draws the charts, barcodes and diagrams as SVG in the browser (no network, no library).
#pragma once

#include "report_model.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// `sweeps`: per sweep found next to the stores, b0 of each type at the first and last frames against
// the radius ({name, t0, t_end, radii, types: [{label, first, last}]}), drawn as one chart per type.
// Pictures made here and embedded as SVG: distances between runs, CROCKER plots.
struct ReportFigure {
  std::string title;
  std::vector<std::string> notes; // one paragraph each
  std::vector<std::string> svgs;  // standalone SVG documents
};

void write_report_html(std::ostream& out, const std::vector<ReportRun>& runs,
                       const std::vector<ReportFigure>& comparison, const std::vector<ReportFigure>& crocker,
                       const nlohmann::ordered_json& sweeps);

} // namespace medusa::cli
