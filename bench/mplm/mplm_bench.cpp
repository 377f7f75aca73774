// Runs the thesis's 2D MPLM examples: one trial at a load, a strength search, or a timed
// run (the speed goals of issue 4).
//   mplm_bench time <example> [load]          full run, prints wall-clock seconds
//   mplm_bench trial <example> <load>         one trial: holds or fails, and why
//   mplm_bench strength <example> <lo> <hi>   bisection; prints the bracket and mode
//   mplm_bench damage <example> <load>        one run; prints where damage reaches 0.5
//   mplm_bench picture <example> <load>       the same, and damage_out/<example>_<step>.png
// Extra model parameters as key=value after the arguments (steps=, rel_tol=, settle=
// and stable_step=true set the run length, the search's tolerances and its time step).
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/comm.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "models/mplm/examples.hpp"
#include "models/mplm/strength.hpp"
#include "post/picture_output.hpp"

using namespace pdq;

int main(int argc, char** argv) {
  MpiSession session(&argc, &argv);
  Comm comm(MPI_COMM_WORLD);
  if (argc < 3) {
    if (comm.root())
      std::fprintf(stderr, "usage: mplm_bench time|trial|strength <example> [numbers] [k=v...]\n");
    return 2;
  }
  const std::string what = argv[1];
  mplm::Example ex = mplm::example(argv[2]);
  std::vector<double> nums;
  mplm::StrengthOptions opt;
  for (int k = 3; k < argc; ++k) {
    const std::string a = argv[k];
    const auto eq = a.find('=');
    if (eq == std::string::npos)
      nums.push_back(std::atof(a.c_str()));
    else if (a.substr(0, eq) == "steps")
      ex.steps = std::atol(a.c_str() + eq + 1);
    else if (a.substr(0, eq) == "rel_tol")
      opt.relTol = std::atof(a.c_str() + eq + 1);
    else if (a.substr(0, eq) == "settle")
      opt.settle = std::atof(a.c_str() + eq + 1);
    else if (a.substr(0, eq) == "stable_step")
      opt.stableStep = std::string(a.c_str() + eq + 1) == "true";
    else
      opt.overrides[a.substr(0, eq)] = a.substr(eq + 1);
  }
  try {
    if (what == "time") {
      const double load = nums.empty() ? 0.5 * ex.thesisMplm : nums[0];
      opt.holdLength = 1;  // exactly the example's steps, as the thesis ran them
      opt.holdDamping = 0;
      const auto t0 = std::chrono::steady_clock::now();
      const mplm::Trial tr = mplm::runTrial(ex, load, comm, opt);
      const double secs =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (comm.root())
        std::printf("%s: %zu particles, %ld steps on %d rank(s): %.2f s (load %g %s)\n",
                    ex.name.c_str(), ex.particles.size(), tr.steps, comm.size(), secs, load,
                    ex.unit.c_str());
    } else if (what == "trial") {
      const mplm::Trial tr = mplm::runTrial(ex, nums.at(0), comm, opt);
      if (comm.root())
        std::printf(
            "%s at %g %s: %s; u hold/mid/end %.4g/%.4g/%.4g m, broken mid/end %g/%g, "
            "%ld steps, damage: %s\n",
            ex.name.c_str(), tr.load, ex.unit.c_str(), tr.holds ? "holds" : "FAILS", tr.uHold,
            tr.uMid, tr.uEnd, tr.brokenMid, tr.brokenEnd, tr.steps, tr.mode.c_str());
      if (comm.root()) std::printf("%s", tr.log.c_str());
    } else if (what == "damage" || what == "picture") {
      // One run on one rank; prints the particles whose damage reaches 0.5, as x y ω_t ω_c.
      Params p("mplm_bench");
      for (const auto& [k, v] : ex.params) p.set(k, v);
      for (const auto& [k, v] : opt.overrides) p.set(k, v);
      p.set("load_scale", std::to_string(nums.at(0)));
      auto model = ModelRegistry::create("mplm2d");
      model->configure(p);
      RunConfig cfg;
      cfg.steps = ex.steps;
      cfg.outDir = "damage_out";
      Simulation sim(std::move(model), ex.particles, cfg, comm);
      if (what == "picture") {
        // The deformed lattice at the end, magnified 10 times as in the thesis's figures,
        // interactions coloured by tensile damage (undamaged ones hidden).
        Params pic("picture");
        pic.set("name", ex.name);
        pic.set("bond_damage", "omega_t");
        pic.set("magnification", "10");
        pic.set("width", "1600");
        sim.addOutput(std::make_unique<post::PictureOutput>(post::pictureOptions(pic)));
      }
      sim.run();
      const auto names = sim.model().fields();
      const std::size_t n = sim.particles().owned();
      std::vector<double> d(n), t(n), c(n);
      sim.model().field(sim.context(), 0, d);
      sim.model().field(sim.context(), 1, t);
      sim.model().field(sim.context(), 2, c);
      for (std::size_t i = 0; i < n; ++i)
        if (d[i] >= 0.5)
          std::printf("%.4f %.4f %.3f %.3f\n", sim.particles().fixed(i)[0],
                      sim.particles().fixed(i)[1], t[i], c[i]);
    } else if (what == "strength") {
      const mplm::Strength st = mplm::findStrength(ex, nums.at(0), nums.at(1), comm, opt);
      if (comm.root()) {
        for (const auto& tr : st.trials)
          std::printf("  %g %s: %s (u mid/end %.4g/%.4g, broken %g/%g)\n", tr.load, ex.unit.c_str(),
                      tr.holds ? "holds" : "fails", tr.uMid, tr.uEnd, tr.brokenMid, tr.brokenEnd);
        std::printf(
            "%s: strength in [%g, %g] %s, failure mode %s (thesis MPLM %g, thesis classical %g, "
            "ACI/classical here %.4g %s)\n",
            ex.name.c_str(), st.lower, st.upper, ex.unit.c_str(), st.mode.c_str(), ex.thesisMplm,
            ex.classical, ex.aci, ex.aciMode.c_str());
      }
    } else {
      throw std::invalid_argument("unknown command " + what);
    }
  } catch (const std::exception& e) {
    if (comm.root()) std::fprintf(stderr, "mplm_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
