#pragma once
// What the peridynamic models (PMB, LPS) share: parameters, particle attributes, bonds
// within the horizon built from reference positions, the partial-volume weight of bonds
// near the horizon, supports and applied loads (for the engine's integrator), damage and
// energies.
// A concrete model adds its bond constants (setupBonds) and its force kernel.
//
// Units are any consistent set (SI in the examples). Attributes:
//   fixed  X Y Z  bc_x bc_y bc_z  fx fy fz  volume
//          bc_a = 1: the velocity along a is prescribed (kept at its initial value; 0 = a
//          support); fx fy fz: applied force on the particle (not a force density)
//   alter  x y z  vx vy vz  [model columns]   velocities (half-step ones after step 0)
//   integ  ax ay az                           acceleration from the bonds
//   bond   xi  weight  [model columns]        reference length |ξ|, and the bond's
//                                             constant, 0 once the bond has broken
// A pre-crack (`notch`, segments X1 Y1 X2 Y2 in the XY plane, through the thickness in
// 3D) removes the bonds whose reference segment crosses it.
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/packed_positions.hpp"

namespace pdq::peri {

class PeriModel : public Model {
 public:
  enum Fixed { BCX = 3, BCY, BCZ, FX, FY, FZ, VOLUME };
  enum Alter { X = 0, Y, Z, VX, VY, VZ };
  enum Integ { AX = 0, AY, AZ };
  enum Bond { XI = 0, WEIGHT };

  void configure(const Params& p) final;
  Schema schema() const final;
  double horizon() const final { return delta_; }
  // Bonds are the only neighbours after setup.
  bool resultsDependOnCells() const final { return false; }
  bool forcesFromBonds() const final { return true; }
  void setup(Context& ctx) final;
  void prepare(Context& ctx) final;
  Motion motion() const final;
  void bodies(const Context& ctx, std::span<Body> owned) const final;

  std::vector<std::string> fields() const override { return {"damage", "energy_density"}; }
  void field(const Context& ctx, int k, std::span<double> out) const override;
  std::vector<std::string> globals() const override;
  std::vector<double> globalValues(Context& ctx) override;

 protected:
  // Reads the model's own parameters (after the shared ones).
  virtual void configureModel(const Params&) {}
  virtual std::vector<std::string> alterExtra() const { return {}; }
  virtual std::vector<std::string> bondExtra() const { return {}; }
  // Fills the bond constants once the bonds exist (in prepare, after a restart has put back
  // the bonds' state). XI is already set; `volume[b]` is the partner's volume times the
  // bond's partial-volume weight, 0 for a bond that a restart says is broken.
  virtual void prepareBonds(Context& ctx, const std::vector<double>& volume) = 0;
  // Elastic energy of owned particle i at the current positions (energy density × volume).
  virtual double particleEnergy(const Context& ctx, std::size_t i) const = 0;
  // True when the bond's reference segment crosses the notch (it is never created).
  bool cutByNotch(const double* Xi, const double* Xj) const;

  // `width` values per owned particle, extended to every local particle (owned and ghosts).
  static std::vector<double> onGhosts(Context& ctx, const std::vector<double>& owned,
                                      int width = 1);
  // The positions the kernels read (every local particle's, rows of PackedPositions::kRow).
  PackedPositions packed_;

  double E_ = 0, nu_ = 0, delta_ = 0, thickness_ = 1, density_ = 0, dt_ = 0;
  double criticalStretch_ = 0, damping_ = 0, spacing_ = 0;
  std::vector<double> notch_;  // pre-cracks: X1 Y1 X2 Y2 per segment (in the XY plane)
  int dim_ = 3;                // from the particles, known in setup
};

// Weight of a bond of reference length r0 in a horizon delta on a lattice of the given
// spacing: the fraction of the partner's cell inside the horizon, linear over the last
// half spacing (the convention of LAMMPS's PERI package); 1 when spacing is 0.
double partialVolume(double r0, double delta, double spacing);
// Bond-based micromodulus c (force per volume squared per unit stretch) giving Young's
// modulus E: 3D c = 12 E / (π δ⁴) (ν = 1/4); 2D plane stress of thickness t
// c = 9 E / (π t δ³) (ν = 1/3).
double pmbMicromodulus(int dim, double E, double delta, double thickness);

}  // namespace pdq::peri
