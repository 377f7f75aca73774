#pragma once
// The engine's time integrator, used by every model that does not override
// Model::integrate: velocity Verlet in its leapfrog form for translations and rotations,
//     v(n+½) = v(n−½) + a(n) Δt,   x(n+1) = x(n) + v(n+½) Δt,
// started right: the first step of a run kicks by half a step, v(½) = v(0) + a(0) Δt/2, so
// a run from given positions and velocities (at rest, or not) follows velocity Verlet
// exactly, loads acting from step 0 included (LAMMPS's fix nve). The stored velocities are
// therefore the half-step ones, except at step 0; a restarted run (first step > 0) reads
// them as such.
//
// What a model declares (Model::motion, Model::bodies):
//   * Motion: which alterable columns hold positions and velocities and which integ columns
//     the forces, by name, and how rotations are stored: none; Planar (2D: one angle θ_z, its
//     rate ω_z and the moment m_z); or Spatial (3D: a unit quaternion qw qx qy qz, the angular
//     velocity ωx ωy ωz in the global frame, and the moments mx my mz). A spatial orientation
//     turns by the exact rotation of the step's increment, q(n+1) = exp(ω(n+½) Δt) ⊗ q(n),
//     renormalised (engine/rotation.hpp), so rotations of any size compose exactly; the
//     moments are those conjugate to such turns about the global axes.
//   * Body per owned particle: mass, rotational inertia (isotropic, so a free rotation obeys
//     dω/dt = M/I with no gyroscopic term), and per degree of freedom (translations first,
//     then rotations) its constraint, its peak external load and its peak prescribed value.
// Every external load and prescribed value follows the load protocol (Loading, owned by the
// engine and set in the scenario's [loading] table): peak × factor(t), in simulated time.
// Damping is mass-proportional: a −= c v, c = Motion::damping, plus 2 ζ_h ω₁ once the loads
// are held (Loading::holdDampingRatio, ω₁ the Rayleigh frequency of the deflection under
// the held loads, computed once and saved in restart files).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/bonds.hpp"
#include "engine/params.hpp"
#include "engine/schema.hpp"
#include "engine/stiffness_matrix.hpp"

