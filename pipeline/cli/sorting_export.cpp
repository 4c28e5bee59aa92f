#include "sorting_export.h"

#include "diagram_export.h"
#include "interrupt.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace medusa::cli {
namespace {

// The shortest text that reads back as the same double. A quantity without a denominator (no edge, no
// cell with a neighbour) is an empty field (NA).
void put_fraction(std::ostream& out, double x) {
  if (std::isnan(x))
    return;
  char buffer[40];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  out.write(buffer, end - buffer);
}

std::string label_of(const medusa::SortingMeasures& m) { return m.type ? std::to_string(*m.type) : "all"; }

// Samples per pixel column of the plot: enough for a faithful step line, few enough that a run with
// hundreds of thousands of batches gives a small SVG.
constexpr double buckets = 2400;

// A fraction in words: three decimals, "n/a" without a denominator.
std::string share(double x) {
  if (std::isnan(x))
    return "n/a";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", x);
  return buffer;
}

} // namespace

std::string contact_fractions(const medusa::SortingMeasures& first, const medusa::SortingMeasures& last,
                              const std::string& arrow) {
  return heterotypic_contacts(first, last, arrow) + ", same-type neighbours " +
         share(first.same_type_fraction) + arrow + share(last.same_type_fraction);
}

std::string largest_cluster_share(const medusa::SortingMeasures& first, const medusa::SortingMeasures& last,
                                  const std::string& arrow) {
  return "largest cluster " + std::to_string(first.largest_cluster) + " of " + std::to_string(first.cells) +
         arrow + std::to_string(last.largest_cluster) + " of " + std::to_string(last.cells) + " cells";
}

std::string heterotypic_contacts(const medusa::SortingMeasures& first, const medusa::SortingMeasures& last,
                                 const std::string& arrow) {
  return "heterotypic contacts " + share(first.heterotypic_fraction()) + arrow +
         share(last.heterotypic_fraction());
}

void write_sorting_csv(std::ostream& out, const std::vector<medusa::SortingSample>& samples,
                       const TypeNames& names) {
  out << "time,type,cells,edges,heterotypic_edges,heterotypic_fraction,cells_with_neighbours,"
         "same_type_fraction,clusters,largest_cluster,mean_cluster_size,type_name\n";
  if (samples.empty())
    return;
  std::vector<std::string> times;
  times.reserve(samples.size());
  for (const medusa::SortingSample& s : samples)
    times.push_back(format_time(s.time));
  for (std::size_t g = 0; g < samples.front().measures.size(); ++g) {
    const std::string label = label_of(samples.front().measures[g]);
    const std::string name = csv_field(type_label_name(names, label));
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (i % 4096 == 0)
        check_interrupted();
      const medusa::SortingMeasures& m = samples[i].measures.at(g);
      out << times[i] << ',' << label << ',' << m.cells << ',' << m.edges << ',' << m.heterotypic_edges
          << ',';
      put_fraction(out, m.heterotypic_fraction());
      out << ',' << m.cells_with_neighbours << ',';
      put_fraction(out, m.same_type_fraction);
      out << ',' << m.clusters << ',' << m.largest_cluster << ',';
      put_fraction(out, m.mean_cluster_size());
      out << ',' << name << '\n';
    }
  }
}

std::vector<CurvePanel> sorting_panels(const std::vector<medusa::SortingSample>& samples, double t0,
                                       double t_end, const TypeNames& names) {
  using Quantity = std::function<double(const medusa::SortingMeasures&)>;
  const std::vector<std::pair<std::string, Quantity>> quantities{
      {"heterotypic contacts: fraction of the edges of K_t (touching the type) that join two types",
       [](const medusa::SortingMeasures& m) { return m.heterotypic_fraction(); }},
      {"same-type neighbours: mean fraction over the cells with a neighbour",
       [](const medusa::SortingMeasures& m) { return m.same_type_fraction; }},
      {"clusters: components of K_t of the type",
       [](const medusa::SortingMeasures& m) { return static_cast<double>(m.clusters); }},
      {"largest cluster (cells)",
       [](const medusa::SortingMeasures& m) { return static_cast<double>(m.largest_cluster); }},
      {"mean cluster size (cells)", [](const medusa::SortingMeasures& m) { return m.mean_cluster_size(); }}};
  std::vector<CurvePanel> panels;
  if (samples.empty())
    return panels;
  const double span = t_end > t0 ? t_end - t0 : 1.0;
  for (const auto& [title, value] : quantities) {
    CurvePanel panel{title, {}};
    for (std::size_t g = 0; g < samples.front().measures.size(); ++g) {
      Curve c{type_label_title(names, label_of(samples.front().measures[g])), {}, {}};
      double last_bucket = -1;
      for (const medusa::SortingSample& s : samples) {
        const double v = value(s.measures.at(g));
        if (std::isnan(v))
          continue;
        // One point per bucket: the bucket's first sample time, with the value of its last sample.
        const double bucket = std::floor(buckets * (s.time - t0) / span);
        if (bucket == last_bucket) {
          c.values.back() = v;
          continue;
        }
        last_bucket = bucket;
        c.times.push_back(s.time);
        c.values.push_back(v);
      }
      panel.curves.push_back(std::move(c));
    }
    panels.push_back(std::move(panel));
  }
  return panels;
}

} // namespace medusa::cli
