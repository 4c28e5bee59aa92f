#include "report_scale.h"

#include "cell_type.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "radius_sweep.h"
#include "recorded_domain.h"

#include "medusa/core/error.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/periodic/periodic_cover.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

namespace medusa::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

// The radius as one canonical decimal text ("3.0" and "3" are one radius).
std::string canonical(const std::string& radius) { return sorted_radii({radius}).front(); }

std::string stem_of(const std::string& path, const std::string& suffix) {
  const std::string name = fs::path(path).filename().string();
  return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0
             ? name.substr(0, name.size() - suffix.size())
             : name;
}

std::string type_title(const std::string& label, const std::string& name) {
  if (label == "all")
    return "all cells";
  return "type " + label + (name.empty() ? "" : " (" + name + ")");
}

std::string type_name_of(const kinetic::Trajectories& input, const std::string& label) {
  if (label == "all")
    return "";
  return cell_type_name(input, std::stoi(label));
}

// "3.04", "3.04 and 3.42", or "3.04 to 4.56" for radii consecutive in `grid`; else all listed.
std::string radii_text(const std::vector<std::string>& radii, const std::vector<std::string>& grid) {
  if (radii.empty())
    return "none";
  if (radii.size() == 1)
    return radii.front();
  if (radii.size() == 2)
    return radii[0] + " and " + radii[1];
  const auto first = std::find(grid.begin(), grid.end(), radii.front());
  if (first != grid.end() && grid.end() - first >= static_cast<std::ptrdiff_t>(radii.size()) &&
      std::equal(radii.begin(), radii.end(), first))
    return radii.front() + " to " + radii.back();
  std::string text;
  for (std::size_t i = 0; i < radii.size(); ++i)
    text += (i == 0 ? "" : i + 1 == radii.size() ? " and " : ", ") + radii[i];
  return text;
}

// The note on radii left out of the sweep of a periodic run: 4 x radius not below its shortest period.
std::string too_large_note(const std::string& name, const io::PeriodicDomain& domain, std::int64_t scale,
                           const std::vector<std::string>& left_out, const std::vector<std::string>& grid,
                           bool none_left) {
  std::size_t shortest = 3;
  for (std::size_t a = 0; a < 3; ++a)
    if (domain.periodic[a] && (shortest == 3 || domain.period[a] < domain.period[shortest]))
      shortest = a;
  std::ostringstream period;
  period << static_cast<double>(domain.period[shortest]) / static_cast<double>(scale);
  return name + " is periodic along " + domain.axes() + ": " +
         (none_left ? std::string("no radius sweep is computed for it, its radii ")
                    : "radi" + std::string(left_out.size() == 1 ? "us " : "i ")) +
         radii_text(left_out, grid) + (none_left || left_out.size() > 1 ? " are" : " is") +
         " left out, as the complex on the torus needs 4 x radius below the shortest period, " +
         period.str() + " along " + char('x' + shortest) + " (docs/MATH.md §8.3)";
}

// The note on a run whose default sweep is not computed: its kinetic stage times the radii is hours
// at a million cells, and the page is wanted in minutes.
std::string too_long_note(const std::string& name, const std::string& store, std::size_t event_times,
                          std::size_t limit, std::size_t radii) {
  const std::string prefix = (fs::path(store).parent_path() / stem_of(store, ".h5")).string();
  return "no radius sweep is computed for " + name + ": its kinetic stage has " +
         std::to_string(event_times) +
         " event times (batches in `medusa info`), more than --max-sweep-events " + std::to_string(limit) +
         ", and the default sweep reruns it at " + std::to_string(radii) +
         " radii; compute it once with `medusa sweep <CC3D run> --radii A:B:STEP -o " + prefix +
         "` (the report then reads " + prefix + ".crocker.csv), or here with --sweep-radii A:B:STEP or " +
         "--max-sweep-events 0";
}

