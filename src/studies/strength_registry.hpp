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
#include "engine/registry.hpp"
#include "scenario/scenario.hpp"

namespace pdq {

using StrengthDriver = std::function<void(Scenario&, const Params&, Comm&)>;
// Keyed by model name; get() throws InputError when the model has no strength driver.
using StrengthRegistry = Registry<StrengthDriver>;
template <>
Registry<StrengthDriver>::Table& Registry<StrengthDriver>::table();

}  // namespace pdq

#define PDQ_REGISTER_STRENGTH(function, model, description)                                  \
  static const bool pdq_strength_##function [[maybe_unused]] = ::pdq::StrengthRegistry::add( \
      model, description,                                                                    \
      [](::pdq::Scenario& s, const ::pdq::Params& p, ::pdq::Comm& c) { function(s, p, c); })
