#pragma once
// Strength searches (`pdq strength`): the load at which a structure stops reaching
// static equilibrium (thesis §4.4) is model-specific, so each model that offers one
// registers a driver under its model name in one line:
//
//     PDQ_REGISTER_STRENGTH(mplmStrength, "mplm2d", "bisection on hold-phase equilibrium");
//
// with `void mplmStrength(Scenario& scenario, const Params& options, Comm& comm)`: it runs
// its trials from the scenario on every rank and prints its report on rank 0. `options`
// holds the command line's `--set key=value` items; unknown ones are errors afterwards.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/comm.hpp"
#include "engine/params.hpp"
#include "scenario/scenario.hpp"

namespace pdq {

class StrengthRegistry {
 public:
  using Driver = std::function<void(Scenario&, const Params&, Comm&)>;
  static bool add(const std::string& model, const std::string& description, Driver d);
  // Throws InputError (naming `source`) when the model has no strength driver.
  static const Driver& get(const std::string& model, const std::string& source = "");
  static std::vector<std::pair<std::string, std::string>> list();  // model, description
};

}  // namespace pdq

#define PDQ_REGISTER_STRENGTH(function, model, description)                                  \
  static const bool pdq_strength_##function [[maybe_unused]] = ::pdq::StrengthRegistry::add( \
      model, description,                                                                    \
      [](::pdq::Scenario& s, const ::pdq::Params& p, ::pdq::Comm& c) { function(s, p, c); })
