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
