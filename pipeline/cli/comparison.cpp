#include "comparison.h"

#include "cell_type.h"
#include "diagram_export.h"
#include "diagram_selection.h"

#include "medusa/core/error.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/bottleneck.h"
#include "medusa/persistence/medusa_diagrams.h"
#include "medusa/persistence/wasserstein.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace medusa::cli {
namespace {

// p of "wasserstein:p": a decimal number >= 1, or nothing when the spec is not of that form.
bool parse_wasserstein(const std::string& spec, double& p, std::string& text) {
  const std::string prefix = "wasserstein:";
  if (spec.compare(0, prefix.size(), prefix) != 0)
    return false;
  text = spec.substr(prefix.size());
  if (text.empty() || text.find_first_not_of("0123456789.") != std::string::npos)
    return false;
  char* end = nullptr;
  p = std::strtod(text.c_str(), &end);
  return end != nullptr && *end == '\0' && p >= 1.0;
}

} // namespace

ComparedDiagram compared_diagram(const std::string& store, const ComparisonSelection& selection) {
  return compared_diagrams(store, {selection}).front();
}

std::vector<ComparedDiagram> compared_diagrams(const std::string& store,
                                               const std::vector<ComparisonSelection>& selections) {
  if (selections.empty())
    return {};
  const medusa::Medusa medusa = medusa::read_store(store);
  if (medusa.input.frame_times.size() < 2)
    throw InputError("store " + store + " has fewer than two frames; its time axis cannot be normalised");
  // One type asked for: only its diagrams are computed; several: the whole medusa and every type.
  DiagramSelection wanted;
  wanted.filtration = selections.front().filtration;
  bool one_type = true;
  for (const ComparisonSelection& s : selections) {
    one_type = one_type && s.type == selections.front().type;
    if (s.filtration != wanted.filtration)
      throw InternalError("medusa compare: selections of different filtrations");
  }
  if (one_type)
    wanted.type = selections.front().type;
  const std::vector<persistence::Diagram> diagrams = selected_diagrams(medusa, wanted, store);
  const double t0 = static_cast<double>(medusa.input.frame_times.front());
  const double t_end = static_cast<double>(medusa.input.frame_times.back());
  std::vector<ComparedDiagram> result;
  for (const ComparisonSelection& s : selections) {
    // A type name is resolved in each run: the same name may have another id in another run.
    const int type = resolve_cell_type(s.type, medusa.input, store);
    const auto d = std::find_if(diagrams.begin(), diagrams.end(),
                                [&](const persistence::Diagram& x) { return x.cell_type == type; });
    if (d == diagrams.end())
      throw InternalError("medusa compare: no diagram of type " + s.type + " in " + store);
    ComparedDiagram c;
    c.name = std::filesystem::path(store).stem().string();
    c.t0 = t0;
    c.t_end = t_end;
    c.dimension = medusa.input.dimension;
    c.points = persistence::normalise_time(persistence::to_points(*d, s.dim), d->direction, t0, t_end);
    result.push_back(std::move(c));
  }
  return result;
}

RunFacts read_run_facts(const std::string& store) {
  medusa::StoreReadOptions cells_only;
  cells_only.events = false;
  medusa::Medusa m = medusa::read_store(store, cells_only);
  RunFacts facts;
  facts.input = std::move(m.input);
  facts.radius_value = m.run.radius;
  facts.radius = m.run.radius_text.empty() ? format_time(m.run.radius) : m.run.radius_text;
  return facts;
}

