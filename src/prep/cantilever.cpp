#include "prep/cantilever.hpp"

#include <sstream>

#include "engine/error.hpp"
#include "engine/model.hpp"
#include "io/thesis_input.hpp"
#include "prep/lattice.hpp"

namespace pdq::prep {

CantileverProblem thesisCantilever(const CantileverSpec& spec) {
  if (spec.m < 1 || spec.n < 1) throw InputError("cantilever", 0, "m and n must be at least 1");
  if (spec.model != "lps" && spec.model != "pmb")
    throw InputError("cantilever", 0, "the cantilever runs with model \"lps\" or \"pmb\"");
  CantileverProblem pb;
  pb.model = spec.model;
  const double s = spec.spacing, delta = spec.horizonFactor * s;
  Params& p = pb.params;
  p.set("E", numberText(spec.E));
  if (spec.model == "lps") p.set("nu", numberText(spec.nu));
  p.set("horizon", numberText(delta));
  p.set("thickness", numberText(s));
  p.set("density", numberText(spec.density));
  p.set("dt", numberText(spec.dt));
  p.set("damping", numberText(spec.damping));
  p.set("lattice_spacing", numberText(s));

  const Schema schema = ModelRegistry::create(spec.model)->schema();
  ParticleSet& ps = pb.particles;
  ps.nFixed = schema.nFixed();
  ps.nAlter = schema.nAlter();
  appendLattice(ps, squareLattice(spec.m + 1, spec.n + 1, s));
  const int bc = schema.fixedIndex("bc_x"), fy = schema.fixedIndex("fy"),
            vol = schema.fixedIndex("volume");
  for (std::size_t k = 0; k < ps.size(); ++k) {
    double* f = ps.fixedRow(k);
    const long i = static_cast<long>(k % (spec.m + 1));
    f[vol] = s * s * s;  // s² × thickness s
    if (i * s < delta) f[bc] = f[bc + 1] = f[bc + 2] = 1;
    if (i == spec.m) f[fy] = spec.load;
  }
  pb.monitored = ps.gid.back();
  pb.run.minCellSize = spec.cellFactor * delta;
  pb.run.steps = spec.steps;
  return pb;
}

void writeThesisCantilever(const CantileverSpec& spec, const std::string& dir) {
  CantileverProblem c = thesisCantilever(spec);
  c.run.source = dir;
  writeThesisInput(dir, makeProblem(c.model, c.params, std::move(c.particles), c.run), c.params);
}

}  // namespace pdq::prep