// One sweep: per type, per radius, the Betti numbers at each frame.
struct Sweep {
  std::string name;   // the run's name or the file's stem
  int run = -1;       // the run it belongs to
  std::string origin; // how it was obtained, for the page
  std::vector<double> times;
  std::vector<std::string> radii; // canonical, increasing
  std::vector<std::string> types; // labels in the file's order
  std::map<std::pair<std::string, std::string>, std::vector<std::array<std::size_t, 3>>>
      betti; // (type, radius)
  std::vector<CrockerRow> rows;
};

Sweep sweep_of(const std::vector<CrockerRow>& rows) {
  Sweep s;
  s.rows = rows;
  for (const CrockerRow& r : rows) {
    if (std::find(s.times.begin(), s.times.end(), r.time) == s.times.end())
      s.times.push_back(r.time);
    if (std::find(s.types.begin(), s.types.end(), r.type) == s.types.end())
      s.types.push_back(r.type);
    s.radii.push_back(r.radius);
  }
  std::sort(s.times.begin(), s.times.end());
  s.radii = sorted_radii(s.radii);
  for (const std::string& type : s.types)
    for (const std::string& radius : s.radii)
      s.betti[{type, radius}].assign(s.times.size(), {});
  for (const CrockerRow& r : rows) {
    const std::size_t k =
        static_cast<std::size_t>(std::find(s.times.begin(), s.times.end(), r.time) - s.times.begin());
    s.betti[{r.type, canonical(r.radius)}][k] = r.betti;
  }
  return s;
}

// Clusters of a type at the first and at the last frame at one radius.
std::pair<std::size_t, std::size_t> first_last(const Sweep& s, const std::string& type,
                                               const std::string& radius) {
  const auto& b = s.betti.at({type, radius});
  return {b.front()[0], b.back()[0]};
}

std::string time_text(double t) {
  std::ostringstream out;
  out << t;
  return out.str();
}

// For one run and type: at which swept radii it joins into one cluster during the run, is one from
// the first frame, or ends in several clusters.
std::string run_scale_line(const Sweep& s, const std::string& type, const std::string& name) {
  std::vector<std::string> joins, one, split;
  for (const std::string& r : s.radii) {
    const auto [first, last] = first_last(s, type, r);
    (last != 1 ? split : first == 1 ? one : joins).push_back(r);
  }
  const std::string t0 = "MCS " + time_text(s.times.front()), t1 = "MCS " + time_text(s.times.back());
  std::string text = type_title(type, name) + ": ";
  if (joins.empty())
    text += "at no swept radius does it join from several clusters at " + t0 + " into one at " + t1;
  else
    text += "joins from several clusters at " + t0 + " into one at " + t1 + " at radi" +
            (joins.size() == 1 ? "us " : "i ") + radii_text(joins, s.radii);
  if (!one.empty())
    text += "; one cluster already at " + t0 + " at radi" + (one.size() == 1 ? "us " : "i ") +
            radii_text(one, s.radii);
  if (!split.empty())
    text += "; several clusters at " + t1 + " at radi" + (split.size() == 1 ? "us " : "i ") +
            radii_text(split, s.radii);
  return text + " (swept radii " + radii_text(s.radii, s.radii) + ")";
}

json sweep_json(const Sweep& s, const std::vector<ReportRun>& runs) {
  json j = {{"name", s.name},   {"run", s.run},     {"origin", s.origin},
            {"times", s.times}, {"radii", s.radii}, {"types", json::array()}};
  for (const std::string& type : s.types) {
    json first = json::array(), last = json::array(), betti = json::array();
    for (const std::string& radius : s.radii) {
      const auto& b = s.betti.at({type, radius});
      first.push_back(b.front()[0]);
      last.push_back(b.back()[0]);
      betti.push_back(b);
    }
    const std::string name =
        s.run >= 0 ? type_name_of(runs[static_cast<std::size_t>(s.run)].input, type) : "";
    j["types"].push_back(
        {{"label", type}, {"name", name}, {"first", first}, {"last", last}, {"betti", betti}});
  }
  return j;
}

