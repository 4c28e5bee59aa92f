#include "medusa/io/csv_reader.h"

#include "medusa/core/error.h"
#include "medusa/io/decimal.h"
#include "medusa/io/excerpt.h"
#include "medusa/io/gzip_reader.h"

#include <map>
#include <optional>
#include <string_view>
#include <unordered_map>

namespace medusa::io {

namespace {

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos)
      return fields;
    start = comma + 1;
  }
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

bool blank(std::string_view s) { return trim(s).empty(); }

struct PairHash {
  std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& p) const {
    // Unsigned arithmetic: a large MCS must not overflow (found by fuzz_csv_reader).
    return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(p.first) * 1000003u ^
                                      static_cast<std::uint64_t>(p.second));
  }
};

} // namespace

CsvContents read_csv(const std::string& path, const CsvOptions& options) {
  scale_decimals(options.scale);
  GzipReader in(path);
  CsvContents out;
  out.rounding.snapped = options.round;
  std::string line;
  if (!in.next_line(line))
    throw InputError(path + ": empty file (expected a header line)");
  // A UTF-8 byte order mark (spreadsheet exports write one) is not part of the first column's name.
  if (line.rfind("\xEF\xBB\xBF", 0) == 0)
    line.erase(0, 3);
  const std::vector<std::string_view> header = split_commas(line);
  const auto column = [&](const std::string& name) -> std::optional<std::size_t> {
    if (name.empty())
      return std::nullopt;
    for (std::size_t k = 0; k < header.size(); ++k)
      if (trim(header[k]) == name)
        return k;
    return std::nullopt;
  };
  const CsvColumns& c = options.columns;
  // Every missing required column at once, so that a hand-written file is fixed in one go.
  std::string missing;
  std::size_t n_missing = 0;
  for (const std::string* name : {&c.mcs, &c.cell_id, &c.type, &c.x, &c.y, &c.z})
    if (!column(*name)) {
      missing += (missing.empty() ? "'" : ", '") + *name + "'";
      ++n_missing;
    }
  // A planar run's export often has no third coordinate: all z equal reads as planar (docs/MATH.md §5.7).
  const bool only_z = n_missing == 1 && !column(c.z);
  if (n_missing > 0)
    throw InputError(path + ":" + std::to_string(in.line()) + ": missing column" +
                     (n_missing > 1 ? "s " : " ") + missing + " in header '" + excerpt(line) +
                     "' (required: " + c.mcs + ", " + c.cell_id + ", " + c.type + ", " + c.x + ", " + c.y +
                     ", " + c.z + "; optional: " + c.volume + ", " + c.type_name + ")" +
                     (only_z ? "; for a planar run add a column " + c.z + " of 0 on every row" : ""));
  const std::size_t col_mcs = *column(c.mcs), col_id = *column(c.cell_id), col_type = *column(c.type);
  const std::size_t col_xyz[3] = {*column(c.x), *column(c.y), *column(c.z)};
  const std::optional<std::size_t> col_volume = column(c.volume), col_name = column(c.type_name);
  const std::vector<std::string> column_names = {c.x, c.y, c.z};
  out.has_volume = col_volume.has_value();
  const std::size_t n_fields = header.size();

  std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::int64_t, PairHash> seen; // (mcs,id) -> line
  std::unordered_map<std::int64_t, std::pair<int, std::int64_t>> cell_type; // id -> (type, line)
  std::map<int, std::pair<std::string, std::int64_t>> type_name;            // type -> (name, line)

  while (in.next_line(line)) {
    if (blank(line))
      continue;
    const std::string at = path + ":" + std::to_string(in.line());
    const std::vector<std::string_view> f = split_commas(line);
    // A row's errors name its line, and its MCS and cell where they read: the frame and the cell a user
    // looks for in the simulation.
    std::int64_t row_mcs = 0, row_id = 0;
    const bool has_mcs = f.size() > col_mcs && try_parse_integer(f[col_mcs], row_mcs);
    const bool has_id = f.size() > col_id && try_parse_integer(f[col_id], row_id);
    const std::string cell = at + (has_mcs || has_id ? ": " : "") +
                             (has_mcs ? "MCS " + std::to_string(row_mcs) + (has_id ? ", " : "") : "") +
                             (has_id ? "cell " + std::to_string(row_id) : "");
    if (f.size() != n_fields)
      throw InputError(cell + ": expected " + std::to_string(n_fields) + " fields as in the header, found " +
                       std::to_string(f.size()));
    CellSample s;
    s.line = in.line();
    s.cell_id = parse_integer(f[col_id], cell + ": column " + c.cell_id);
    if (s.cell_id <= 0)
      throw InputError(cell + ": cell ids must be positive (medium has no row)");
    s.mcs = parse_integer(f[col_mcs], cell + ": column " + c.mcs);
    const std::int64_t type = parse_integer(f[col_type], cell + ": column " + c.type);
    if (type <= 0 || type > 1000000)
      throw InputError(cell + ": type " + std::to_string(type) + " is not a cell type (must be 1, 2, ...)");
    s.type = static_cast<int>(type);
    bool rounded = false;
    for (int a = 0; a < 3; ++a) {
      const GridDecimal x = read_grid_decimal(f[col_xyz[a]], options.scale, options.round);
      if (x.problem == GridDecimal::Problem::too_many_decimals)
        throw InputError(cell + ": column " + column_names[a] + ": " +
                         grid_decimal_problem(x, f[col_xyz[a]], options.scale) + "; " + options.round_option +
                         " rounds the centres to the grid (recorded in the store)");
      if (x.problem != GridDecimal::Problem::none)
        throw InputError(cell + ": column " + column_names[a] + ": " +
                         grid_decimal_problem(x, f[col_xyz[a]], options.scale));
      s.position[a] = x.value;
      if (x.rounded) {
        rounded = true;
        out.rounding.widen(x.offset_num, x.offset_den);
      }
    }
    if (options.round) {
      ++out.rounding.positions;
      out.rounding.moved += rounded ? 1 : 0;
    }
    if (col_volume) {
      s.volume = parse_integer(f[*col_volume], cell + ": column " + c.volume);
      if (s.volume < 0)
        throw InputError(cell + ": negative volume " + std::to_string(s.volume));
    }
    const auto [dup, fresh] = seen.emplace(std::make_pair(s.mcs, s.cell_id), s.line);
    if (!fresh)
      throw InputError(cell + ": duplicate row for MCS " + std::to_string(s.mcs) + " (first at line " +
                       std::to_string(dup->second) + ")");
    const auto [known, new_cell] = cell_type.emplace(s.cell_id, std::make_pair(s.type, s.line));
    if (!new_cell && known->second.first != s.type)
      throw InputError(cell + ": type changes from " + std::to_string(known->second.first) + " (line " +
                       std::to_string(known->second.second) + ") to " + std::to_string(s.type));
    if (col_name) {
      const std::string name(trim(f[*col_name]));
      const auto [named, new_type] = type_name.emplace(s.type, std::make_pair(name, s.line));
      if (!new_type && named->second.first != name)
        throw InputError(cell + ": type " + std::to_string(s.type) + " is named '" + excerpt(name) +
                         "' but '" + excerpt(named->second.first) + "' at line " +
                         std::to_string(named->second.second));
    }
    out.samples.push_back(s);
  }
  if (out.samples.empty())
    throw InputError(path + ": no data rows after the header");
  for (const auto& [type, name] : type_name) {
    if (out.type_names.size() <= static_cast<std::size_t>(type))
      out.type_names.resize(type + 1);
    out.type_names[type] = name.first;
  }
  return out;
}

} // namespace medusa::io