namespace pdq {

class Context;
class Model;
class Particles;

// The load protocol: loads rise linearly from 0 at t = 0 to `scale` at t = rampTime and are
// then held (rampTime = 0: `scale` from the start). The run lasts `steps` (RunConfig) or,
// when that is negative, rampTime + holdTime.
struct Loading {
  double scale = 1;             // peak load factor: multiplies every load and prescribed value
  double rampTime = 0;          // s
  double holdTime = 0;          // s, after the ramp (sets the run's length when steps < 0)
  double holdDampingRatio = 0;  // ζ_h of mass-proportional damping once the loads are held
  // The load factor at time t.
  double factor(double t) const {
    return rampTime > 0 && t < rampTime ? scale * (t / rampTime) : scale;
  }
  bool held(double t) const { return !(rampTime > 0 && t < rampTime); }
};

// The protocol from the keys load_scale, ramp_time, hold_time, hold_damping_ratio (the
// scenario's [loading] table, or pdQInput.dat); `writeLoading` gives the keys that differ
// from the defaults, one "key value" line each (17 digits).
Loading readLoading(const Params& p);
std::string writeLoading(const Loading& l);

// Displacement control of the quasi-static solver: the particles `ids` (sorted) have their
// translation along `axis` prescribed, `displacement` × the load factor, and the reaction
// (the sum of their internal forces along the control) is the load of the curve.
struct DisplacementControl {
  int axis = -1;  // 0, 1, 2 (x, y, z); -1: no displacement control
  double displacement = 0;
  std::vector<Gid> ids;
  int line = 0;  // where the control was given, for its errors
  bool active() const { return axis >= 0; }
};

// The solver: explicit dynamics (the default), or quasi-static loading by dynamic
// relaxation (engine/relaxation.cpp): the loads and prescribed values × load_scale applied
// in increments of at most 1/`loadSteps` of it, each relaxed to static equilibrium, i.e.
// until the out-of-balance force is below `tolerance` × the applied load (or × the
// reactions when no load is applied). A load step that does not converge, or breaks more
// than `maxBroken` interactions (0: any number), is tried again with half the increment,
// down to 2^-`maxCutBacks` of the largest; two load steps in a row taken at once double it
// again (up to 1/`loadSteps`).
struct Solver {
  bool quasiStatic = false;
  double tolerance = 1e-6;
  long maxIterations = 100000;  // per load step
  long loadSteps = 1;
  long maxBroken = 0;
  int maxCutBacks = 10;
  // Force control: the run also ends once the lowest load factor found to have no
  // equilibrium near the last one lies within peakTolerance × the last equilibrium's
  // (0: only when the smallest increment reaches it), as the bisection's bracket does.
  double peakTolerance = 0;
  // Fictitious masses: each DOF's Gershgorin bound of the stiffness (the default), the
  // model's masses and inertias, or the assembled stiffness matrix, which turns the
  // relaxation into a modified Newton iteration (docs/quasi-static.md, "Assembled
  // stiffness").
  enum class Masses { Stiffness, Model, Assembled };
  Masses masses = Masses::Stiffness;
  DisplacementControl control;
  int line = 0;  // of max_iterations (or of the kind) in the run's input, for the error when a
                 // load step does not converge in time
};

// The solver from the keys `kindKey` ("dynamic" or "quasi_static"), tolerance,
// max_iterations, load_steps, max_broken, max_cut_backs, peak_tolerance, masses (the scenario's
// [solver] table with kindKey "kind", or pdQInput.dat with kindKey "solver"); `writeSolver` gives
// the keys for pdQInput.dat, the displacement control as control_axis, control_displacement and
// control_ids (read back by readControl; a scenario gives it as [solver.control]).
Solver readSolver(const Params& p, const std::string& kindKey);
// The fictitious masses from the key `key`: "stiffness", "model" or "assembled" (`fallback`
// when it is not given).
Solver::Masses readMasses(const Params& p, const std::string& key, const std::string& fallback);
std::string writeSolver(const Solver& s);
// The displacement control's axis (x, y or z) and displacement from the keys `prefix`axis
// and `prefix`displacement (both or neither), its line that of the axis.
DisplacementControl readControl(const Params& p, const std::string& prefix);
// InputError (naming the key's line) for a time-based [loading] key under the quasi-static
// solver, whose run is its load steps.
void checkStaticLoading(const Solver& s, const Params& loading);

enum class Rotation { None, Planar, Spatial };

struct Motion {
  std::vector<std::string> position{"x", "y", "z"};  // alterable columns (among x y z)
  std::vector<std::string> velocity{"vx", "vy", "vz"};
  std::vector<std::string> force{"fx", "fy", "fz"};  // integ columns
  // True when the force columns hold accelerations (force per unit mass, as peridynamic
  // kernels produce); external loads are still forces.
  bool perMass = false;
  double damping = 0;  // mass-proportional damping c (1/s), at all times
  Rotation rotation = Rotation::None;
  // Planar: {"theta"}, {"omega"}, {"mz"}; Spatial: {"qw","qx","qy","qz"}, {"wx","wy","wz"},
  // {"mx","my","mz"}.
  std::vector<std::string> orientation, angularVelocity, moment;
};

enum class Constraint : std::uint8_t {
  Free,
  // The coordinate is the reference one plus value × factor(t) (a rotation: the angle; for
  // Spatial rotations the angular velocity component follows the rate of value × factor).
  Prescribed,
  KeepVelocity,  // the velocity keeps its initial value (0: a support)
  Resting,       // free, but never below the reference coordinate: a support that only pushes
};

struct Body {
  double mass = 1, inertia = 1;
  std::array<Constraint, 6> constraint{};  // translations, then rotations
  std::array<double, 6> load{};            // peak external force or moment
  std::array<double, 6> value{};           // peak prescribed displacement or rotation
};

class Integrator {
 public:
  explicit Integrator(Model& model) : model_(model) {}
  // Advances the owned particles from step n−1 to step n = ctx.step(), with the forces of
  // step n−1 in the integ table.
  void step(Context& ctx);

