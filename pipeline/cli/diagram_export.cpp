#include "diagram_export.h"

#include "diagram_selection.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>

namespace medusa::cli {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (const char c : text)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string format_time(double t) {
  if (std::isinf(t))
    return t > 0 ? "inf" : "-inf";
  // The shortest text that reads back as t: 349.9, not 349.89999999999998; -0 (a time typed as "-0")
  // is MCS 0.
  char buffer[64];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, t == 0 ? 0.0 : t);
  return std::string(buffer, r.ptr);
}

void write_pairs_text(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
                      const TypeNames& names) {
  for (const persistence::Diagram& d : diagrams) {
    out << "# " << (d.cell_type == persistence::all_types ? "type all" : cell_type_title(names, d.cell_type))
        << ", " << direction_name(d.direction) << ", " << d.pairs.size() << " pairs (birth death dim)\n";
    for (const persistence::PersistencePair& p : d.pairs)
      out << format_time(p.birth) << ' ' << format_time(p.death) << ' ' << p.dim << '\n';
  }
}

void write_pers(std::ostream& out, const std::vector<persistence::Diagram>& diagrams) {
  for (const persistence::Diagram& d : diagrams)
    for (const persistence::PersistencePair& p : d.pairs)
      out << p.dim << ' ' << format_time(p.birth) << ' ' << format_time(p.death) << '\n';
}

void write_csv(std::ostream& out, const std::vector<persistence::Diagram>& diagrams, const TypeNames& names,
               const std::string& run_id) {
  if (!run_id.empty())
    out << "# medusa run " << run_id << "\n";
  out << "birth,death,dimension,type,direction,type_name\n";
  for (const persistence::Diagram& d : diagrams) {
    const std::string name = csv_field(type_label_name(names, type_label(d.cell_type)));
    for (const persistence::PersistencePair& p : d.pairs)
      out << format_time(p.birth) << ',' << format_time(p.death) << ',' << p.dim << ','
          << type_label(d.cell_type) << ',' << direction_name(d.direction) << ',' << name << '\n';
  }
}

void write_json(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
                const TypeNames& names) {
  nlohmann::json list = nlohmann::json::array();
  for (const persistence::Diagram& d : diagrams) {
    nlohmann::json pairs = nlohmann::json::array();
    for (const persistence::PersistencePair& p : d.pairs) {
      nlohmann::json death =
          std::isinf(p.death) ? nlohmann::json(format_time(p.death)) : nlohmann::json(p.death);
      pairs.push_back({{"dimension", p.dim}, {"birth", p.birth}, {"death", death}});
    }
    list.push_back({{"type", type_label(d.cell_type)},
                    {"type_name", type_label_name(names, type_label(d.cell_type))},
                    {"direction", direction_name(d.direction)},
                    {"pairs", pairs}});
  }
  out << nlohmann::json{{"diagrams", list}}.dump(1) << '\n';
}

} // namespace medusa::cli
