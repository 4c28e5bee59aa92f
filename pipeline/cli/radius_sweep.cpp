#include "radius_sweep.h"

#include "diagram_selection.h"
#include "interrupt.h"
#include "medusa_in_memory.h"

#include "medusa/core/error.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace medusa::cli {
namespace {

std::int64_t rescaled(const Decimal& d, int decimals) {
  std::int64_t u = d.units;
  for (int i = d.decimals; i < decimals; ++i)
    u *= 10;
  return u;
}

RadiusResult sweep_one(const kinetic::Trajectories& trajectories, const medusa::RunInfo& base,
                       const io::PeriodicDomain& domain, const std::string& radius, bool diagrams) {
  medusa::RunInfo info = base;
  info.radius_text = radius;
  info.radius = std::stod(radius);
  const medusa::Medusa medusa = medusa_in_memory(trajectories, info, domain);
  check_interrupted();
  RadiusResult result;
  result.radius = radius;
  result.edges = !medusa.cells_of_dimension(1).empty();
  result.slices = slices_at_frames(medusa);
  if (!diagrams)
    return result;
  const std::vector<int> vertex_type = vertex_types(medusa);
  const std::vector<int> types = distinct_types(vertex_type);
  check_interrupted();
  persistence::DiagramRunOptions options;
  options.zero_length = false;
  options.poll = check_interrupted;
  for (const persistence::Diagram& d :
       persistence::compute_medusa_diagrams(medusa.cells, vertex_type, types, options))
    if (d.direction == persistence::Direction::forward)
      result.counts.emplace_back(type_label(d.cell_type), forward_counts(d));
  return result;
}

} // namespace

bool parse_decimal(const std::string& text, Decimal& d) {
  const std::size_t dot = text.find('.');
  const std::string whole = text.substr(0, dot),
                    fraction = dot == std::string::npos ? "" : text.substr(dot + 1);
  if ((whole.empty() && fraction.empty()) || whole.size() + fraction.size() > 15 ||
      whole.find_first_not_of("0123456789") != std::string::npos ||
      fraction.find_first_not_of("0123456789") != std::string::npos)
    return false;
  d.decimals = static_cast<int>(fraction.size());
  d.units = std::stoll("0" + whole + fraction);
  return true;
}

std::string decimal_text(std::int64_t units, int decimals) {
  std::string digits = std::to_string(units);
  if (decimals == 0)
    return digits;
  if (digits.size() <= static_cast<std::size_t>(decimals))
    digits.insert(0, static_cast<std::size_t>(decimals) + 1 - digits.size(), '0');
  std::string text = digits.substr(0, digits.size() - static_cast<std::size_t>(decimals)) + "." +
                     digits.substr(digits.size() - static_cast<std::size_t>(decimals));
  while (text.back() == '0')
    text.pop_back();
  if (text.back() == '.')
    text.pop_back();
  return text;
}

std::string expand_range(const std::string& spec, std::vector<std::string>* radii) {
  const std::size_t c1 = spec.find(':'), c2 = c1 == std::string::npos ? c1 : spec.find(':', c1 + 1);
  Decimal a, b, step;
  if (c2 == std::string::npos || !parse_decimal(spec.substr(0, c1), a) ||
      !parse_decimal(spec.substr(c1 + 1, c2 - c1 - 1), b) || !parse_decimal(spec.substr(c2 + 1), step))
    return "'" + spec + "' is not A:B:STEP with decimal numbers";
  const int decimals = std::max({a.decimals, b.decimals, step.decimals});
  const std::int64_t from = rescaled(a, decimals), to = rescaled(b, decimals), by = rescaled(step, decimals);
  if (from <= 0 || by <= 0 || to < from)
    return "'" + spec + "' needs 0 < A <= B and STEP > 0";
  if ((to - from) / by + 1 > static_cast<std::int64_t>(max_sweep_radii))
    return "'" + spec + "' gives more than " + std::to_string(max_sweep_radii) + " radii";
  for (std::int64_t u = from; u <= to; u += by)
    if (radii != nullptr)
      radii->push_back(decimal_text(u, decimals));
  return "";
}

std::string radius_error(const std::string& text) {
  Decimal d;
  if (!parse_decimal(text, d) || d.units <= 0)
    return "'" + text + "' is not a positive decimal radius";
  return "";
}

std::vector<std::string> sorted_radii(const std::vector<std::string>& texts) {
  std::vector<Decimal> values;
  int decimals = 0;
  for (const std::string& t : texts) {
    Decimal d;
    if (!parse_decimal(t, d))
      throw InputError("'" + t + "' is not a decimal radius");
    decimals = std::max(decimals, d.decimals);
    values.push_back(d);
  }
  std::vector<std::int64_t> keyed;
  for (const Decimal& d : values)
    keyed.push_back(rescaled(d, decimals));
  std::sort(keyed.begin(), keyed.end());
  keyed.erase(std::unique(keyed.begin(), keyed.end()), keyed.end());
  if (keyed.size() > max_sweep_radii)
    throw InputError("more than " + std::to_string(max_sweep_radii) + " radii");
  std::vector<std::string> radii;
  for (const std::int64_t u : keyed)
    radii.push_back(decimal_text(u, decimals));
  return radii;
}

std::vector<RadiusResult>
sweep_radii(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info,
            const io::PeriodicDomain& domain, const std::vector<std::string>& radii, unsigned workers,
            bool diagrams, const std::function<void(const std::string&, std::size_t, std::size_t)>& done) {
  std::vector<RadiusResult> results(radii.size());
  std::vector<std::exception_ptr> errors(radii.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex print;
  std::size_t finished = 0;
  auto work = [&] {
    for (std::size_t i = next++; i < radii.size() && !failed; i = next++) {
      try {
        results[i] = sweep_one(trajectories, info, domain, radii[i], diagrams);
        const std::lock_guard<std::mutex> lock(print);
        ++finished;
        if (done)
          done(radii[i], finished, radii.size());
      } catch (...) {
        errors[i] = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned w = 1; w < std::min<std::size_t>(workers, radii.size()); ++w)
    pool.emplace_back(work);
  work();
  for (std::thread& t : pool)
    t.join();
  for (const std::exception_ptr& e : errors)
    if (e) {
      try {
        std::rethrow_exception(e);
      } catch (const Interrupted&) {
        throw;
      } catch (...) {
      }
    }
  for (const std::exception_ptr& e : errors)
    if (e)
      std::rethrow_exception(e);
  check_interrupted();
  return results;
}

std::vector<CrockerRow> crocker_rows(const std::vector<RadiusResult>& results,
                                     const std::vector<std::int64_t>& frame_times) {
  std::vector<CrockerRow> rows;
  for (const RadiusResult& r : results)
    for (const TypeSlices& s : r.slices)
      for (std::size_t k = 0; k < s.at_frame.size(); ++k)
        rows.push_back({r.radius,
                        static_cast<double>(frame_times.at(k)),
                        s.label,
                        {s.at_frame[k].betti[0], s.at_frame[k].betti[1], s.at_frame[k].betti[2]}});
  return rows;
}

} // namespace medusa::cli
