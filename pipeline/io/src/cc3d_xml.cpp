#include "medusa/io/cc3d_xml.h"

#include "medusa/io/decimal.h"
#include "medusa/io/gzip_reader.h"
#include "medusa/kinetic/error.h"

#include <regex>

namespace medusa::io {

namespace {

std::string without_comments(std::string text) {
  for (std::size_t open = text.find("<!--"); open != std::string::npos; open = text.find("<!--", open)) {
    const std::size_t close = text.find("-->", open + 4);
    text.erase(open, close == std::string::npos ? std::string::npos : close + 3 - open);
  }
  return text;
}

// Value of attribute `name` in the attribute text of one tag, or "" if absent.
std::string attribute(const std::string& attributes, const std::string& name) {
  const std::regex pattern("(^|\\s)" + name + "\\s*=\\s*[\"']([^\"']*)[\"']");
  std::smatch m;
  return std::regex_search(attributes, m, pattern) ? m[2].str() : std::string();
}

} // namespace

Cc3dSimulation read_cc3d_xml(const std::string& path) {
  GzipReader in(path);
  std::string text, line;
  while (in.next_line(line))
    text += line + "\n";
  text = without_comments(text);
  Cc3dSimulation sim;
  sim.path = path;
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(R"(<Dimensions\s([^>]*)>)")))
    throw InputError(path + ": no <Dimensions x=\"..\" y=\"..\" z=\"..\"/> in the CC3DML file");
  const std::string dims = m[1].str();
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const std::string v = attribute(dims, axes[a]);
    // CC3D treats a missing dimension as 1.
    sim.dimensions[a] = v.empty() ? 1 : parse_integer(v, path + ": <Dimensions " + axes[a] + "=>");
    if (sim.dimensions[a] <= 0)
      throw InputError(path + ": <Dimensions> " + axes[a] + " must be positive");
  }
  const std::regex boundary(R"(<Boundary_([xyz])>\s*([A-Za-z]+)\s*</Boundary_[xyz]>)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), boundary); it != std::sregex_iterator(); ++it)
    sim.periodic[(*it)[1].str()[0] - 'x'] = (*it)[2].str() == "Periodic";
  const std::regex cell_type(R"(<CellType\s([^>]*)>)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), cell_type); it != std::sregex_iterator();
       ++it) {
    const std::string attrs = (*it)[1].str();
    const std::string name = attribute(attrs, "TypeName"), id = attribute(attrs, "TypeId");
    if (name.empty() || id.empty())
      continue;
    const std::int64_t type = parse_integer(id, path + ": <CellType TypeId=>");
    if (type < 0 || type > 1000000)
      throw InputError(path + ": <CellType> TypeId " + id + " out of range");
    if (sim.type_names.size() <= static_cast<std::size_t>(type))
      sim.type_names.resize(static_cast<std::size_t>(type) + 1);
    sim.type_names[static_cast<std::size_t>(type)] = name;
  }
  return sim;
}

std::string periodic_axes(const Cc3dSimulation& sim) {
  std::string axes;
  for (int a = 0; a < 3; ++a)
    if (sim.periodic[a])
      axes += std::string(axes.empty() ? "" : ",") + char('x' + a);
  return axes;
}

} // namespace medusa::io
