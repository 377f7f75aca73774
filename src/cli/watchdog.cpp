#include "cli/watchdog.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "cli/guard.hpp"
#include "engine/process_state.hpp"

namespace pdq::cli {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}
}  // namespace

Watchdog::Watchdog(double timeout, bool threadMultiple) : timeout_(timeout) {
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  if (size_ == 1 || timeout_ <= 0 || !threadMultiple) return;
  MPI_Comm_dup(MPI_COMM_WORLD, &beats_);
  // Each rank tells the next one its machine and process id.
  struct Whereabouts {
    char host[MPI_MAX_PROCESSOR_NAME] = {};
    int pid = 0;
  } mine, previous;
  int length = 0;
  MPI_Get_processor_name(mine.host, &length);
  mine.pid = static_cast<int>(getpid());
  const int next = (rank_ + 1) % size_, before = (rank_ + size_ - 1) % size_;
  MPI_Sendrecv(&mine, sizeof mine, MPI_BYTE, next, 1, &previous, sizeof previous, MPI_BYTE, before,
               1, beats_, MPI_STATUS_IGNORE);
  previousPid_ = previous.pid;
  previousSameHost_ = std::strncmp(mine.host, previous.host, sizeof mine.host) == 0;
  thread_ = std::thread([this] { watch(); });
}

Watchdog::~Watchdog() {
  if (!thread_.joinable()) return;
  finishing_ = true;
  thread_.join();
  MPI_Comm_free(&beats_);
}

void Watchdog::watch() {
  const int next = (rank_ + 1) % size_, previous = (rank_ + size_ - 1) % size_;
  // A few beats within the timeout, so one late beat is no alarm.
  const double period = std::min(0.5, timeout_ / 5);
  auto heard = Clock::now(), looked = heard, beaten = Clock::now() - std::chrono::hours(1);
  MPI_Request allDone = MPI_REQUEST_NULL;
  bool warned = false;  // of this silence
  while (true) {
    if (allDone == MPI_REQUEST_NULL && finishing_) MPI_Ibarrier(beats_, &allDone);
    if (allDone != MPI_REQUEST_NULL) {
      int done = 0;
      MPI_Test(&allDone, &done, MPI_STATUS_IGNORE);
      if (done) break;
    }
    if (since(beaten) >= period) {
      MPI_Request r;
      MPI_Isend(nullptr, 0, MPI_BYTE, next, 0, beats_, &r);
      MPI_Request_free(&r);
      beaten = Clock::now();
    }
    // This rank itself was stopped (and continued): its own silence is no news of others.
    if (since(looked) > timeout_ / 2) heard = Clock::now();
    looked = Clock::now();
    for (int arrived = 1; arrived;) {
      MPI_Iprobe(previous, 0, beats_, &arrived, MPI_STATUS_IGNORE);
      if (arrived) {
        MPI_Recv(nullptr, 0, MPI_BYTE, previous, 0, beats_, MPI_STATUS_IGNORE);
        heard = Clock::now();
      }
    }
    if (const double silent = since(heard); silent > timeout_) {
      const ProcessState state =
          previousSameHost_ ? processState(previousPid_) : ProcessState::Unknown;
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.1f", silent);
      const std::string quiet =
          "rank " + std::to_string(previous) + " has given no sign of life for " + seconds + " s";
      if (state == ProcessState::Alive) {
        if (!warned) {
          std::fprintf(stderr,
                       "pdq: warning: %s, but its process is alive: the machine is overloaded; "
                       "waiting for it\n",
                       quiet.c_str());
          warned = true;
        }
      } else {
        const char* cause = state == ProcessState::Stopped ? "it is stopped (SIGSTOP, a debugger)"
                            : state == ProcessState::Gone
                                ? "its process has ended"
                                : "it is stopped (SIGSTOP, a debugger) or its node is lost";
        printError(quiet + ": " + cause + "; rank " + std::to_string(rank_) +
                   " ends the job (--watchdog sets the time)");
        MPI_Abort(MPI_COMM_WORLD, RunFailed);
      }
    } else if (silent < period) {
      warned = false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace pdq::cli