  // What the engine's instability checks (engine/simulation.cpp) need of a step, gathered
  // while the step moves each particle, its data at hand: whether any owned particle's
  // alterable attribute or force is not finite, the largest move v Δt (the move the step
  // made) and what the particle followed from the step before moved now.
  static constexpr std::size_t kNoParticle = static_cast<std::size_t>(-1);
  struct Watch {
    std::size_t tracked = kNoParticle;  // in: an owned particle to follow, or none
    bool done = false;                  // out: filled by step() or see()
    bool nonFinite = false;
    double most = 0;                      // the square of the largest move
    std::size_t fastest = kNoParticle;    // whose move it is (of equal moves the largest ID)
    std::array<double, 3> fastestStep{};  // its move
    std::array<double, 3> trackedStep{};  // the followed particle's move
    bool sawTracked = false;
  };
  // The next step() fills `w` (which must live until then).
  void watchNextStep(Watch* w) { watch_ = w; }
  // The same for a step made by a model's own integration (the velocities being v(n+½)).
  void see(Context& ctx, Watch& w);
  // Whether any alterable attribute or force (moment) of owned particle i is not finite
  // (after the first step or see()).
  bool notFinite(const Particles& P, std::size_t i) const;
  // The owned particles changed (a shuffle): bodies are asked for again before the next step.
  void particlesMoved() { haveBodies_ = false; }
  // State kept between steps, saved in restart files.
  std::vector<double> state() const;
  void setState(std::span<const double> s);

  // Quasi-static: where the load path stands, in units of the largest increment
  // (1/load_steps of load_scale): the last converged load step's `progress`, the next
  // increment (a power of 2, at most 1), the load steps in a row taken at once, and under
  // force control the lowest progress found to have no equilibrium near the last one
  // (0: none), which no later load step reaches, and the iterations of the first load step
  // (0: not done). Saved in restart files with the integrator's state.
  struct LoadPath {
    double progress = 0, increment = 1, easy = 0, beyond = 0, first = 0;
  };
  LoadPath& loadPath() { return path_; }
  // The most iterations a load step may take: max_iterations, or kFirstStepsPerCap times the
  // first load step's when more (docs/quasi-static.md, "Iteration cap").
  long iterationCap(const Solver& solver) const;

  // Quasi-static: relaxes the owned particles to static equilibrium under the loads and
  // prescribed values × `factor` (the previous load step's factor `previous`), by
  // dynamic relaxation (engine/relaxation.cpp). `forces` evaluates the model's forces at the
  // current state; `exchange` refreshes the ghosts after the particles moved; `source` names
  // the run's input in errors.
  struct Relaxed {
    bool converged = true;
    bool runaway = false;  // not converged: ran away from the last equilibrium or snapped
    long iterations = 0;
    double residual = 0, reference = 0;  // out-of-balance and applied (or reaction) norms
    // The curve: |factor × loads| and the work-conjugate displacement; under displacement
    // control the reaction and the displacement along the control's direction.
    double load = 0, displacement = 0;
    // Under force control, a converged load step's compliance (its displacement along the
    // loads per load) over the last equilibrium's secant u/λ: 1 for a linear structure,
    // growing as the structure softens towards a peak (0: not measured; measured for the
    // modified Newton iteration only, whose work shrinks with the increment).
    double softening = 0;
    // With the assembled stiffness, the iteration at which it took up momentum (-1: never).
    long momentumFrom = -1;
  };
  Relaxed relax(Context& ctx, const Solver& solver, const std::string& source, double factor,
                double previous, const std::function<void()>& forces,
                const std::function<void()>& exchange);

