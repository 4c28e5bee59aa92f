#include "medusa/periodic/periodic_cover.h"

#include "medusa/core/error.h"

#include <gmpxx.h>

#include <algorithm>
#include <limits>

namespace medusa::periodic {

namespace {

// The smallest integer r with r^2 >= rho_g^2 = num / den: a margin in grid units that is never short.
std::int64_t radius_ceiling(const kinetic::SquaredRadius& rho2) {
  mpz_class q;
  mpz_cdiv_q(q.get_mpz_t(), rho2.num.get_mpz_t(), rho2.den.get_mpz_t());
  mpz_class r;
  mpz_sqrt(r.get_mpz_t(), q.get_mpz_t());
  if (r * r < q)
    ++r;
  if (!r.fits_slong_p())
    throw GeometryError("the radius does not fit the grid");
  return r.get_si();
}

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0)))
    --q;
  return q;
}

std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

struct Box {
  std::array<std::int64_t, 3> lo{}, hi{};
  bool empty = true;
};

// splitmix64: a fixed pseudo-random sequence, so that the sentinels are the same on every machine.
std::uint64_t next_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Static sentinels on the faces of the box holding every covering position at every frame, grown by
// 2 r + 1 (so more than 2 rho from every point at every time: positions between frames are convex
// combinations of positions at frames), about max(2 r + 1, L_min / 4) apart and jittered off the grid
// outwards (general position). Copies are exact translates, so copies on the cover's own hull lie
// permanently in one plane, and the hull events around them ended in static repairs; inside the
// sentinels' hull, which never changes, there are none (docs/MATH.md §8.4).
void add_sentinels(PeriodicCover& cover, const io::PeriodicDomain& domain, std::int64_t r) {
  const std::size_t dims = static_cast<std::size_t>(cover.trajectories.dimension);
  std::array<std::int64_t, 3> lo{}, hi{};
  bool first = true;
  for (const kinetic::Trajectory& c : cover.trajectories.cells)
    for (const kinetic::GridPoint& p : c.positions) {
      for (std::size_t a = 0; a < dims; ++a) {
        lo[a] = first ? p[a] : std::min(lo[a], p[a]);
        hi[a] = first ? p[a] : std::max(hi[a], p[a]);
      }
      first = false;
    }
  if (first)
    return;
  std::int64_t spacing = 2 * r + 1;
  for (std::size_t a = 0; a < 3; ++a)
    if (domain.periodic[a])
      spacing = std::max(spacing, domain.period[a] / 4);
  std::array<std::int64_t, 3> count{}, step{};
  for (std::size_t a = 0; a < dims; ++a) {
    lo[a] -= 2 * r + 1;
    hi[a] += 2 * r + 1;
    count[a] = std::max<std::int64_t>(1, (hi[a] - lo[a]) / spacing);
    step[a] = (hi[a] - lo[a]) / count[a];
  }
  std::uint64_t state = 0;
  const auto jitter = [&](std::int64_t a) {
    return static_cast<std::int64_t>(next_random(state) %
                                     static_cast<std::uint64_t>(std::max<std::int64_t>(1, a)));
  };
  const std::size_t frames = cover.trajectories.frames();
  std::array<std::int64_t, 3> i{};
  for (i[0] = 0; i[0] <= count[0]; ++i[0])
    for (i[1] = 0; i[1] <= count[1]; ++i[1])
      for (i[2] = 0; i[2] <= (dims == 3 ? count[2] : 0); ++i[2]) {
        bool on_face = false;
        for (std::size_t a = 0; a < dims; ++a)
          on_face = on_face || i[a] == 0 || i[a] == count[a];
        if (!on_face)
          continue;
        kinetic::GridPoint p{0, 0, 0};
        for (std::size_t a = 0; a < dims; ++a) {
          const std::int64_t j = jitter(step[a] / 3);
          p[a] = i[a] == 0          ? lo[a] - j
                 : i[a] == count[a] ? hi[a] + j
                                    : lo[a] + i[a] * step[a] + j - step[a] / 6;
        }
        kinetic::Trajectory t;
        t.cell_id = -1;
        t.type = cover.trajectories.cells.front().type;
        t.positions.assign(frames, p);
        cover.trajectories.cells.push_back(std::move(t));
        CoverVertex v;
        v.original = -1;
        cover.vertices.push_back(v);
        ++cover.sentinels;
      }
}

} // namespace

int axis_too_short_for_radius(const io::PeriodicDomain& domain, const kinetic::SquaredRadius& rho2) {
  for (std::size_t a = 0; a < 3; ++a) {
    if (!domain.periodic[a])
      continue;
    // 4 rho < L  <=>  16 rho_g^2 < L_g^2  <=>  16 num < L_g^2 den (exact).
    const mpz_class period(static_cast<long>(domain.period[a]));
    if (16 * rho2.num >= period * period * rho2.den)
      return static_cast<int>(a);
  }
  return -1;
}

void check_periodic_radius(const io::PeriodicDomain& domain, const kinetic::SquaredRadius& rho2,
                           const std::string& radius_text) {
  const int a = axis_too_short_for_radius(domain, rho2);
  if (a >= 0)
    throw GeometryError("radius " + radius_text +
                        " is too large for the periodic lattice: 4 x radius must be below " + "the period " +
                        std::to_string(domain.lattice[static_cast<std::size_t>(a)]) + " along " +
                        char('x' + a) + " for the complex on the torus to be defined (docs/MATH.md §8.3)");
}