std::vector<std::string> comparability_warnings(const std::vector<std::string>& names,
                                                const std::vector<RunFacts>& runs,
                                                const std::vector<ComparisonSelection>& selections) {
  std::vector<std::string> warnings;
  // run_names keeps the paths as given when stems coincide, so a name repeats only for a path given twice.
  for (std::size_t i = 0; i < names.size(); ++i)
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
        names.begin() + static_cast<std::ptrdiff_t>(i))
      warnings.push_back(names[i] + " is given twice: its distance to itself is 0");
  std::vector<std::string> checked;
  for (const ComparisonSelection& s : selections) {
    // Only a type given by id can be matched to types of different names; a name is looked up in
    // each run (resolve_cell_type).
    if (s.type.empty() || s.type.find_first_not_of("0123456789") != std::string::npos ||
        std::find(checked.begin(), checked.end(), s.type) != checked.end())
      continue;
    checked.push_back(s.type);
    std::vector<std::string> distinct, named;
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (const std::string name = cell_type_name(runs[i].input, std::stoi(s.type)); !name.empty()) {
        named.push_back(names[i] + " " + name);
        if (std::find(distinct.begin(), distinct.end(), name) == distinct.end())
          distinct.push_back(name);
      }
    if (distinct.size() > 1) {
      std::string list;
      for (const std::string& n : named)
        list += (list.empty() ? "" : ", ") + n;
      warnings.push_back("type " + s.type + " has different names in the runs (" + list +
                         "): types are matched by id; --type NAME matches them by name");
    }
  }
  const auto [lo, hi] =
      std::minmax_element(runs.begin(), runs.end(), [](const RunFacts& a, const RunFacts& b) {
        return a.radius_value < b.radius_value;
      });
  if (lo->radius_value > 0 && hi->radius_value > 1.05 * lo->radius_value) {
    std::string list;
    for (std::size_t i = 0; i < runs.size(); ++i)
      list += (list.empty() ? "" : ", ") + names[i] + " " + runs[i].radius;
    warnings.push_back(
        "the runs were analysed at radii more than 5% apart (" + list +
        "): their distances measure the radius as well as the sorting; `medusa run --radius R` "
        "gives every run one radius");
  }
  return warnings;
}

std::vector<std::string> run_names(const std::vector<std::string>& stores) {
  std::vector<std::string> names;
  for (const std::string& s : stores)
    names.push_back(std::filesystem::path(s).stem().string());
  std::vector<std::string> sorted = names;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return stores;
  return names;
}

std::string metric_spec_error(const std::string& spec) {
  double p = 0;
  std::string text;
  if (spec == "bottleneck" || parse_wasserstein(spec, p, text))
    return {};
  return "'" + spec + "' is not 'bottleneck' or 'wasserstein:p' with a number p >= 1";
}

ComparisonMetric::ComparisonMetric(const std::string& spec, bool ignore_essential)
    : ignore_essential_(ignore_essential) {
  if (spec == "bottleneck")
    return;
  if (!parse_wasserstein(spec, p_, p_text_))
    throw InputError("metric " + metric_spec_error(spec));
  wasserstein_ = true;
}

double ComparisonMetric::operator()(const persistence::PointDiagram& a,
                                    const persistence::PointDiagram& b) const {
  if (!wasserstein_)
    return persistence::bottleneck_distance(a, b, ignore_essential_).total;
  persistence::WassersteinOptions options;
  options.p = p_;
  options.ignore_essential = ignore_essential_;
  const persistence::DistanceResult r = persistence::wasserstein_distance(a, b, options);
  if (!r.exact) {
    const std::lock_guard<std::mutex> lock(mutex_);
    relative_error_ = std::max(relative_error_, r.relative_error);
  }
  return r.total;
}

std::string ComparisonMetric::description() const {
  const std::string essential =
      ignore_essential_ ? "essential classes ignored" : "inf when the essential counts differ";
  return (wasserstein_ ? "Wasserstein W_" + p_text_ : std::string("bottleneck")) + " (" + essential + ")";
}

std::string ComparisonMetric::reading() const {
  std::string text = "0: the runs have the same classes at the same times; ";
  if (wasserstein_)
    text += "larger: more classes, or classes further apart in time, differ (each class's share counts)";
  else
    text += "d: every class of one run has a partner in the other whose start and end are within d (a "
            "fraction of the run's duration), except classes that lasted at most 2d";
  if (!ignore_essential_)
    text += "; inf: the runs have different numbers of classes that never ended";
  return text;
}

double ComparisonMetric::largest_relative_error() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return relative_error_;
}

std::string mixed_dimensions_note(const std::vector<std::string>& names, const std::vector<int>& dimensions) {
  std::string planar, spatial;
  for (std::size_t i = 0; i < names.size() && i < dimensions.size(); ++i) {
    std::string& list = dimensions[i] == 2 ? planar : spatial;
    list += (list.empty() ? "" : ", ") + names[i];
  }
  if (planar.empty() || spatial.empty())
    return "";
  return "runs of different dimension, planar (2D): " + planar + "; 3D: " + spatial +
         ". A radius is a disc in the plane and a ball in space, and a cell has fewer neighbours in the "
         "plane, so clusters, contacts and radii are read within each run; the distances between runs "
         "compare the shapes of their diagrams only";
}

} // namespace medusa::cli