 private:
  void resolve(const Schema& schema);
  void ensureBodies(Context& ctx);
  double displacement(const Particles& P, std::size_t i, int dof) const;
  double rayleighDamping(Context& ctx, double factor) const;
  // Relaxation (relaxation.cpp): the fictitious mass scale from the highest frequency of
  // the free degrees of freedom, and the force of DOF d of owned particle i in force units
  // with the external load at `factor`.
  // ω_max² of M⁻¹K, M the model's masses, or the given ones per owned DOF.
  double highestFrequencySquared(Context& ctx, const std::function<void()>& forces,
                                 const std::vector<double>& masses);
  // Per free DOF of the owned particles (nT_ + nR_ each), the Gershgorin bound Σ_j |K_ij| of
  // the model's stiffness at the current state, from finite differences of its forces with
  // the particles coloured so that each probe reaches every row from one particle at most;
  // empty when that takes too many probes (docs/quasi-static.md, "Fictitious masses").
  // With `entries`, also the entries K_ij of the free rows (central differences), when the
  // model's forces reach no further than the nearby cells (one force pass).
  std::vector<double> gershgorinRows(Context& ctx, const std::function<void()>& forces,
                                     std::vector<StiffnessEntry>* entries = nullptr);
  // gershgorinRows from the model's own stiffness (Model::referenceStiffness), with
  // `entries` where given; false when the model states none.
  bool statedRows(Context& ctx, std::vector<double>& rows, std::vector<StiffnessEntry>* entries);
  // A finite-difference probe of the stiffness at the current state: f = −K u for a
  // displacement field u given at every local particle (forces and moments of the owned
  // particles); the state is put back after each probe. `passes`, when given, is set to
  // one plus the ghost refreshes one force evaluation makes.
  std::function<void(std::span<const double>, std::span<double>)> stiffnessProbe(
      Context& ctx, const std::function<void()>& forces, long* passes = nullptr);
  double dofForce(const Particles& P, std::size_t i, int d, double factor) const;
  // The mass (translations) or rotational inertia (rotations) of DOF d of owned particle i.
  double dofMass(std::size_t i, int d) const {
    return d < nT_ ? bodies_[i].mass : bodies_[i].inertia;
  }
  // Turns the spatial orientation of owned particle i by the rotation vector phi.
  void turn(Particles& P, std::size_t i, const double phi[3]) const;
  // Owned particle i's step (kick, the loads at fNow, damping c; prescribed values at fNext);
  // with kMove, returns the square of its move v Δt (0 without).
  template <bool kMove>
  double advance(Particles& P, std::size_t i, double h, double kick, double fNow, double fNext,
                 double c) const;
  // The same for a particle of freeInverseMass_ (free and unloaded, no spatial rotation);
  // zero is 0 × fNow, the unloaded force's term, so that the bits are advance's.
  template <bool kMove>
  double advanceFree(Particles& P, std::size_t i, double h, double kick, double zero,
                     double c) const;
  // Fills freeInverseMass_ from bodies_.
  void indexFreeBodies();
  // The square of owned particle i's move v Δt.
  double moveSquared(const Particles& P, std::size_t i, double h) const;
  // Adds owned particles [begin, end), just moved by a step of h, to `w` (one thread's
  // share): `moves` holds their squared moves, `most` the largest.
  void seeBlock(const Particles& P, std::size_t begin, std::size_t end, const double* moves,
                double most, double h, Watch& w) const;
  static void merge(const Particles& P, const Watch& part, Watch& w);

  Model& model_;
  bool resolved_ = false, haveBodies_ = false, perMass_ = false, forcesOnly_ = false;
  Rotation rotation_ = Rotation::None;
  double damping_ = 0;
  int nT_ = 0, nR_ = 0, nA_ = 0;
  std::array<int, 6> pos_{}, vel_{}, frc_{};  // per DOF (a planar angle is a position)
  std::array<int, 4> quat_{};                 // orientation columns
  std::vector<Body> bodies_;
  // Per owned particle, 1 / mass when every DOF is free and unloaded and rotations are
  // none or planar (the step then reads 8 or 16 bytes of it, not its whole Body), else 0;
  // with planar rotations, 1 / inertia beside it.
  std::vector<double> freeInverseMass_, freeInverseInertia_;
  Watch* watch_ = nullptr;
  // Whether any of n values is not finite: a vectorised sweep (AVX2 when the CPU has it).
  bool (*anyNotFinite_)(const double*, std::size_t) = nullptr;
  double holdDamping_ = -1;  // 2 ζ_h ω₁ once computed
  // Quasi-static fictitious masses, computed at the first load step and saved in restart
  // files: ω_max² of M⁻¹K (or, with Gershgorin masses, the largest ratio of a DOF's
  // Gershgorin bound to its mass), and μ, ω_max² of G⁻¹K with G the Gershgorin masses
  // (0: the masses are the model's); and the iterations done so far.
  double omega2_ = -1, mu_ = 0;
  std::vector<double> rows_;  // the Gershgorin rows and the interactions' state they were
  Bonds::Saved rowsBonds_;    // probed with
  // The assembled stiffness (Masses::Assembled, chosen at the first load step and saved in
  // restart files), factorised with the rows unless it is not positive definite.
  bool assembled_ = false, factorised_ = false;
  std::shared_ptr<StiffnessMatrix> matrix_;
  double iterations_ = 0;
  LoadPath path_;
};

}  // namespace pdq
