#include "python_store.h"
#include "cell_type.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/class_winding.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/filtration.h"

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <charconv>

namespace medusa::python {
namespace {

// The shortest decimal that reads back as t: 1000, not 1000.000000.
std::string shortest(double t) {
  std::array<char, 32> buffer{};
  const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), t).ptr;
  return std::string(buffer.data(), end);
}

std::pair<int, int> key_of(persistence::Direction direction, int cell_type) {
  return {static_cast<int>(direction), cell_type};
}

// Whether the store has a /persistence group (read_diagrams throws when it has none).
bool has_persistence_group(const std::string& path) {
  H5E_auto2_t func = nullptr;
  void* data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  bool found = false;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file >= 0) {
    found = H5Lexists(file, "persistence", H5P_DEFAULT) > 0;
    H5Fclose(file);
  }
  H5Eset_auto2(H5E_DEFAULT, func, data);
  return found;
}

} // namespace

StoreView::StoreView(std::string path) : path_(std::move(path)), medusa_(medusa::read_store(path_)) {}

std::vector<int> StoreView::types() const { return cli::cell_types(medusa_.input); }

void StoreView::check_type(int cell_type) const {
  const std::vector<int> all = types();
  if (cell_type != persistence::all_types && std::find(all.begin(), all.end(), cell_type) == all.end())
    throw InputError("cell type " + std::to_string(cell_type) + " has no cells in " + path_ +
                     "; its cell types are " + cli::cell_type_list(medusa_.input));
}

const persistence::Diagram& StoreView::diagram(persistence::Direction direction, int cell_type) {
  check_type(cell_type);
  if (!stored_read_) {
    stored_read_ = true;
    if (has_persistence_group(path_))
      for (persistence::Diagram& d : persistence::read_diagrams(path_))
        diagrams_.emplace(key_of(d.direction, d.cell_type), std::move(d));
  }
  const auto key = key_of(direction, cell_type);
  if (const auto it = diagrams_.find(key); it != diagrams_.end())
    return it->second;
  std::vector<int> vertex_type;
  for (const kinetic::Trajectory& t : medusa_.input.cells)
    vertex_type.push_back(t.type);
  const persistence::Filtration f =
      cell_type == persistence::all_types
          ? persistence::make_filtration(medusa_.cells, direction)
          : persistence::make_type_filtration(medusa_.cells, vertex_type, cell_type, direction);
  return diagrams_.emplace(key, persistence::compute_diagram(medusa_.cells, f)).first->second;
}

std::vector<persistence::ClassRecord> StoreView::classes(persistence::Direction direction, int cell_type,
                                                         std::optional<int> dim, bool zero_length,
                                                         bool shorten, std::vector<std::string>* wraps) {
  persistence::RepresentativeOptions options;
  options.max_dim = dim ? *dim : 2;
  options.zero_length = zero_length;
  options.shorten = shorten;
  const persistence::DiagramWithClasses with_classes =
      persistence::diagram_with_classes(path_, medusa_, direction, cell_type, options);
  std::map<std::size_t, std::string> axes_by_row;
  if (!medusa_.run.periodic_axes.empty()) {
    const std::vector<std::string> axes = persistence::class_wrapping_axes(medusa_, with_classes);
    for (std::size_t i = 0; i < with_classes.classes.size(); ++i)
      axes_by_row[with_classes.classes.rows[i]] = axes[i];
  }
  std::vector<persistence::ClassRecord> out;
  for (persistence::ClassRecord& r : persistence::class_records(medusa_, with_classes))
    if (!dim || r.dim == *dim) {
      if (wraps != nullptr && !medusa_.run.periodic_axes.empty())
        wraps->push_back(axes_by_row[r.id]);
      out.push_back(std::move(r));
    }
  return out;
}

std::vector<std::vector<std::int64_t>> StoreView::complex_at(double t, std::optional<int> type) const {
  const auto& frames = medusa_.input.frame_times;
  // Written so that nan, which compares false with everything, is outside too.
  if (frames.empty() ||
      !(t >= static_cast<double>(frames.front()) && t <= static_cast<double>(frames.back())))
    throw InputError("time " + shortest(t) + " is outside the run " + path_ + " (MCS " +
                     (frames.empty()
                          ? std::string("none")
                          : std::to_string(frames.front()) + " to " + std::to_string(frames.back())) +
                     ")");
  if (type)
    check_type(*type);
  const medusa::ComplexIndex index(medusa_, type);
  std::vector<std::vector<std::int64_t>> simplices;
  for (medusa::CellId id : index.at_time(t)) {
    std::vector<std::int64_t> s;
    for (kinetic::VertexId v : medusa_.cell(id).vertices)
      s.push_back(medusa_.input.cells.at(static_cast<std::size_t>(v)).cell_id);
    std::sort(s.begin(), s.end());
    simplices.push_back(std::move(s));
  }
  std::sort(simplices.begin(), simplices.end(),
            [](const auto& a, const auto& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; });
  return simplices;
}

} // namespace medusa::python
