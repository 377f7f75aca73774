#pragma once
// The model interface: the physics, which the engine knows nothing about. A model is one
// folder under src/models/ (or a plugin library) and registers itself by name in one line:
//
//     PDQ_REGISTER_MODEL(MyModel, "mymodel", "what it simulates");
//
// The engine calls, in order:
//   configure(params)        read parameters (unknown ones are errors afterwards)
//   schema(), horizon(), shuffles()
//   setup(ctx)               once: bonds (ctx.bonds.add), time step (ctx.setDt)
//   [restart values are loaded here]
//   prepare(ctx)             once, after restart: anything derived from current state
//   every step: force(ctx) -> integrate(ctx) -> engine exchange/shuffle -> outputs
//   neighboursChanged(ctx)   after every shuffle (shuffling models only)
// integrate() is the engine's integrator (engine/integrator.hpp) unless a model with special
// needs overrides it: the model declares its degrees of freedom (motion) and each owned
// particle's mass, inertia, constraints and loads (bodies), and writes forces and moments
// into the integ columns it named. A 3D model with rotations declares
// Rotation::Spatial (orientation as a unit quaternion, angular velocity in the global frame).
// A model writes only its owned particles (i < particles.owned()) and reads neighbours
// through the ghosts; it never calls MPI. See src/models/spring/ for a commented example.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/context.hpp"
#include "engine/integrator.hpp"
#include "engine/params.hpp"
#include "engine/registry.hpp"
#include "engine/schema.hpp"

namespace pdq {

// What `pdq strength` (src/studies/strength.hpp) needs of a model to search the load at
// which a structure stops reaching static equilibrium: three of its globals by name and a
// failure classifier. A model that declares these gets `pdq strength` with no code of its
// own; one that leaves `load` empty has no strength search.
struct StrengthSpec {
  std::string load;                       // global: the load factor applied now
  std::vector<std::string> displacement;  // globals: components of the monitored displacement
  std::string damage;                     // global: the number of broken interactions
  // How the structure failed ("tension", "shear", ...), judged from the state at the end of
  // a trial; called on every rank alike (it may use the context's reductions).
  std::function<std::string(Context&)> failureMode;
};

class Model {
 public:
  virtual ~Model() = default;

  virtual void configure(const Params& params) = 0;
  virtual Schema schema() const = 0;
  // Radius beyond which two particles never interact (at the positions cells are built
  // from: reference positions for non-shuffling models, current ones otherwise).
  virtual double horizon() const = 0;
  // The minimum cell size when the input sets none: the horizon, or more for a model that
  // keeps pair lists with a skin (cells >= cut-off + skin).
  virtual double minCellSize() const { return horizon(); }
  // Each cell of at least the minimum cell size cut into k x k x k sub-cells (decomposition.hpp):
  // the cuts between ranks k times finer, the reach the same.
  virtual int cellDivisions() const { return 1; }
  // True when particles change neighbours (molecular dynamics): the engine then shuffles
  // particles between cells and ranks, and bins them by current position.
  virtual bool shuffles() const { return false; }
  // True when setup bonds the particles within the horizon (of the lattice, as `pdq info`
  // estimates them before any particle exists); false for a model without bonds.
  virtual bool bondsWithinHorizon() const { return true; }
  // True when results depend on the cell lattice (the model visits neighbours through the
  // cells after setup, in the cells' order). A model whose only neighbours are its bonds
  // (sorted by partner ID), or whose sums do not depend on the order (exact sums, lj), says
  // false; the engine may then take fewer, larger cells along axes cut among ranks to
  // balance them better.
  virtual bool resultsDependOnCells() const { return true; }
  // True when the forces on a particle depend on nothing but its own state and its bonds'
  // partners', per force pass (no interaction with particles it is not bonded to): the
  // quasi-static solver's stiffness probes then colour the bond graph instead of the cells
  // (engine/bond_colouring.hpp), far fewer probes.
  virtual bool forcesFromBonds() const { return false; }
  // Whether the model states its stiffness (below): the quasi-static solver then probes
  // nothing. The same answer on every rank.
  virtual bool statesStiffness() const { return false; }
  // The stiffness at the reference configuration (positions X, the reference orientation)
  // with the interactions' state as it is, which the quasi-static solver's fictitious masses
  // and assembled stiffness need: for every owned particle i, add(i, i, K, Kb) and then
  // add(i, j, K, Kb) for each particle j it interacts with (local index; each once). K is the
  // nd × nd block −∂F_i/∂u_j row by row, F the force (and moment) columns the model writes
  // and u the DOFs of motion(): translations, then rotations about the global axes. Where
  // an interaction is stiffer one way than the other (damaged in tension, it is stiffer
  // pushed than pulled), K holds the mean of the two, as central differences give it, and
  // Kb the block with each interaction on its stiffer side, for the Gershgorin bounds of the
  // fictitious masses (elsewhere Kb = K).
  using StiffnessBlocks = std::function<void(
      std::size_t i, std::size_t j, std::span<const double> K, std::span<const double> Kb)>;
  virtual void referenceStiffness(const Context&, const StiffnessBlocks&) const {}

