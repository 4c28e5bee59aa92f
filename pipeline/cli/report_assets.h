// The styles and script of the report page (pipeline/cli/report/report.css and report.js), compiled in
// so that the page is one file with nothing to fetch.
#pragma once

namespace medusa::cli {

extern const char* const report_css;
extern const char* const report_js;

// The classes section's 3D view (pipeline/cli/report/classes3d.css, classes3d.js), and three.js with
// its orbit controls from Debian's libjs-three, which it draws with.
extern const char* const report_classes_css;
extern const char* const report_classes_js;
extern const char* const three_js;
extern const char* const three_orbit_controls_js;

} // namespace medusa::cli
