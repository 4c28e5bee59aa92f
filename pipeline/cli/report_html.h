// The self-contained HTML page of `medusa report`: data as JSON, styles, and a small script that
// draws the charts, barcodes and diagrams as SVG in the browser (no network, no library).
#pragma once

#include "report_model.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// `sweeps`: per radius sweep, the Betti numbers of each type at the frames against the radius (see
// report_scale.h); `scale`: the runs compared over their common swept radii.
// Pictures made here and embedded as SVG: distances between runs, CROCKER plots.
struct ReportFigure {
  std::string title;
  std::vector<std::string> notes; // one paragraph each
  std::vector<std::string> svgs;  // standalone SVG documents
};

void write_report_html(std::ostream& out, const std::vector<ReportRun>& runs,
                       const std::vector<ReportFigure>& comparison, const std::vector<ReportFigure>& crocker,
                       const nlohmann::ordered_json& sweeps, const nlohmann::ordered_json& scale);

} // namespace medusa::cli
