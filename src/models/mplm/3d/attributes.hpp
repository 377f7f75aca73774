#pragma once
// The attributes of a 3D MPLM particle and interaction, shared by the model and the
// generators that fill a ParticleSet for it. Six degrees of freedom: the position and the
// orientation of the particle's triad, a unit quaternion (engine/rotation.hpp; generators
// leave it zero, which the model reads as the reference orientation).
#include "engine/schema.hpp"
#include "models/mplm/common/attributes.hpp"

namespace pdq::mplm3d {

using namespace mplm::attributes;

// Fixed attributes (never change; sent only when a ghost is created): the shared ones
// (models/mplm/common/attributes.hpp), then
enum Fixed {
  LOAD_X = N_SHARED_FIXED,  // peak external force (N), then moment (N·m), on the particle
  LOAD_Y,
  LOAD_Z,
  LOAD_MX,
  LOAD_MY,
  LOAD_MZ,
  DISP_X,  // peak prescribed displacement (m), then rotation (rad), of constrained DOFs
  DISP_Y,
  DISP_Z,
  DISP_RX,
  DISP_RY,
  DISP_RZ,
  MONITOR,  // 1: part of the displacement reported in the history
  N_FIXED
};
// Alterable attributes: everything a neighbour reads (damping needs the velocities); the
// angular velocity is in the global frame.
enum Alter { AX = 0, AY, AZ, VX, VY, VZ, QW, QX, QY, QZ, WX, WY, WZ, N_ALTER };
// Per-step scratch of owned particles: force, then moment.
enum Integ { FORCE_X = 0, FORCE_Y, FORCE_Z, MOMENT_X, MOMENT_Y, MOMENT_Z, N_INTEG };
// Bits of CONSTRAINT: bit d (d = 0..5) prescribes DOF d (u_x, u_y, u_z, θ_x, θ_y, θ_z).
// REST_Y: the particle rests on a bearing: it cannot go below its reference Y but may lift
// off (unilateral support).
enum Constraint {
  FIX_X = 1,
  FIX_Y = 2,
  FIX_Z = 4,
  FIX_RX = 8,
  FIX_RY = 16,
  FIX_RZ = 32,
  FIX_ALL = 63,
  REST_Y = 64
};

inline Schema schema() {
  return Schema::make(
      fixedNames({"load_x", "load_y", "load_z", "load_mx", "load_my", "load_mz", "disp_x", "disp_y",
                  "disp_z", "disp_rx", "disp_ry", "disp_rz", "monitor"}),
      {"vx", "vy", "vz", "qw", "qx", "qy", "qz", "wx", "wy", "wz"},
      {"fx", "fy", "fz", "mx", "my", "mz"}, bondNames());
}

}  // namespace pdq::mplm3d
