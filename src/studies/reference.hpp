#pragma once
// What a strength report puts beside pdq's strength, computed from the scenario that made
// the specimen (its generator's table and the model's parameters): the unit loads are
// given in (what load_scale = 1 means) and, when the specimen has one, a textbook value
// (ACI 318 for a reinforced concrete beam, f_t for a plate in tension, ...). Each
// generator that knows its specimen's unit or textbook value has a function here
// (reference.cpp lists them); particles from files or other generators are loaded in
// units of load_scale, with no textbook value.
#include <string>

#include "scenario/scenario.hpp"

namespace pdq {

struct Reference {
  std::string unit = "x load_scale";  // the unit strengths are reported in
  double unitLoad = 1;                // the load, in `unit`, at load_scale = 1
  double value = 0;                   // the textbook strength, in `unit` (0: none)
  std::string label;                  // "ACI 318" or "classical"
  std::string mode;                   // its failure mode: flexural, shear, tension, ...
};

// `model` is the scenario's [model] table with any overrides the trials use.
Reference referenceFor(const Scenario& sc, const Params& model);

}  // namespace pdq
