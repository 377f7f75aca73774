#pragma once
// Particle generators: a scenario's [particles] table names one (`generator = "square"`)
// and gives its parameters; the generator fills every particle in the model's schema.
// A generator registers itself by name in one line, like a model:
//
//     PDQ_REGISTER_GENERATOR(myLattice, "mylattice", "what it builds");
//
// where `Generated myLattice(const Params& p, const Schema& schema)` reads its
// parameters from `p` (unknown ones are reported afterwards) and returns the particles
// with nFixed/nAlter set to the schema's widths. A generator that must agree with the
// model (its lattice spacing, its thickness) takes the [model] table as a third argument,
// `Generated f(const Params& p, const Schema& schema, const Params& model)`, and reads the
// model's values from there rather than asking for them twice.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "engine/registry.hpp"
#include "engine/schema.hpp"

namespace pdq {

struct Generated {
  ParticleSet particles;
  // The box a periodic crystal fills (e.g. fcc): a scenario's periodic axes take their
  // box from here unless [decomposition] gives box_lo/box_hi.
  std::optional<std::array<double, 3>> boxLo, boxHi;
};

using Generator = std::function<Generated(const Params&, const Schema&, const Params& model)>;
using GeneratorRegistry = Registry<Generator>;
template <>
Registry<Generator>::Table& Registry<Generator>::table();

// What a generator would make, from its parameters alone, without making it (`pdq info`
// on a problem too large for the machine): how many particles, the box they fill and the
// lattice they sit on, from which the pairs within a model's horizon are counted.
struct SizeEstimate {
  double particles = 0;                          // on the lattice
  std::array<double, 3> lo{}, hi{};              // the lattice's bounding box
  std::array<double, 3> stride{};                // between the lattice's sites along each axis
  std::vector<std::array<double, 3>> primitive;  // the lattice's vectors, one per dimension
  // Particles and interactions beside the lattice's pairs (an MPLM member's steel).
  double extraParticles = 0, extraPairs = 0;

  // Pairs of sites within `r` of each other: each site's neighbours within r, fewer near
  // the faces (an offset d has a partner for the share prod_a (1 - |d_a| / L_a) of the
  // sites, L_a the extent the sites fill along axis a: exact for a box of a simple
  // lattice).
  double pairsWithin(double r) const;
};
using GeneratorEstimate = std::function<SizeEstimate(const Params&, const Params& model)>;
using EstimateRegistry = Registry<GeneratorEstimate>;
template <>
Registry<GeneratorEstimate>::Table& Registry<GeneratorEstimate>::table();

namespace detail {
// Calls a generator with or without the [model] table, whichever it takes.
template <class F>
Generated callGenerator(F f, const Params& p, const Schema& s, const Params& model) {
  if constexpr (std::is_invocable_v<F, const Params&, const Schema&, const Params&>)
    return f(p, s, model);
  else
    return f(p, s);
}
}  // namespace detail

}  // namespace pdq

#define PDQ_REGISTER_GENERATOR(function, name, description)                                    \
  static const bool pdq_generator_##function [[maybe_unused]] = ::pdq::GeneratorRegistry::add( \
      name, description,                                                                       \
      [](const ::pdq::Params& p, const ::pdq::Schema& s, const ::pdq::Params& m) {             \
        return ::pdq::detail::callGenerator(function, p, s, m);                                \
      })

// Registers the size estimate of the generator `name`, e.g.
//     PDQ_REGISTER_ESTIMATE(myLatticeSize, "mylattice");
// with `SizeEstimate myLatticeSize(const Params& p, const Params& model)`.
#define PDQ_REGISTER_ESTIMATE(function, name)                                                \
  static const bool pdq_estimate_##function [[maybe_unused]] = ::pdq::EstimateRegistry::add( \
      name, "size estimate",                                                                 \
      [](const ::pdq::Params& p, const ::pdq::Params& m) { return function(p, m); })
