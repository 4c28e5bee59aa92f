#include "medusa/io/vtk_reader.h"

#include "medusa/core/error.h"
#include "medusa/io/decimal.h"
#include "medusa/io/gzip_reader.h"
#include "periodic_centroid.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <optional>
#include <unordered_map>

namespace medusa::io {

namespace {

std::string lower(std::string s) {
  for (char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Size in bytes of an integer VTK data type in a BINARY legacy file, and whether it is signed;
// nullopt for non-integer types (ids and types must be integers).
struct IntType {
  std::size_t bytes;
  bool is_signed;
};
std::optional<IntType> integer_type(const std::string& name) {
  const std::string n = lower(name);
  if (n == "bit")
    return std::nullopt;
  if (n == "unsigned_char")
    return IntType{1, false};
  if (n == "char" || n == "signed_char")
    return IntType{1, true};
  if (n == "unsigned_short")
    return IntType{2, false};
  if (n == "short")
    return IntType{2, true};
  if (n == "unsigned_int")
    return IntType{4, false};
  if (n == "int")
    return IntType{4, true};
  if (n == "unsigned_long" || n == "vtktypeuint64")
    return IntType{8, false};
  if (n == "long" || n == "vtktypeint64" || n == "vtkidtype")
    return IntType{8, true};
  return std::nullopt;
}

bool mul_overflows(std::int64_t a, std::int64_t b, std::int64_t& r) {
  return __builtin_mul_overflow(a, b, &r);
}
bool add_overflows(std::int64_t a, std::int64_t b, std::int64_t& r) {
  return __builtin_add_overflow(a, b, &r);
}

class SnapshotParser {
public:
  SnapshotParser(const std::string& path, std::int64_t scale) : in_(path), scale_(scale) {
    snap_.path = path;
  }

  VtkSnapshot parse(const std::array<bool, 3>& periodic) {
    header();
    field_arrays();
    accumulate();
    if (periodic[0] || periodic[1] || periodic[2])
      periodic_centroids(snap_, ids_, periodic, scale_);
    return std::move(snap_);
  }

private:
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(in_.path() + ":" + std::to_string(in_.line()) + ": " + why);
  }

  std::string token(const char* what) {
    std::string_view t;
    if (!in_.next_token(t))
      throw InputError(in_.path() + ": file ends before " + what + " (truncated?)");
    return std::string(t);
  }

  std::int64_t integer(const char* what) {
    const std::string t = token(what);
    return parse_integer(t, in_.path() + ":" + std::to_string(in_.line()) + ": " + what);
  }

  std::int64_t decimal(const char* what) {
    const std::string t = token(what);
    return parse_scaled_decimal(t, scale_, in_.path() + ":" + std::to_string(in_.line()) + ": " + what);
  }

  void header() {
    std::string line;
    if (!in_.next_line(line) || line.rfind("# vtk DataFile Version", 0) != 0)
      fail("not a legacy VTK file (first line must start with '# vtk DataFile Version')");
    if (!in_.next_line(line))
      fail("file ends after the version line");
    if (!in_.next_line(line))
      fail("file ends before ASCII/BINARY");
    const std::string mode = lower(line.substr(0, line.find_last_not_of(" \t") + 1));
    if (mode != "ascii" && mode != "binary")
      fail("expected ASCII or BINARY, found '" + line + "'");
    snap_.binary = mode == "binary";
    if (lower(token("DATASET")) != "dataset" || lower(token("the dataset type")) != "structured_points")
      fail("only DATASET STRUCTURED_POINTS is supported (CompuCell3D lattice snapshots)");
    bool have_dims = false, have_spacing = false, have_origin = false;
    for (;;) {
      const std::string key = lower(token("POINT_DATA"));
      if (key == "dimensions") {
        for (auto& d : snap_.dimensions) {
          d = integer("DIMENSIONS");
          if (d <= 0)
            fail("DIMENSIONS must be positive, got " + std::to_string(d));
        }
        have_dims = true;
      } else if (key == "spacing" || key == "aspect_ratio") {
        for (auto& h : snap_.spacing) {
          h = decimal("SPACING");
          if (h <= 0)
            fail("SPACING must be positive");
        }
        have_spacing = true;
      } else if (key == "origin") {
        for (auto& g : snap_.origin)
          g = decimal("ORIGIN");
        have_origin = true;
      } else if (key == "point_data") {
        points_ = integer("POINT_DATA");
        break;
      } else {
        fail("unexpected '" + key + "' in the STRUCTURED_POINTS header (CELL_DATA is not supported)");
      }
    }
    if (!have_dims)
      fail("DIMENSIONS missing before POINT_DATA");
    if (!have_spacing)
      snap_.spacing = {scale_, scale_, scale_};
    if (!have_origin)
      snap_.origin = {0, 0, 0};
    // Bound each extent before multiplying, so the product cannot overflow (fuzz_vtk_reader).
    constexpr std::int64_t max_extent = 1 << 16;
    for (std::int64_t d : snap_.dimensions)
      if (d > max_extent)
        fail("DIMENSIONS " + std::to_string(d) + " exceeds the supported lattice extent " +
             std::to_string(max_extent));
    const std::int64_t expected = snap_.dimensions[0] * snap_.dimensions[1] * snap_.dimensions[2];
    if (points_ != expected)
      fail("POINT_DATA " + std::to_string(points_) + " does not match DIMENSIONS " +
           std::to_string(snap_.dimensions[0]) + " " + std::to_string(snap_.dimensions[1]) + " " +
           std::to_string(snap_.dimensions[2]) + " (" + std::to_string(expected) + " points)");
  }

  void field_arrays() {
    if (lower(token("FIELD")) != "field")
      fail("expected FIELD point data (CompuCell3D writes 'FIELD FieldData 3')");
    token("the FIELD name");
    const std::int64_t arrays = integer("the number of FIELD arrays");
    for (std::int64_t a = 0; a < arrays; ++a) {
      std::string name = token("a FIELD array");
      if (name == "METADATA") {
        skip_metadata();
        name = token("a FIELD array");
      }
      const std::int64_t components = integer("array components");
      const std::int64_t tuples = integer("array tuples");
      const std::string type = token("array type");
      if (tuples != points_)
        fail("array " + name + " has " + std::to_string(tuples) + " tuples but POINT_DATA is " +
             std::to_string(points_));
      // tuples x components values follow: refused before the product can overflow.
      if (components < 1 || (tuples > 0 && components > std::numeric_limits<std::int64_t>::max() / tuples))
        fail("array " + name + " has " + std::to_string(components) + " components per tuple");
      std::vector<std::int64_t>* target = name == "CellType" ? &types_ : name == "CellId" ? &ids_ : nullptr;
      const std::optional<IntType> itype = integer_type(type);
      if (target != nullptr && (!itype || components != 1))
        fail("array " + name + " must have 1 component of an integer type, found " +
             std::to_string(components) + " of " + type);
      values(name, tuples * components, itype, target);
    }
    std::string_view rest;
    if (in_.next_token(rest)) {
      if (rest != "METADATA")
        fail("unexpected '" + std::string(rest) + "' after the FIELD arrays (too many values?)");
      skip_metadata();
    }
    if (ids_.empty() && points_ > 0)
      throw InputError(in_.path() + ": no CellId array in the FIELD data");
    if (types_.empty() && points_ > 0)
      throw InputError(in_.path() + ": no CellType array in the FIELD data");
  }

  // VTK writes optional METADATA blocks after an array; they end at an empty line.
  void skip_metadata() {
    std::string line;
    in_.next_line(line); // rest of the METADATA line
    while (in_.next_line(line))
      if (line.find_first_not_of(" \t") == std::string::npos)
        return;
  }

  void values(const std::string& name, std::int64_t count, const std::optional<IntType>& itype,
              std::vector<std::int64_t>* target) {
    // Values are appended as they are read, never allocated from the header's count up front: a
    // header announcing 10^12 points in a tiny file must fail as truncated, not exhaust memory.
    if (target != nullptr) {
      target->clear();
      target->reserve(static_cast<std::size_t>(std::min<std::int64_t>(count, std::int64_t(1) << 20)));
    }
    if (snap_.binary) {
      if (!itype)
        fail("binary array " + name + " of a non-integer type cannot be skipped");
      // After the array header line the raw big-endian values start right after its newline.
      std::string rest;
      in_.next_line(rest);
      constexpr std::int64_t block = 1 << 16;
      std::vector<unsigned char> bytes;
      for (std::int64_t done = 0; done < count; done += block) {
        const std::int64_t n = std::min(block, count - done);
        bytes.resize(static_cast<std::size_t>(n) * itype->bytes);
        in_.read_bytes(reinterpret_cast<char*>(bytes.data()), bytes.size());
        if (target == nullptr)
          continue;
        for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
          std::uint64_t u = 0;
          for (std::size_t b = 0; b < itype->bytes; ++b)
            u = (u << 8) | bytes[k * itype->bytes + b];
          std::int64_t v = static_cast<std::int64_t>(u);
          if (itype->is_signed && itype->bytes < 8 && (u >> (8 * itype->bytes - 1)) != 0)
            v = static_cast<std::int64_t>(u) - (std::int64_t(1) << (8 * itype->bytes));
          if (!itype->is_signed && itype->bytes == 8 && v < 0)
            fail("array " + name + " value #" + std::to_string(done + static_cast<std::int64_t>(k)) +
                 " is out of range");
          target->push_back(v);
        }
      }
      return;
    }
    std::string_view t;
    for (std::int64_t k = 0; k < count; ++k) {
      if (!in_.next_token(t))
        throw InputError(in_.path() + ": array " + name + " has only " + std::to_string(k) + " of " +
                         std::to_string(count) + " values (file ends at line " + std::to_string(in_.line()) +
                         ")");
      std::int64_t v = 0;
      if (target != nullptr) {
        if (!try_parse_integer(t, v))
          fail("bad token '" + std::string(t) + "' in array " + name + " (value #" + std::to_string(k) +
               "; expected an integer)");
        target->push_back(v);
      }
    }
  }

  void accumulate() {
    struct Acc {
      VtkCell cell;
      std::array<std::int64_t, 3> index_sum{};
      std::int64_t first_voxel = 0;
    };
    std::unordered_map<std::int64_t, Acc> cells;
    // Plain variables, not a structured binding: clang 14 cannot capture bindings in lambdas.
    const std::int64_t nx = snap_.dimensions[0], ny = snap_.dimensions[1], nz = snap_.dimensions[2];
    const auto voxel = [&](std::int64_t p) {
      return "(" + std::to_string(p % nx) + "," + std::to_string((p / nx) % ny) + "," +
             std::to_string(p / (nx * ny)) + ")";
    };
    (void)nz;
    for (std::int64_t p = 0; p < points_; ++p) {
      const std::int64_t id = ids_[static_cast<std::size_t>(p)];
      const std::int64_t type = types_[static_cast<std::size_t>(p)];
      if (id < 0)
        throw InputError(in_.path() + ": negative cell id " + std::to_string(id) + " at voxel " + voxel(p));
      if (id == 0) {
        if (type != 0)
          throw InputError(in_.path() + ": voxel " + voxel(p) + " has cell id 0 (medium) but type " +
                           std::to_string(type));
        continue;
      }
      if (type <= 0 || type > 1000000)
        throw InputError(in_.path() + ": cell " + std::to_string(id) + " has type " + std::to_string(type) +
                         " at voxel " + voxel(p) + " (cells must have a type 1, 2, ...)");
      auto [it, fresh] = cells.try_emplace(id);
      Acc& acc = it->second;
      if (fresh) {
        acc.cell.id = id;
        acc.cell.type = static_cast<int>(type);
        acc.first_voxel = p;
      } else if (acc.cell.type != type) {
        throw InputError(in_.path() + ": cell " + std::to_string(id) + " has voxels of type " +
                         std::to_string(acc.cell.type) + " (at " + voxel(acc.first_voxel) + ") and type " +
                         std::to_string(type) + " (at " + voxel(p) + ")");
      }
      ++acc.cell.voxels;
      acc.index_sum[0] += p % nx;
      acc.index_sum[1] += (p / nx) % ny;
      acc.index_sum[2] += p / (nx * ny);
    }
    snap_.cells.reserve(cells.size());
    for (auto& [id, acc] : cells) {
      // X = n * S*g + S*h * sum(i): exact integer sums (docs/MATH.md §1.3).
      for (int a = 0; a < 3; ++a) {
        std::int64_t base = 0, offset = 0;
        if (mul_overflows(acc.cell.voxels, snap_.origin[a], base) ||
            mul_overflows(snap_.spacing[a], acc.index_sum[a], offset) ||
            add_overflows(base, offset, acc.cell.scaled_sum[a]))
          throw InputError(in_.path() + ": cell " + std::to_string(id) +
                           ": centroid sum overflows 64 bits at grid scale " + std::to_string(scale_));
      }
      snap_.cells.push_back(acc.cell);
    }
    std::sort(snap_.cells.begin(), snap_.cells.end(),
              [](const VtkCell& a, const VtkCell& b) { return a.id < b.id; });
  }

  GzipReader in_;
  std::int64_t scale_;
  VtkSnapshot snap_;
  std::int64_t points_ = 0;
  std::vector<std::int64_t> types_, ids_;
};

} // namespace

VtkSnapshot read_vtk_snapshot(const std::string& path, std::int64_t scale,
                              const std::array<bool, 3>& periodic) {
  scale_decimals(scale);
  return SnapshotParser(path, scale).parse(periodic);
}

bool is_vtk_step_name(const std::string& filename) {
  const std::string prefix = "Step_";
  std::size_t end = filename.size();
  if (filename.size() > 3 && filename.compare(end - 3, 3, ".gz") == 0)
    end -= 3;
  if (end < 4 || filename.compare(end - 4, 4, ".vtk") != 0)
    return false;
  end -= 4;
  if (filename.compare(0, prefix.size(), prefix) != 0 || end <= prefix.size())
    return false;
  for (std::size_t k = prefix.size(); k < end; ++k)
    if (filename[k] < '0' || filename[k] > '9')
      return false;
  return true;
}

std::int64_t vtk_step_mcs(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (!is_vtk_step_name(name))
    throw InputError(path + ": not a CompuCell3D snapshot name Step_<MCS>.vtk(.gz); cannot tell its MCS");
  const std::size_t underscore = name.find_last_of('_');
  const std::size_t dot = name.find(".vtk", underscore);
  return parse_integer(name.substr(underscore + 1, dot - underscore - 1), path);
}

} // namespace medusa::io
