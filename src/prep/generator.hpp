#pragma once
// Particle generators: a scenario's [particles] table names one (`generator = "square"`)
// and gives its parameters; the generator fills every particle in the model's schema.
// A generator registers itself by name in one line, like a model:
//
//     PDQ_REGISTER_GENERATOR(myLattice, "mylattice", "what it builds");
//
// where `Generated myLattice(const Params& p, const Schema& schema)` reads its
// parameters from `p` (unknown ones are reported afterwards) and returns the particles
// with nFixed/nAlter set to the schema's widths.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "engine/schema.hpp"

namespace pdq {

struct Generated {
  ParticleSet particles;
  // The box a periodic crystal fills (e.g. fcc): a scenario's periodic axes take their
  // box from here unless [decomposition] gives box_lo/box_hi.
  std::optional<std::array<double, 3>> boxLo, boxHi;
};

class GeneratorRegistry {
 public:
  using Generator = std::function<Generated(const Params&, const Schema&)>;
  static bool add(const std::string& name, const std::string& description, Generator g);
  // Throws InputError (naming `source` and `line`) for an unknown name, suggesting the
  // nearest and listing the known ones.
  static const Generator& get(const std::string& name, const std::string& source = "",
                              int line = 0);
  static std::vector<std::pair<std::string, std::string>> list();  // name, description
};

}  // namespace pdq

#define PDQ_REGISTER_GENERATOR(function, name, description)                                    \
  static const bool pdq_generator_##function [[maybe_unused]] = ::pdq::GeneratorRegistry::add( \
      name, description,                                                                       \
      [](const ::pdq::Params& p, const ::pdq::Schema& s) { return function(p, s); })
