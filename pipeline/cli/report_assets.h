// The styles and script of the report page (pipeline/cli/report/report.css and report.js), compiled in
// so that the page is one file with nothing to fetch.
#pragma once

namespace medusa::cli {

extern const char* const report_css;
extern const char* const report_js;

} // namespace medusa::cli