PeriodicCover cover_trajectories(const kinetic::Trajectories& originals, const io::PeriodicDomain& domain,
                                 const kinetic::SquaredRadius& rho2) {
  PeriodicCover cover;
  cover.trajectories = originals;
  cover.originals = originals.cells.size();
  cover.vertices.resize(cover.originals);
  for (std::size_t i = 0; i < cover.originals; ++i)
    cover.vertices[i].original = static_cast<kinetic::VertexId>(i);
  if (!domain.any())
    return cover;

  const std::size_t frames = originals.frames();
  const std::int64_t r = radius_ceiling(rho2);
  // The originals' box per frame (periodic axes) and the largest displacement per slab (any axis).
  std::vector<Box> box(frames);
  std::vector<std::int64_t> displacement(frames, 0);
  for (const kinetic::Trajectory& c : originals.cells)
    for (std::size_t k = c.first_frame; k <= c.last_frame(); ++k) {
      Box& b = box[k];
      for (std::size_t a = 0; a < 3; ++a) {
        b.lo[a] = b.empty ? c.at(k)[a] : std::min(b.lo[a], c.at(k)[a]);
        b.hi[a] = b.empty ? c.at(k)[a] : std::max(b.hi[a], c.at(k)[a]);
      }
      b.empty = false;
      if (k < c.last_frame())
        for (std::size_t a = 0; a < 3; ++a)
          displacement[k] = std::max(displacement[k], std::abs(c.at(k + 1)[a] - c.at(k)[a]));
    }
  std::int64_t widest_margin = 2 * r;
  for (std::size_t k = 0; k < frames; ++k)
    widest_margin = std::max(widest_margin, 2 * r + 2 * displacement[k]);

  std::vector<std::size_t> axes;
  for (std::size_t a = 0; a < 3; ++a)
    if (domain.periodic[a])
      axes.push_back(a);

  // Whether p + offset lies within `margin` of box b along every periodic axis.
  const auto near = [&](const kinetic::GridPoint& p, const std::array<std::int64_t, 3>& offset, const Box& b,
                        std::int64_t margin) {
    for (std::size_t a : axes) {
      const std::int64_t x = p[a] + offset[a] * domain.period[a];
      if (x < b.lo[a] - margin || x > b.hi[a] + margin)
        return false;
    }
    return true;
  };

  for (std::size_t i = 0; i < cover.originals; ++i) {
    const kinetic::Trajectory& c = originals.cells[i];
    // Candidate offsets per periodic axis: those that can reach the widest box at any frame.
    std::array<std::int64_t, 3> first{}, last{};
    for (std::size_t a : axes) {
      std::int64_t lo = std::numeric_limits<std::int64_t>::max(),
                   hi = std::numeric_limits<std::int64_t>::min();
      std::int64_t plo = lo, phi = hi;
      for (std::size_t k = c.first_frame; k <= c.last_frame(); ++k) {
        lo = std::min(lo, box[k].lo[a]);
        hi = std::max(hi, box[k].hi[a]);
        plo = std::min(plo, c.at(k)[a]);
        phi = std::max(phi, c.at(k)[a]);
      }
      first[a] = ceil_div(lo - widest_margin - phi, domain.period[a]);
      last[a] = floor_div(hi + widest_margin - plo, domain.period[a]);
    }
    std::array<std::int64_t, 3> offset{};
    // Odometer over the product of the candidate ranges.
    for (std::size_t a : axes)
      offset[a] = first[a];
    while (true) {
      const bool zero = offset[0] == 0 && offset[1] == 0 && offset[2] == 0;
      if (!zero) {
        std::vector<char> needed(frames, 0);
        for (std::size_t k = c.first_frame; k <= c.last_frame(); ++k) {
          if (near(c.at(k), offset, box[k], 2 * r))
            needed[k] = 1;
          if (k < c.last_frame() && near(c.at(k), offset, box[k], 2 * r + 2 * displacement[k]))
            needed[k] = needed[k + 1] = 1;
        }
        // Copies come and go at frames (insertions and deletions of the engine, far from every
        // original, docs/MATH.md §8.4). Keeping every copy for its original's whole life instead was
        // measured slower on the real periodic run (28.6 against 23.8 s for 8 frames): more copies,
        // more ties between the copies of one event.
        for (std::size_t k = c.first_frame; k <= c.last_frame();) {
          if (!needed[k]) {
            ++k;
            continue;
          }
          kinetic::Trajectory ghost;
          ghost.cell_id = c.cell_id;
          ghost.type = c.type;
          ghost.first_frame = k;
          for (; k <= c.last_frame() && needed[k]; ++k) {
            kinetic::GridPoint p = c.at(k);
            for (std::size_t a : axes)
              p[a] += offset[a] * domain.period[a];
            ghost.positions.push_back(p);
          }
          cover.trajectories.cells.push_back(std::move(ghost));
          CoverVertex v;
          v.original = static_cast<kinetic::VertexId>(i);
          v.offset = offset;
          cover.vertices.push_back(v);
        }
      }
      std::size_t j = 0;
      for (; j < axes.size(); ++j) {
        const std::size_t a = axes[j];
        if (offset[a] < last[a]) {
          ++offset[a];
          break;
        }
        offset[a] = first[a];
      }
      if (j == axes.size())
        break;
    }
  }
  add_sentinels(cover, domain, r);
  if (cover.vertices.size() > static_cast<std::size_t>(std::numeric_limits<kinetic::VertexId>::max()))
    throw GeometryError("too many cells with their periodic copies for 32-bit vertex ids");
  return cover;
}

} // namespace medusa::periodic
