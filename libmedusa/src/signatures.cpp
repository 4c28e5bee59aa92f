#include "medusa/medusa/signatures.h"

#include "medusa/core/error.h"
#include "medusa/medusa/homology.h"

#include <array>
#include <limits>
#include <string>
#include <unordered_map>

namespace medusa {

Signature signature_of(const Medusa& medusa, const std::vector<CellId>& cells,
                       const std::function<void()>& poll) {
  Signature s;
  // Local index of each member by cell id: an array over the medusa, not a hash table, since a
  // million-cell run's slices have millions of members and every facet is looked up.
  constexpr std::uint32_t absent = std::numeric_limits<std::uint32_t>::max();
  if (cells.size() >= absent)
    throw InternalError("medusa signature: " + std::to_string(cells.size()) + " cells, more than 2^32 - 1");
  std::vector<std::uint32_t> local(medusa.cells.size(), absent);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells[i] >= local.size())
      throw InternalError("medusa signature: no cell " + std::to_string(cells[i]) + " in the medusa");
    local[cells[i]] = static_cast<std::uint32_t>(i);
  }
  ChainComplex complex;
  complex.reserve(cells.size(), 3 * cells.size());
  std::array<std::uint32_t, 4> facets{};
  for (CellId id : cells) {
    const Cell& c = medusa.cell(id);
    if (c.dim() < 0 || c.dim() > 3)
      throw InternalError("medusa signature: cell " + std::to_string(id) + " of dimension " +
                          std::to_string(c.dim()) + " in K_t");
    ++s.f[static_cast<std::size_t>(c.dim())];
    if (c.facets.size() > facets.size())
      throw InternalError("medusa signature: cell " + std::to_string(id) + " has " +
                          std::to_string(c.facets.size()) + " facets");
    for (std::size_t k = 0; k < c.facets.size(); ++k) {
      const CellId f = c.facets[k];
      facets[k] = f < local.size() ? local[f] : absent;
      if (facets[k] == absent)
        throw InternalError("medusa signature: facet cell " + std::to_string(f) + " of cell " +
                            std::to_string(id) + " is not in K_t");
    }
    complex.add(c.dim(), facets.begin(), facets.begin() + static_cast<std::ptrdiff_t>(c.facets.size()));
  }
  s.euler = static_cast<long long>(s.f[0]) - static_cast<long long>(s.f[1]) + static_cast<long long>(s.f[2]) -
            static_cast<long long>(s.f[3]);
  const std::vector<std::size_t> betti = betti_numbers(complex, poll);
  for (std::size_t k = 0; k < betti.size(); ++k)
    s.betti[k] = betti[k];
  return s;
}

std::vector<SignatureSample> signatures_over_time(const ComplexIndex& index) {
  const Medusa& m = index.medusa();
  std::vector<SignatureSample> samples;
  for (const BatchRecord& b : m.batches) {
    SignatureSample s;
    s.batch = b.batch;
    s.time = b.time;
    s.signature = signature_of(m, index.after(b.batch));
    samples.push_back(std::move(s));
  }
  SignatureSample end;
  end.batch = m.end.batch;
  end.before = true;
  end.time = m.end.time;
  end.signature = signature_of(m, index.before(m.end.batch));
  samples.push_back(std::move(end));
  assign_frames(m, samples);
  return samples;
}

void assign_frames(const Medusa& m, std::vector<SignatureSample>& samples) {
  if (samples.size() != m.batches.size() + 1)
    throw InternalError("medusa signature: " + std::to_string(samples.size()) + " samples for " +
                        std::to_string(m.batches.size()) + " batches");
  std::unordered_map<std::uint64_t, std::size_t> by_batch;
  for (std::size_t i = 0; i < m.batches.size(); ++i)
    by_batch.emplace(m.batches[i].batch, i);
  for (std::size_t k = 0; k < m.input.frames(); ++k) {
    if (k + 1 == m.input.frames()) {
      samples.back().frames.push_back(k);
      continue;
    }
    auto it = by_batch.find(frame_batch(m, k));
    if (it == by_batch.end())
      throw InternalError("medusa signature: frame " + std::to_string(k) + " maps to no batch");
    samples[it->second].frames.push_back(k);
  }
}

} // namespace medusa
