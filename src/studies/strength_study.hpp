#pragma once
// `pdq strength scenario.toml`: the strength search (studies/strength.hpp) of any scenario
// whose model declares a StrengthSpec. The [strength] table and --set items are the
// search's options (docs/scenario.md), [strength.model] the trials' model parameters.
// Prints each trial as it ends and the result beside the textbook value of the specimen
// (studies/reference.hpp) and the scenario's `reference`, and writes <output>/strength/:
// strength.txt (the report), trials.csv, journal.txt, and trial_NN/ with each trial's
// load-displacement history and final restart files (for `pdq post picture`).
#include "engine/comm.hpp"
#include "engine/params.hpp"
#include "scenario/scenario.hpp"
#include "studies/strength.hpp"

namespace pdq {

// The trials' problem: the scenario's, with [strength.model] over its [model] (checked, so
// that a wrong key is named at its line before any trial), its loads in the unit of the
// specimen's reference (studies/reference.hpp). InputError if the model has no strength spec.
strength::Case strengthCase(const Scenario& sc);

// `options`: the [strength] table with --set items; unknown ones are errors before any trial.
// Finished trials are recorded in <output>/strength/journal.txt (studies/strength_journal.hpp);
// `resume` continues the search recorded there without running them again (`force`: even
// one of another scenario or other options).
void strengthStudy(const Scenario& sc, const Params& options, Comm& comm, bool resume = false,
                   bool force = false);

}  // namespace pdq
