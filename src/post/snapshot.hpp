#pragma once
// The whole lattice at one step in one place: particles sorted by global ID with their
// reference and current positions and every per-particle quantity by name, and every
// bond once with its attributes. gatherSnapshot builds it on rank 0 from a running
// simulation; `pdq post` can fill one from restart files. renderSnapshot draws it.
#include <array>
#include <string>
#include <vector>

#include "engine/comm.hpp"
#include "engine/context.hpp"
#include "post/lattice_picture.hpp"

namespace pdq {
class Model;
}

namespace pdq::post {

struct Snapshot {
  long step = 0;
  double time = 0;
  std::vector<Gid> id;                            // ascending
  std::vector<double> reference, current;         // x y z per particle
  std::vector<std::string> names;                 // per-particle quantities ...
  std::vector<std::vector<double>> values;        // ... values[k][particle]
  std::vector<std::array<std::size_t, 2>> bonds;  // particle indices, smaller ID first
  std::vector<std::string> bondNames;
  std::vector<double> bondAttrs;  // bondNames.size() per bond

  std::size_t particles() const { return id.size(); }
};

// The per-particle quantities a snapshot carries, in order: the model's fixed and
// alterable attributes beyond the positions, then its fields.
std::vector<std::string> quantityNames(const Schema& schema, const Model& model);

// Collective: every rank sends its owned particles (the model's fixed and alterable
// attributes beyond the positions, then the model's fields) and the bonds it owns with
// the smaller ID; rank 0 gets the whole lattice, other ranks an empty snapshot. A bond
// across a periodic boundary (its far end a shifted image) is left out.
Snapshot gatherSnapshot(const Context& ctx, const Model& model, const Comm& comm, long step);

// For snapshots filled from files (`pdq post`): puts the particles in ID order (with
// their quantities), then adds bonds named by their ends' global IDs, as restart files
// store them (each bond may be listed from both ends): one copy per pair is kept, the
// one listed by the smaller ID, in ID-pair order. `attrs` holds bondNames.size() values
// per listed bond. InputError naming `source` for an ID that is not a particle.
void sortParticles(Snapshot& s);
void addBonds(Snapshot& s, const std::vector<Gid>& owner, const std::vector<Gid>& partner,
              const std::vector<double>& attrs, const std::string& source);

// A slab of the lattice: the particles whose reference coordinate along `axis` (0, 1, 2
// for X, Y, Z; -1: no slab, every particle) lies in [lo, hi], and the bonds between them.
struct Slab {
  int axis = -1;
  double lo = 0, hi = 0;
  bool contains(const double* reference) const {
    return axis < 0 || (reference[axis] >= lo && reference[axis] <= hi);
  }
};

// Parses "z=0.05:0.11" (axis x, y or z, then the range lo:hi with lo < hi); InputError
// naming `file` and `line` otherwise.
Slab parseSlab(const std::string& text, const std::string& file, int line);

// What to draw from a snapshot.
struct PictureRequest {
  PictureStyle style;
  // Colour the particles by this quantity: a name in Snapshot::names, or "displacement"
  // (its magnitude); empty: grey dots.
  std::string colourBy;
  // The bond attribute drawn as damage (0..1); empty: "damage" if there is one, else
  // no bonds; "none": no bonds.
  std::string bondDamage;
  // Only the particles in this slab (reference positions) and the bonds between them.
  Slab slab;
  // Where the names were written, for errors.
  // Where colour_by, bond_damage and the slab were given (file and line), for messages.
  std::string source = "picture", bondDamageSource = "picture", slabSource = "picture";
  int colourByLine = 0, bondDamageLine = 0, slabLine = 0;
};

// The error for a slab that holds no particle, given the particles' reference range along
// its axis.
[[noreturn]] void emptySlab(const PictureRequest& request, double lo, double hi);

// Throws InputError (suggesting the nearest name) when a requested name is unknown.
void checkRequest(const PictureRequest& request, const std::vector<std::string>& names,
                  const std::vector<std::string>& bondNames);
// The picture's arrays: the request's quantities of the particles in its slab. InputError
// (at the slab's line) when the slab holds no particle.
LatticeImage latticeImage(const Snapshot& snapshot, const PictureRequest& request);
void renderSnapshot(const Snapshot& snapshot, const PictureRequest& request,
                    const std::string& path);

}  // namespace pdq::post
