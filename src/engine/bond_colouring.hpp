#pragma once
// A distance-2 colouring of the bond graph: no two particles of one colour are bonded to
// each other or to a common partner. Moving every particle of one colour at once, the
// force change at a particle whose forces come from its bonds alone comes from one moved
// particle at most (itself or one partner): the quasi-static solver's stiffness probes
// (engine/relaxation.cpp) take a handful of colours where the cells' colouring needs dozens
// (Curtis, Powell & Reid 1974).
#include <vector>

namespace pdq {

class Context;

// Collective: each owned particle's colour (0, 1, ...), greedy in global-ID order on rank 0
// over every bond, alive or not, so the same colours on any number of ranks; `count` is
// set to the number of colours.
std::vector<long> bondColours(Context& ctx, long& count);

}  // namespace pdq
