#pragma once
// Building blocks for MPLM problems: concrete lattices, steel bars, supports, loads and
// monitored particles written into the fixed attributes of a ParticleSet.
#include <array>
#include <functional>
#include <vector>

#include "engine/particle_set.hpp"
#include "prep/rebar.hpp"

namespace pdq::mplm {

// An empty set in the MPLM attribute widths.
ParticleSet newParticleSet();

// Appends concrete particles at the points (global IDs continue from the set's size).
void addConcrete(ParticleSet& ps, const std::vector<std::array<double, 2>>& points);
// Appends steel particles of bar `barId` at the points, of the bar's section, in the
// widths of either dimension's set (the steel columns are shared); every other one (the
// first included) links to concrete. `count` > 1: one line of particles for that many
// equal bars side by side (a 2D layer): their area and second moment summed.
void addSteel(ParticleSet& ps, const std::vector<prep::Point>& points,
              const prep::BarSection& section, int barId, int count = 1);
// A straight bar's steel particles (prep::barPoints).
void addBar(ParticleSet& ps, const prep::Bar& bar, double s, int barId, int count = 1);
// Appends a steel plate as bar `barId` at the points: every particle bonded to the concrete
// within one spacing, of the given section area and second moment.
void addPlate(ParticleSet& ps, const std::vector<prep::Point>& points, double area,
              double secondMoment, int barId);

// Indices of the particles whose fixed row satisfies `pick`.
std::vector<std::size_t> select(const ParticleSet& ps,
                                const std::function<bool(const double*)>& pick);

// Constrains DOFs (Constraint bits) of the particles, with prescribed peak values.
void constrain(ParticleSet& ps, const std::vector<std::size_t>& idx, int bits,
               std::array<double, 3> peak = {0, 0, 0});
// Adds a peak external force (and moment) to each particle.
void load(ParticleSet& ps, const std::vector<std::size_t>& idx, double fx, double fy, double m = 0);
// Distributes a total force over the particles as a uniform traction would: each gets the
// share of its tributary length along `axis` (0 = X, 1 = Y) within its layer (particles
// with equal other coordinate), the layer's ends extended to [lo, hi]. End particles of a
// layer thus carry less than interior ones, as nodal loads of a uniform traction do.
void loadUniform(ParticleSet& ps, const std::vector<std::size_t>& idx, int axis, double lo,
                 double hi, double totalFx, double totalFy);
void monitor(ParticleSet& ps, const std::vector<std::size_t>& idx);

// Concrete particles only, and the largest coordinate along an axis.
bool isConcrete(const double* fixedRow);
double maxCoord(const ParticleSet& ps, int axis);

}  // namespace pdq::mplm
