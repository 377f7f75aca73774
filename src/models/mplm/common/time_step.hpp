#pragma once
// The MPLM's report of its time step against the stable one (engine/frequency.hpp).
#include "engine/context.hpp"

namespace pdq::mplm {

// Logs the frequency and the steps, tells the engine the stable step (named in its
// instability messages), and warns (on standard error through the pdq command) when the
// time step in use exceeds the stable one.
void reportTimeStep(Context& ctx, const char* model, double omegaMax, double stable,
                    double thesisDt);

}  // namespace pdq::mplm
