// meeting_in_slab (collision.h, docs/MATH.md §2.5): two cells at one position inside a slab, decided in
// integers. Each case is worked out by hand: p(u) - q(u) = da + u db per coordinate.
#include "collision.h"

#include <catch2/catch.hpp>

#include <optional>

using medusa::kinetic::meeting_in_slab;
using medusa::kinetic::MeetingTime;
using medusa::kinetic::MovingPoint;

namespace {
__extension__ typedef __int128 Int128; // the cross-multiplied fractions below exceed 64 bits

MovingPoint moving(std::int64_t ax, std::int64_t ay, std::int64_t az, std::int64_t bx, std::int64_t by,
                   std::int64_t bz) {
  return MovingPoint{{ax, ay, az}, {bx, by, bz}};
}
// u as a reduced comparison: num / den == n / d.
bool at(const std::optional<MeetingTime>& m, std::int64_t n, std::int64_t d) {
  return m && m->den > 0 && static_cast<Int128>(m->num) * d == static_cast<Int128>(n) * m->den;
}
} // namespace

TEST_CASE("two cells crossing each other meet at the time their differences vanish together",
          "[kinetic][collision]") {
  // p from (0, 0, 0) by (4, 2, 0); q from (3, 3, 0) by (-2, -4, 0): da = (-3, -3, 0), db = (6, 6, 0),
  // both coordinates vanish at u = 1/2.
  const MovingPoint p = moving(0, 0, 0, 4, 2, 0), q = moving(3, 3, 0, -2, -4, 0);
  CHECK(at(meeting_in_slab(p, q), 1, 2));
  CHECK(at(meeting_in_slab(q, p), 1, 2)); // symmetric, whatever the sign of db
}

TEST_CASE("two cells whose coordinates vanish at different times never meet", "[kinetic][collision]") {
  // da = (-3, -1, 0), db = (6, 6, 0): x at u = 1/2, y at u = 1/6.
  CHECK_FALSE(meeting_in_slab(moving(0, 0, 0, 4, 2, 0), moving(3, 1, 0, -2, -4, 0)));
}

TEST_CASE("a meeting at a slab end is not inside the slab", "[kinetic][collision]") {
  // da = (-6, 0, 0), db = (6, 0, 0): u = 1 exactly; da = (0, 0, 0) with db != 0: u = 0 exactly.
  CHECK_FALSE(meeting_in_slab(moving(0, 0, 0, 6, 0, 0), moving(6, 0, 0, 0, 0, 0)));
  CHECK_FALSE(meeting_in_slab(moving(5, 5, 5, 1, 0, 0), moving(5, 5, 5, 0, 0, 0)));
}

TEST_CASE("cells apart in a coordinate they do not move in never meet", "[kinetic][collision]") {
  // Same x motion towards each other, but z differs by 1 for the whole slab.
  CHECK_FALSE(meeting_in_slab(moving(0, 0, 0, 2, 0, 0), moving(1, 0, 1, 0, 0, 0)));
}

TEST_CASE("cells moving apart or not far enough never meet", "[kinetic][collision]") {
  CHECK_FALSE(meeting_in_slab(moving(0, 0, 0, -2, 0, 0), moving(1, 0, 0, 0, 0, 0))); // apart
  CHECK_FALSE(meeting_in_slab(moving(0, 0, 0, 1, 0, 0), moving(3, 0, 0, 0, 0, 0)));  // u = 3
}

TEST_CASE("a meeting in the plane and one near the grid's limit are exact", "[kinetic][collision]") {
  // Planar cells (z equal and still): u = 2/7.
  CHECK(at(meeting_in_slab(moving(0, 0, 9, 7, 0, 0), moving(2, 0, 9, 0, 0, 0)), 2, 7));
  // Coordinates near 2^40: the cross products need 128 bits. da = (-2^40, -2^39, 0),
  // db = (2^41 - 2, 2^40 - 1, 0): both vanish at u = 2^40 / (2^41 - 2).
  const std::int64_t big = std::int64_t(1) << 40;
  const MovingPoint p = moving(0, 0, 0, 2 * big - 2, big - 1, 0), q = moving(big, big / 2, 0, 0, 0, 0);
  CHECK(at(meeting_in_slab(p, q), big, 2 * big - 2));
  // One unit off in y: the y coordinate vanishes at another time, so they miss each other.
  CHECK_FALSE(meeting_in_slab(p, moving(big, big / 2 + 1, 0, 0, 0, 0)));
}
