#pragma once
// Scenario generators for MPLM specimens (docs/scenario.md lists their keys):
//
//     [particles]
//     generator = "mplm_beam"     # or "mplm_plate"
//     span = 1.16                 # ...
//
// The lattice spacing and thickness are the model's (`spacing`, `thickness` in [model]),
// so particles and interactions can never disagree on them.
#include "engine/params.hpp"
#include "prep/mplm/examples.hpp"

namespace pdq::mplm {

// The specimen a generator table describes (InputError naming the key's line when a value
// is out of range).
PlateSpec plateSpec(const Params& generator, const Params& model);
BeamSpec beamSpec(const Params& generator, const Params& model);

}  // namespace pdq::mplm