  virtual void setup(Context&) {}
  virtual void prepare(Context&) {}
  virtual void neighboursChanged(Context&) {}
  virtual void force(Context& ctx) = 0;
  virtual void integrate(Context& ctx) { ctx.integrate(); }
  // For the engine's integrator: which columns move and how (default: x y z, vx vy vz,
  // fx fy fz, no rotation), and every owned particle's Body (default: unit mass, free),
  // asked for before the first step and again after every shuffle.
  virtual Motion motion() const { return {}; }
  virtual void bodies(const Context&, std::span<Body> /*owned*/) const {}

  // What the model keeps between steps beyond its attributes and bonds (a random
  // generator's state, ...), identical on every rank; saved with restart files and given
  // back after prepare() on a restart. Anything prepare() derives again is not state.
  virtual std::vector<double> saveState() const { return {}; }
  virtual void loadState(std::span<const double> /*saved*/) {}

  // Per-particle derived quantities for visual output (damage, energy, ...).
  virtual std::vector<std::string> fields() const { return {}; }
  virtual void field(const Context&, int /*k*/, std::span<double> /*ownedValues*/) const {}
  // Global quantities for the history file (load, displacement, energies); called on
  // every rank at output steps, so they may use the context's reductions. Every model
  // names its potential energy at the current positions (and rotations) "potential": its
  // forces and moments are minus its gradient (tests/conformance checks it).
  virtual std::vector<std::string> globals() const { return {}; }
  virtual std::vector<double> globalValues(Context&) { return {}; }
  // Declared by models that support `pdq strength` (see StrengthSpec); the classifier may
  // refer to this model, so the spec lives no longer than it.
  virtual StrengthSpec strengthSpec() { return {}; }
};

using ModelFactory = std::function<std::unique_ptr<Model>()>;
template <>
Registry<ModelFactory>::Table& Registry<ModelFactory>::table();

struct ModelRegistry : Registry<ModelFactory> {
  // A new, unconfigured model; InputError (naming `source` and `line`) for an unknown name.
  static std::unique_ptr<Model> create(const std::string& name, const std::string& source = "",
                                       int line = 0) {
    return get(name, source, line)();
  }
  // ... and configured with `params`, every one of which it must read (InputError otherwise).
  static std::unique_ptr<Model> create(const std::string& name, const Params& params,
                                       const std::string& source = "", int line = 0) {
    auto model = create(name, source, line);
    model->configure(params);
    params.checkAllUsed();
    return model;
  }
};

}  // namespace pdq

#define PDQ_REGISTER_MODEL(Class, name, description)                                     \
  static const bool pdq_registered_##Class [[maybe_unused]] = ::pdq::ModelRegistry::add( \
      name, description, [] { return std::unique_ptr<::pdq::Model>(new Class()); })
