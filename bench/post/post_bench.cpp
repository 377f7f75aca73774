// Speed of the visual outputs on a large 2D spring lattice (nx x ny particles, 8 bonds
// each): one ParaView step (particles and bonds, all ranks) and one damage picture
// (gather to rank 0 and draw). Usage: mpirun -np R post_bench [nx] [ny] [outDir]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/comm.hpp"
#include "engine/model.hpp"
#include "engine/simulation.hpp"
#include "io/standard_outputs.hpp"
#include "io/vtu_output.hpp"
#include "post/picture_output.hpp"

int main(int argc, char** argv) {
  pdq::MpiSession mpi(&argc, &argv);
  pdq::Comm comm;
  const int nx = argc > 1 ? std::atoi(argv[1]) : 700, ny = argc > 2 ? std::atoi(argv[2]) : 700;
  const std::string dir = argc > 3 ? argv[3] : "post_bench_out";
  pdq::Params p("bench");
  p.set("critical_stretch", "0.01");
  pdq::Problem pb = pdq::makeProblem("spring", p, {});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) pb.particles.add(static_cast<pdq::Gid>(j) * nx + i, i, j, 0);
  pb.run.outDir = dir;
  const auto simulation = pdq::makeSimulation(std::move(pb), comm);
  pdq::Simulation& sim = *simulation;
  sim.setup();
  // Break a "crack" of bonds so the picture has something to draw.
  for (std::size_t i = 0; i < sim.particles().owned(); ++i)
    if (sim.particles().fixed(i)[0] < nx / 2 + 1 && sim.particles().fixed(i)[0] > nx / 2 - 1)
      for (std::size_t b = sim.bonds().begin(i); b < sim.bonds().end(i); ++b)
        sim.bonds().attr(b)[0] = 1;
  pdq::OutputContext oc{sim.context(), sim.model(), comm, dir, 0, 0};

  auto time = [&](auto&& f) {
    comm.barrier();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    comm.barrier();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  pdq::VtuOutput vtu(pdq::VtuOptions{});
  const double tv = time([&] { vtu.write(oc); });
  pdq::post::PictureOptions po;
  po.request.bondDamage = "broken";
  pdq::post::PictureOutput pic(po);
  const double tp = time([&] { pic.write(oc); });
  pdq::post::Snapshot snap;
  const double tg = time([&] { snap = pdq::post::gatherSnapshot(oc.ctx, oc.model, comm, 0); });
  if (comm.root()) {
    std::uintmax_t bytes = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir + "/particles"))
      if (e.is_regular_file()) bytes += e.file_size();
    std::printf("post_bench: %d particles on %d rank(s)\n", nx * ny, comm.size());
    std::printf("  ParaView step (particles + bonds): %.3f s, %.1f MB\n", tv, bytes / 1e6);
    std::printf("  damage picture (gather + PNG):     %.3f s (gather %.3f s)\n", tp, tg);
  }
  return 0;
}
