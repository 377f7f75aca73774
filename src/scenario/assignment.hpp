#pragma once
// Attribute values by region, a scenario's [[particles.set]] entries: after the particles
// are generated or read, each entry sets one fixed or alterable attribute (beyond the
// positions) of the particles it selects to
//     value + gradient · X        (X the reference position)
// selecting by reference-position ranges (x, y, z = [lo, hi], inclusive) and/or IDs.
// Entries apply in file order, so a later one overrides an earlier one.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "engine/schema.hpp"

namespace pdq {

// Particles selected by reference-position ranges and/or IDs (also the quasi-static
// solver's displacement control, [solver.control]).
struct Selection {
  std::array<std::optional<std::pair<double, double>>, 3> range;
  std::vector<Gid> ids;  // sorted; empty: any ID
  bool selects(const double* X, Gid id) const;
  // The IDs of the particles selected, sorted.
  std::vector<Gid> selected(const ParticleSet& particles) const;
};

// Reads the selection keys x, y, z (ranges) and ids of an entry.
Selection readSelection(const Params& entry, const std::string& file);

struct Assignment {
  std::string attribute;
  double value = 0;
  std::array<double, 3> gradient{0, 0, 0};
  Selection where;
  std::string file;  // where the entry was written
  int line = 0, attributeLine = 0;
};

// Reads one entry's keys (attribute, value, gradient, x, y, z, ids); unknown keys are
// errors at their line.
Assignment readAssignment(const Params& entry, const std::string& file, int line);

// Throws InputError at the entry's line for an unknown attribute (suggesting the nearest
// name), a position column, or an entry that selects no particle. Returns how many
// particles each entry selected, in order.
std::vector<std::size_t> applyAssignments(ParticleSet& particles, const Schema& schema,
                                          const std::vector<Assignment>& entries);

}  // namespace pdq
