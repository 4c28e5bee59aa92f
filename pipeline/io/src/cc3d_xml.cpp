#include "medusa/io/cc3d_xml.h"

#include "medusa/core/error.h"
#include "medusa/io/decimal.h"
#include "medusa/io/gzip_reader.h"

namespace medusa::io {

namespace {

std::string without_comments(std::string text) {
  for (std::size_t open = text.find("<!--"); open != std::string::npos; open = text.find("<!--", open)) {
    const std::size_t close = text.find("-->", open + 4);
    text.erase(open, close == std::string::npos ? std::string::npos : close + 3 - open);
  }
  return text;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Attribute text of every tag `<name ...>` (name followed by a blank, so <CellTypeX> is not <CellType>).
std::vector<std::string> tags(const std::string& text, const std::string& name) {
  std::vector<std::string> found;
  const std::string open = "<" + name;
  for (std::size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
    const std::size_t start = at + open.size();
    if (start >= text.size() || !is_blank(text[start]))
      continue;
    const std::size_t close = text.find('>', start);
    if (close == std::string::npos)
      break;
    found.push_back(text.substr(start, close - start));
  }
  return found;
}

// Value of attribute `name` in the attribute text of one tag, or "" if absent.
std::string attribute(const std::string& attributes, const std::string& name) {
  for (std::size_t at = attributes.find(name); at != std::string::npos; at = attributes.find(name, at + 1)) {
    if (at > 0 && !is_blank(attributes[at - 1]))
      continue;
    std::size_t k = at + name.size();
    while (k < attributes.size() && is_blank(attributes[k]))
      ++k;
    if (k >= attributes.size() || attributes[k] != '=')
      continue;
    ++k;
    while (k < attributes.size() && is_blank(attributes[k]))
      ++k;
    if (k >= attributes.size() || (attributes[k] != '"' && attributes[k] != '\''))
      continue;
    const std::size_t end = attributes.find(attributes[k], k + 1);
    if (end == std::string::npos)
      return {};
    return attributes.substr(k + 1, end - k - 1);
  }
  return {};
}

// Trimmed text between <name> and the next '<', or "" if the element is absent.
std::string element_text(const std::string& text, const std::string& name) {
  const std::string open = "<" + name + ">";
  const std::size_t at = text.find(open);
  if (at == std::string::npos)
    return {};
  std::size_t start = at + open.size();
  std::size_t end = text.find('<', start);
  if (end == std::string::npos)
    end = text.size();
  while (start < end && is_blank(text[start]))
    ++start;
  while (end > start && is_blank(text[end - 1]))
    --end;
  return text.substr(start, end - start);
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
  const std::vector<std::string> dimensions = tags(text, "Dimensions");
  if (dimensions.empty())
    throw NotASimulation(path + ": no <Dimensions x=\"..\" y=\"..\" z=\"..\"/> in the CC3DML file");
  // The boundary conditions are read from <Potts>; a file cut before its end (a copy interrupted,
  // a full disk) would silently read as open boundaries.
  if (text.find("</Potts>") == std::string::npos || text.find("</CompuCell3D>") == std::string::npos)
    throw InputError(path + ": the CC3DML file ends before </Potts> or </CompuCell3D> (cut off?), so its "
                            "boundary conditions cannot be read");
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const std::string v = attribute(dimensions.front(), axes[a]);
    // CC3D treats a missing dimension as 1.
    sim.dimensions[a] = v.empty() ? 1 : parse_integer(v, path + ": <Dimensions " + axes[a] + "=>");
    if (sim.dimensions[a] <= 0)
      throw InputError(path + ": <Dimensions> " + axes[a] + " must be positive");
    sim.periodic[a] = element_text(text, std::string("Boundary_") + axes[a]) == "Periodic";
  }
  if (const std::string steps = element_text(text, "Steps"); !steps.empty()) {
    sim.steps = parse_integer(steps, path + ": <Steps>");
    if (sim.steps <= 0)
      throw InputError(path + ": <Steps> must be positive, got " + steps);
  }
  for (const std::string& attrs : tags(text, "CellType")) {
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
