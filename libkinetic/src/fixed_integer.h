// Fixed-width exact integers and their conversions to GMP. Int128: a double's significand times a
// slab's span (reported times). FixedInt: integers of at most 512 bits kept in place, for the exact
// certificate polynomials that event times need (KeyPolynomial): the polynomials of CompuCell3D lattices take
// 101 to 271 bits (docs/MATH.md §1.5), and GMP allocates for every intermediate value, which made it half of
// the cost of rounding a time exactly. A value that would need more bits throws std::overflow_error (Boost's
// checked arithmetic), and the caller computes in GMP instead: the fixed width decides speed, never results.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <gmpxx.h>

namespace medusa::kinetic {

using FixedInt = boost::multiprecision::number<
    boost::multiprecision::cpp_int_backend<512, 512, boost::multiprecision::signed_magnitude,
                                           boost::multiprecision::checked, void>,
    boost::multiprecision::et_off>;

__extension__ typedef __int128 Int128; // GCC and Clang

mpz_class to_mpz(Int128 x);
mpz_class to_mpz(const FixedInt& x);
// std::overflow_error when x needs more than 512 bits.
FixedInt to_fixed(const mpz_class& x);

} // namespace medusa::kinetic
