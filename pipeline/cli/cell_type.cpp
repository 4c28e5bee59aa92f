#include "cell_type.h"

#include "medusa/core/error.h"
#include "medusa/persistence/filtration.h"

#include <algorithm>
#include <cctype>
#include <optional>

namespace medusa::cli {
namespace {

std::optional<int> parse_id(const std::string& text) {
  if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  return std::stoi(text);
}

bool same_ignoring_case(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// The id whose name is `text`: an exact match first, then the one case-blind match, if unique.
std::optional<int> id_named(const std::string& text, const kinetic::Trajectories& input) {
  const auto& names = input.type_names;
  if (const auto it = std::find(names.begin(), names.end(), text); it != names.end())
    return static_cast<int>(it - names.begin());
  std::optional<int> found;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!names[i].empty() && same_ignoring_case(names[i], text)) {
      if (found)
        return std::nullopt;
      found = static_cast<int>(i);
    }
  return found;
}

} // namespace

std::string cell_type_name(const TypeNames& names, int type) {
  const auto i = static_cast<std::size_t>(type);
  return type >= 0 && i < names.size() ? names[i] : std::string();
}

std::string cell_type_name(const kinetic::Trajectories& input, int type) {
  return cell_type_name(input.type_names, type);
}

std::string cell_type_title(const TypeNames& names, int type) {
  const std::string name = cell_type_name(names, type);
  return "type " + std::to_string(type) + (name.empty() ? "" : " (" + name + ")");
}

std::string cell_type_title(const kinetic::Trajectories& input, int type) {
  return cell_type_title(input.type_names, type);
}

std::string type_label_title(const TypeNames& names, const std::string& label) {
  return label == "all" ? std::string("all cells") : cell_type_title(names, std::stoi(label));
}

std::string type_label_name(const TypeNames& names, const std::string& label) {
  return label == "all" ? std::string() : cell_type_name(names, std::stoi(label));
}

std::vector<int> cell_types(const kinetic::Trajectories& input) {
  std::vector<int> types;
  types.reserve(input.cells.size());
  for (const kinetic::Trajectory& t : input.cells)
    types.push_back(t.type);
  std::sort(types.begin(), types.end());
  types.erase(std::unique(types.begin(), types.end()), types.end());
  return types;
}

std::string cell_type_list(const kinetic::Trajectories& input) {
  std::string out;
  for (int type : cell_types(input)) {
    out += (out.empty() ? "" : ", ") + std::to_string(type);
    if (const std::string name = cell_type_name(input, type); !name.empty())
      out += " (" + name + ")";
  }
  return out.empty() ? "none" : out;
}

int resolve_cell_type(const std::string& text, const kinetic::Trajectories& input, const std::string& source,
                      bool allow_all) {
  if (allow_all && text == "all")
    return persistence::all_types;
  const std::optional<int> id = parse_id(text);
  const std::optional<int> named = id ? id : id_named(text, input);
  if (!named)
    throw InputError("no cell type is named '" + text + "' in " + source + "; its cell types are " +
                     cell_type_list(input));
  const std::vector<int> present = cell_types(input);
  if (!std::binary_search(present.begin(), present.end(), *named)) {
    const std::string name = cell_type_name(input, *named);
    throw InputError("cell type " + (id ? text : text + " (" + std::to_string(*named) + ")") +
                     (id && !name.empty() ? " (" + name + ")" : "") + " has no cells in " + source +
                     "; its cell types are " + cell_type_list(input));
  }
  return *named;
}

} // namespace medusa::cli
