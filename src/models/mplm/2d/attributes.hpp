#pragma once
// The attributes of an MPLM particle and interaction, shared by the model and the
// generators that fill a ParticleSet for it (src/prep/hexagonal, src/prep/rebar).
#include "engine/schema.hpp"
#include "models/mplm/common/attributes.hpp"

namespace pdq::mplm {

// Fixed attributes (never change; sent only when a ghost is created): the shared ones
// (models/mplm/common/attributes.hpp), then
enum Fixed {
  LOAD_X = N_SHARED_FIXED,
  LOAD_Y,
  LOAD_M,  // peak external force (N) and moment (N·m) on the particle
  DISP_X,
  DISP_Y,
  DISP_T,   // peak prescribed displacement/rotation of constrained DOFs
  MONITOR,  // 1: part of the displacement reported in the history
  N_FIXED
};
// Alterable attributes: everything a neighbour reads (damping needs the velocities).
enum Alter { AX = 0, AY, AZ, VX, VY, THETA, OMEGA, N_ALTER };
// Per-step scratch of owned particles.
enum Integ { FORCE_X = 0, FORCE_Y, MOMENT, N_INTEG };
// Bits of CONSTRAINT: 1 = u_x, 2 = u_y, 4 = θ_z prescribed.
// REST_Y: the particle rests on a support (a bearing): it cannot go below its reference
// Y but may lift off, and the support pushes only (unilateral contact).
enum Constraint { FIX_X = 1, FIX_Y = 2, FIX_T = 4, REST_Y = 8 };

inline Schema schema() {
  return Schema::make(
      fixedNames({"load_x", "load_y", "load_m", "disp_x", "disp_y", "disp_t", "monitor"}),
      {"vx", "vy", "theta", "omega"}, {"fx", "fy", "mz"}, bondNames());
}

}  // namespace pdq::mplm
