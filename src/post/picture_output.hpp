#pragma once
// Pictures during a run: at its steps the lattice is gathered on rank 0 and drawn
// (deformed, damaged bonds coloured as in the thesis's Fig. 4.5, or particles coloured
// by a quantity) to <outDir>/<name>_<step>.<format>.
#include <string>

#include "engine/output.hpp"
#include "engine/params.hpp"
#include "post/snapshot.hpp"

namespace pdq::post {

struct PictureOptions {
  long every = 0;     // steps between pictures, from step 0 (0: not during the run)
  bool atEnd = true;  // also at the last step
  std::string name = "damage";
  std::string format = "png";  // png, svg or pdf
  PictureRequest request;
};

// Options from a scenario's table (e.g. [output.picture]): every, at_end, name, format,
// colour_by, bond_damage, magnification, view, width, height, dot_radius,
// damage_threshold, value_min, value_max, title, slab.
PictureOptions pictureOptions(const Params& table);

class PictureOutput final : public Output {
 public:
  explicit PictureOutput(PictureOptions options);
  bool atEnd() const override { return opt_.atEnd; }
  // Checks the request's names and slab against the lattice (every rank alike), then
  // removes an earlier run's pictures after this run's first step (all: started afresh).
  void begin(OutputContext& out, bool resumed) override;
  void write(OutputContext& out) override;
  // The file of the picture at `step`.
  static std::string fileName(const PictureOptions& options, long step);

 private:
  PictureOptions opt_;
};

}  // namespace pdq::post