// Per type, the radii (common to the runs' sweeps) at which the runs differ in whether the type is
// one cluster at the end of the run. Alpha complexes grow with the radius (docs/MATH.md §7.10), so b0
// does not increase with it: each run is one cluster at the end from some radius on.
json comparison(const std::vector<const Sweep*>& sweeps, const std::vector<ReportRun>& runs) {
  std::vector<std::string> common = sweeps.front()->radii;
  for (const Sweep* s : sweeps) {
    std::vector<std::string> kept;
    for (const std::string& r : common)
      if (std::find(s->radii.begin(), s->radii.end(), r) != s->radii.end())
        kept.push_back(r);
    common = kept;
  }
  json out = {{"radii", common}, {"statements", json::array()}};
  if (common.empty())
    return out;
  for (const std::string& type : sweeps.front()->types) {
    if (type == "all" || std::any_of(sweeps.begin(), sweeps.end(), [&](const Sweep* s) {
          return std::find(s->types.begin(), s->types.end(), type) == s->types.end();
        }))
      continue;
    const std::string name = type_name_of(runs[static_cast<std::size_t>(sweeps.front()->run)].input, type);
    std::vector<std::string> differ;
    for (const std::string& r : common) {
      bool some = false, all = true;
      for (const Sweep* s : sweeps) {
        const bool one = first_last(*s, type, r).second == 1;
        some = some || one;
        all = all && one;
      }
      if (some && !all)
        differ.push_back(r);
    }
    // Runs grouped by the smallest common radius at which they end in one cluster: smallest first,
    // those that never do last.
    std::vector<std::pair<std::string, std::vector<std::string>>> groups;
    for (const Sweep* s : sweeps) {
      std::string smallest;
      for (const std::string& r : common)
        if (first_last(*s, type, r).second == 1) {
          smallest = r;
          break;
        }
      auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == smallest; });
      if (g == groups.end())
        groups.push_back({smallest, {s->name}});
      else
        g->second.push_back(s->name);
    }
    std::stable_sort(groups.begin(), groups.end(), [&common](const auto& a, const auto& b) {
      const auto rank = [&common](const std::string& r) {
        return r.empty()
                   ? common.size()
                   : static_cast<std::size_t>(std::find(common.begin(), common.end(), r) - common.begin());
      };
      return rank(a.first) < rank(b.first);
    });
    std::string text = type_title(type, name) + " is one cluster at the end of the run ";
    for (std::size_t i = 0; i < groups.size(); ++i) {
      std::string runs_text;
      for (std::size_t k = 0; k < groups[i].second.size(); ++k)
        runs_text += (k == 0 ? "" : k + 1 == groups[i].second.size() ? " and " : ", ") + groups[i].second[k];
      text += std::string(i == 0                   ? ""
                          : i + 1 == groups.size() ? " and "
                                                   : ", ") +
              (groups[i].first.empty() ? "at no swept radius (up to " + common.back() + ")"
                                       : "from radius " + groups[i].first) +
              " in " + runs_text;
    }
    if (differ.empty())
      text += ": the runs do not differ in this at any swept radius (" + radii_text(common, common) + ")";
    else
      text += ": the runs differ at radi" + std::string(differ.size() == 1 ? "us " : "i ") +
              radii_text(differ, common);
    // Where the sorting itself shows: several clusters at the first frame, one at the last.
    std::vector<std::pair<std::string, std::vector<std::string>>> joins;
    for (const Sweep* s : sweeps) {
      std::vector<std::string> at;
      for (const std::string& r : common) {
        const auto [first, last] = first_last(*s, type, r);
        if (first > 1 && last == 1)
          at.push_back(r);
      }
      const std::string where =
          at.empty() ? "at no swept radius"
                     : "at radi" + std::string(at.size() == 1 ? "us " : "i ") + radii_text(at, common);
      auto g = std::find_if(joins.begin(), joins.end(), [&](const auto& x) { return x.first == where; });
      if (g == joins.end())
        joins.push_back({where, {s->name}});
      else
        g->second.push_back(s->name);
    }
    text += ". It joins from several clusters at the first frame into one at the last ";
    for (std::size_t i = 0; i < joins.size(); ++i) {
      std::string runs_text;
      for (std::size_t k = 0; k < joins[i].second.size(); ++k)
        runs_text += (k == 0 ? "" : k + 1 == joins[i].second.size() ? " and " : ", ") + joins[i].second[k];
      text += std::string(i == 0                  ? ""
                          : i + 1 == joins.size() ? " and "
                                                  : ", ") +
              joins[i].first + " in " + runs_text;
    }
    out["statements"].push_back({{"label", type}, {"name", name}, {"text", text}, {"radii", differ}});
  }
  return out;
}

} // namespace

