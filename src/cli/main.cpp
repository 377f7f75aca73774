// The pdq command: `pdq run|prep|post|strength|info|list ...`; `pdq --help` for more.
// Runs alone (one rank) or under mpirun; every rank parses the same command line.
#include <malloc.h>
#include <omp.h>

#include <cstdio>
#include <cstdlib>

#include "cli/command_line.hpp"
#include "cli/guard.hpp"
#include "cli/plugins.hpp"
#include "cli/watchdog.hpp"
#include "engine/comm.hpp"

using namespace pdq::cli;

int main(int argc, char** argv) {
  // Memory freed stays with the process (up to 1 GiB at the heap's top): glibc would map
  // large blocks alone and give them back to the system when freed, and each new one (the
  // quasi-static solver's matrix, probes and messages at every load step) would fault its
  // pages in again (docs/quasi-static.md, "Where the work goes"). No block is mapped alone.
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  pdq::MpiSession mpi(&argc, &argv, true);
  // Threads are asked for with OMP_NUM_THREADS; OpenMP's own default, a thread per core in
  // every rank, makes each of a step's parallel loops wait for the rank's slowest thread,
  // and a thread without a core (ranks or other jobs sharing the cores) holds it for a time
  // slice: small problems and relaxation's many short force evaluations spend their time
  // waiting. The results are the same bits with any number of threads.
  if (std::getenv("OMP_NUM_THREADS") == nullptr) omp_set_num_threads(1);
  Guard guard;
  const bool root = pdq::Comm().root();

  const CommandLine c = parseCommandLine(argc, argv);
  if (c.exit >= 0) {
    if (root) {
      std::fputs(c.out.c_str(), stdout);
      if (!c.error.empty()) printError(c.error);
    }
    return c.exit;
  }
  const Watchdog watchdog(c.watchdog, mpi.threadMultiple());
  int code = Ok;
  const int failed = guard.run([&] {
    loadPlugins(c.plugins);
    using C = CommandLine::Command;
    switch (c.command) {
      case C::Run:
        code = runCommand(c.run);
        break;
      case C::Prep:
        prepCommand(c.prep);
        break;
      case C::Picture:
        pictureCommand(c.picture);
        break;
      case C::Plot:
        plotCommand(c.plot);
        break;
      case C::Strength:
        strengthCommand(c.strength);
        break;
      case C::Info:
        infoCommand(c.info);
        break;
      case C::List:
        listCommand(c.list, root);
        break;
    }
  });
  return failed != Ok ? failed : code;
}
