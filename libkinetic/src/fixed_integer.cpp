#include "fixed_integer.h"

#include <array>
#include <cstdint>
#include <stdexcept>

namespace medusa::kinetic {

mpz_class to_mpz(Int128 x) {
  __extension__ typedef unsigned __int128 UInt128;
  const bool negative = x < 0;
  const auto magnitude = static_cast<UInt128>(negative ? -x : x);
  mpz_class r(static_cast<unsigned long>(magnitude >> 64));
  r <<= 64;
  r += static_cast<unsigned long>(magnitude & ~std::uint64_t{0});
  return negative ? mpz_class(-r) : r;
}

mpz_class to_mpz(const FixedInt& x) {
  const auto& limbs = x.backend();
  mpz_class r;
  mpz_import(r.get_mpz_t(), limbs.size(), -1, sizeof(*limbs.limbs()), 0, 0, limbs.limbs());
  return x.sign() < 0 ? mpz_class(-r) : r;
}

FixedInt to_fixed(const mpz_class& x) {
  if (x == 0)
    return 0;
  if (mpz_sizeinbase(x.get_mpz_t(), 2) > 512)
    throw std::overflow_error("more than 512 bits");
  std::array<std::uint64_t, 8> words{};
  std::size_t count = 0;
  mpz_export(words.data(), &count, -1, sizeof(std::uint64_t), 0, 0, x.get_mpz_t());
  FixedInt r;
  boost::multiprecision::import_bits(r, words.begin(), words.begin() + static_cast<std::ptrdiff_t>(count), 64,
                                     false);
  return sgn(x) < 0 ? FixedInt(-r) : r;
}

} // namespace medusa::kinetic
