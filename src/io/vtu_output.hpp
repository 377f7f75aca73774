#pragma once
// ParaView output: at its steps every rank writes its owned particles as one .vtu piece
// (points at the current positions; point data: global ID, displacement x - X, the
// model's fixed and alterable attributes beyond the positions, and the model's fields),
// rank 0 writes the step's .pvtu and rewrites the .pvd time series. With bonds on, a
// second series holds every bond once as a line cell (written by the end with the
// smaller global ID, the other end at its ghost's position) with the bond attributes
// as cell data. Layout under the run's output directory:
//     <name>.pvd, <name>_bonds.pvd
//     <name>/<name>_<step>.pvtu, <name>/<name>_<step>_<rank>.vtu   (and _bonds_ likewise)
#include <string>
#include <vector>

#include "engine/output.hpp"
#include "engine/params.hpp"
#include "io/vtu_format.hpp"

namespace pdq {

struct VtuOptions {
  long every = 0;     // steps between writes, from step 0 (0: not during the run)
  bool atEnd = true;  // also at the last step
  bool bonds = true;  // also the bond series
  std::string name = "particles";
};

// Options from a scenario's table (e.g. [output.paraview]): every, at_end, bonds, name.
VtuOptions vtuOptions(const Params& table);

class VtuOutput final : public Output {
 public:
  explicit VtuOutput(VtuOptions options);
  bool atEnd() const override { return opt_.atEnd; }
  void write(OutputContext& out) override;

 private:
  struct Series {
    std::string name;  // file stem: <name>.pvd, <name>/... pieces are in folder opt_.name
    std::vector<vtu::SeriesEntry> entries;
    std::vector<long> steps;
    bool loaded = false;
  };
  void writeStep(OutputContext& out, Series& series, const vtu::Piece& piece);
  VtuOptions opt_;
  Series particles_, bonds_;
};

// The pieces themselves, for one rank's procCube (exposed for tests and tools).
vtu::Piece particlePiece(const Context& ctx, const Model& model);
vtu::Piece bondPiece(const Context& ctx);

}  // namespace pdq
