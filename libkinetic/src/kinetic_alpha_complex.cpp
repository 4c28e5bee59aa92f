// The public API of the kinetic alpha complex: the exact squared radius from a decimal, and the
// pimpl forwarding to the engine (engine.h, engine_*.cpp). docs/MATH.md sections are cited where each
// rule is applied.
#include "medusa/kinetic/kinetic_alpha_complex.h"

#include "engine.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <variant>

namespace medusa::kinetic {

SquaredRadius squared_radius_from_decimal(const std::string& rho, std::int64_t scale) {
  // rho = digits[.digits]; rho_g = S rho = N / 10^d exactly, rho_g^2 = N^2 / 10^(2d).
  std::size_t dot = rho.find('.');
  std::string digits = rho.substr(0, dot);
  std::string fraction = dot == std::string::npos ? "" : rho.substr(dot + 1);
  if ((digits.empty() && fraction.empty()) || rho.find_first_not_of("0123456789.") != std::string::npos ||
      std::count(rho.begin(), rho.end(), '.') > 1)
    throw InputError("radius '" + rho + "' is not a positive decimal number");
  mpz_class n(digits.empty() ? "0" : digits);
  mpz_class den = 1;
  for (char c : fraction) {
    n = n * 10 + (c - '0');
    den *= 10;
  }
  if (n == 0)
    throw InputError("radius must be positive, got '" + rho + "'");
  n *= scale;
  mpz_class g = gcd(n, den);
  n /= g;
  den /= g;
  return {n * n, den * den};
}

// The engine of the run's dimension (kinetic_traits.h); any dimension but 2 takes the 3D engine,
// whose run rejects it (Trajectories::validate).
struct KineticAlphaComplex::Impl {
  Impl(const Trajectories& t, KineticOptions o)
      : engine(t.dimension == 2 ? Engines(std::in_place_index<0>, t, std::move(o))
                                : Engines(std::in_place_index<1>, t, std::move(o))) {}
  using Engines =
      std::variant<detail::Engine<detail::KineticTraits2>, detail::Engine<detail::KineticTraits3>>;
  Engines engine;
};

KineticAlphaComplex::KineticAlphaComplex(const Trajectories& trajectories, KineticOptions options)
    : impl_(std::make_unique<Impl>(trajectories, std::move(options))) {}

KineticAlphaComplex::~KineticAlphaComplex() = default;

void KineticAlphaComplex::run(Observer& observer) {
  std::visit([&](auto& e) { e.run(observer); }, impl_->engine);
}

const KineticStatistics& KineticAlphaComplex::statistics() const {
  return std::visit([](const auto& e) -> const KineticStatistics& { return e.statistics(); }, impl_->engine);
}

std::vector<Simplex> KineticAlphaComplex::current_complex() const {
  return std::visit([](const auto& e) { return e.current_complex(); }, impl_->engine);
}

} // namespace medusa::kinetic
