#pragma once
// The job's watchdog: a rank that is stopped (SIGSTOP, a frozen node) would leave the
// others waiting in a collective call for ever, since MPI notices dead processes but not
// stopped ones. Each rank runs one thread that, every fraction of a second, sends an empty
// message to the next rank (rank + 1, in a ring) on a communicator of its own and
// receives the previous rank's. When a rank has heard nothing from the previous one for
// `timeout` seconds, it names that rank and the cause and aborts the job. When that rank
// runs on the same machine, the operating system is asked first (/proc): a rank that is
// stopped or gone ends the job, a rank whose process is still alive is only starved of
// cores (an overloaded machine) and is waited for, with a warning, for as long as it
// takes; on another machine the silence alone decides.
//
// The thread only sends and receives its own messages: it never touches the simulation,
// so runs are bitwise the same with it, and the time loop does not wait for it. A rank
// busy for long (writing a large file, a slow trial) still beats, so the timeout need not
// cover the longest wait in a collective.
#include <mpi.h>

#include <atomic>
#include <thread>

namespace pdq::cli {

class Watchdog {
 public:
  // Collective over MPI_COMM_WORLD. Does nothing on one rank, with `timeout` <= 0, or
  // when MPI does not allow calls from a second thread (`threadMultiple` false).
  Watchdog(double timeout, bool threadMultiple);
  // Collective: keeps watching until every rank has got here, then stops.
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  void watch();
  MPI_Comm beats_ = MPI_COMM_NULL;
  std::thread thread_;
  std::atomic<bool> finishing_{false};
  double timeout_ = 0;
  int rank_ = 0, size_ = 1;
  int previousPid_ = 0;            // the previous rank's process id
  bool previousSameHost_ = false;  // and whether it runs on this machine
};

}  // namespace pdq::cli