std::vector<std::string> default_sweep_radii(const std::string& radius_text) {
  Decimal r;
  if (!parse_decimal(radius_text, r) || r.units <= 0)
    throw InputError("'" + radius_text + "' is not a positive decimal radius");
  // r * k / 8 in units of 0.01, rounded half up: units * k * 100 / (8 * 10^decimals).
  std::int64_t scale = 8;
  for (int i = 0; i < r.decimals; ++i)
    scale *= 10;
  std::vector<std::string> radii;
  for (std::int64_t k = 4; k <= 12; ++k) {
    const std::int64_t hundredths = (2 * r.units * k * 100 + scale) / (2 * scale);
    if (hundredths > 0)
      radii.push_back(decimal_text(hundredths, 2));
  }
  return sorted_radii(radii);
}

ScaleSection report_scale(std::vector<ReportRun>& runs, const ScaleOptions& options) {
  std::vector<Sweep> sweeps;
  std::string computed_how;
  const unsigned workers = worker_threads(options.threads);
  std::vector<std::string> computed_radii = options.radii;
  if (computed_radii.empty() && !runs.empty())
    computed_radii = default_sweep_radii(runs.front().data["facts"]["radius"].get<std::string>());
  std::vector<std::string> notes;
  // The files given are read first: a malformed one fails before any sweep is computed.
  std::vector<Sweep> given;
  for (const std::string& file : options.given) {
    check_interrupted();
    // A store's own sweep given again is shown once, as that store's.
    std::error_code ec;
    if (options.radii.empty() &&
        std::any_of(options.stores.begin(), options.stores.end(), [&](const std::string& store) {
          const fs::path own = fs::path(store).parent_path() / (stem_of(store, ".h5") + ".crocker.csv");
          return fs::exists(own, ec) && fs::equivalent(own, file, ec);
        }))
      continue;
    Sweep s = sweep_of(read_crocker_csv(file));
    s.name = stem_of(file, ".crocker.csv");
    s.origin = "read from " + file + " (written by medusa sweep)";
    given.push_back(std::move(s));
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    check_interrupted();
    const std::string& store = options.stores.at(i);
    const fs::path own = fs::path(store).parent_path() / (stem_of(store, ".h5") + ".crocker.csv");
    std::error_code ec;
    Sweep s;
    if (options.radii.empty() && fs::is_regular_file(own, ec)) {
      s = sweep_of(read_crocker_csv(own.string()));
      s.origin = "read from " + own.string() + " (written by medusa sweep)";
    } else if (options.no_sweep) {
      continue;
    } else if (options.radii.empty() && options.max_sweep_events != 0 &&
               runs[i].event_times > options.max_sweep_events) {
      notes.push_back(too_long_note(runs[i].name, store, runs[i].event_times, options.max_sweep_events,
                                    computed_radii.size()));
      if (!options.quiet)
        std::cerr << "medusa: warning: " << notes.back() << "\n";
      continue;
    } else {
      // A periodic run is swept on the torus, at the radii whose complex there is defined (docs/MATH.md
      // §8.3): the others are left out, with a note on the page.
      const io::PeriodicDomain domain = recorded_domain(runs[i].run_info, runs[i].input.scale, store);
      std::vector<std::string> radii, too_large;
      for (const std::string& r : computed_radii) {
        const kinetic::SquaredRadius rho2 = kinetic::squared_radius_from_decimal(r, runs[i].input.scale);
        if (domain.any() && periodic::axis_too_short_for_radius(domain, rho2) >= 0)
          too_large.push_back(r);
        else
          radii.push_back(r);
      }
      if (!too_large.empty()) {
        notes.push_back(too_large_note(runs[i].name, domain, runs[i].input.scale, too_large, computed_radii,
                                       radii.empty()));
        if (!options.quiet)
          std::cerr << "medusa: warning: " << notes.back() << "\n";
      }
      if (radii.empty())
        continue;
      if (!options.quiet)
        std::cerr << "medusa report: radius sweep of " << runs[i].name << " at " << radii.size()
                  << " radii on " << std::min<std::size_t>(workers, radii.size()) << " thread(s)\n";
      const std::vector<RadiusResult> results =
          sweep_radii(runs[i].input, runs[i].run_info, domain, radii, workers, false,
                      [&](const std::string& radius, std::size_t done, std::size_t total) {
                        if (!options.quiet)
                          std::cerr << "medusa report: " << runs[i].name << " radius " << radius << " done ("
                                    << done << "/" << total << ")\n";
                      });
      s = sweep_of(crocker_rows(results, runs[i].input.frame_times));
      s.origin = "computed at report time from the trajectories in " + store;
    }
    s.name = runs[i].name;
    s.run = static_cast<int>(i);
    runs[i].data["scale"] = json::array();
    for (const std::string& type : s.types)
      if (type != "all")
        runs[i].data["scale"].push_back(
            {{"label", type}, {"text", run_scale_line(s, type, type_name_of(runs[i].input, type))}});
    sweeps.push_back(std::move(s));
  }
  for (Sweep& s : given)
    sweeps.push_back(std::move(s));

  ScaleSection section;
  std::vector<const Sweep*> of_runs;
  for (const Sweep& s : sweeps) {
    check_interrupted();
    ReportFigure f;
    f.title = "CROCKER plot of " + s.name;
    f.notes.push_back("Radius sweep " + s.origin + "; radii " + radii_text(s.radii, s.radii) + ".");
    std::ostringstream svg;
    write_crocker_svg(svg, s.rows, s.name + ": Betti numbers of K_t over time and radius",
                      s.run >= 0 && runs[static_cast<std::size_t>(s.run)].dimension == 2 ? 1 : 2);
    f.svgs.push_back(svg.str());
    section.figures.push_back(std::move(f));
    section.sweeps.push_back(sweep_json(s, runs));
    if (s.run >= 0)
      of_runs.push_back(&s);
  }
  if (!options.radii.empty())
    computed_how = "at the radii given with --sweep-radii";
  else
    computed_how = "at nine radii from half to one and a half times the radius of " +
                   (runs.empty() ? std::string() : runs.front().name) + " (" +
                   (runs.empty() ? std::string() : runs.front().data["facts"]["radius"].get<std::string>()) +
                   ") in steps of an eighth of it, rounded to 0.01";
  section.scale = of_runs.size() >= 2 ? comparison(of_runs, runs)
                                      : json{{"radii", json::array()}, {"statements", json::array()}};
  section.scale["how"] = computed_how;
  section.scale["computed_radii"] = computed_radii;
  section.scale["notes"] = notes;
  section.scale["computed"] = std::any_of(sweeps.begin(), sweeps.end(),
                                          [](const Sweep& s) { return s.origin.rfind("computed", 0) == 0; });
  return section;
}

} // namespace medusa::cli
