#pragma once
// Errors in a command that runs on every rank. Each rank catches its own exception; if
// every rank failed (bad input is seen alike everywhere) rank 0 prints the message once
// and all ranks exit with the error's code; if only some ranks failed, the others are
// stuck in a collective call, so a failed rank prints its message and aborts the job.
#include <mpi.h>

#include <functional>
#include <string>

namespace pdq::cli {

// Exit codes of the pdq command (docs/tutorial.md).
enum Exit : int {
  Ok = 0,
  BadInput = 1,     // an input file or parameter is wrong (the message names file and line)
  BadCommand = 2,   // the command line is wrong
  RunFailed = 3,    // the run failed (unstable, out of memory, a file could not be written)
  Interrupted = 4,  // stopped early by a signal or --max-wall-time, a checkpoint written
};

class Guard {
 public:
  // Collective over MPI_COMM_WORLD: call on every rank after MPI is initialised.
  Guard();
  ~Guard();
  Guard(const Guard&) = delete;
  Guard& operator=(const Guard&) = delete;

  // Runs `command`; returns its exit code (Ok, or the failure's code on every rank).
  int run(const std::function<void()>& command);

 private:
  bool everyRankFailed(double seconds);
  MPI_Comm failures_ = MPI_COMM_NULL;  // only failed ranks ever call into it
  int rank_ = 0;
};

// Prints "pdq: error: message" (or `prefix` in place of "pdq: error: ") to stderr.
void printError(const std::string& message, const char* prefix = "pdq: error: ");

}  // namespace pdq::cli
