#include "cli/guard.hpp"

#include <chrono>
#include <cstdio>
#include <new>
#include <thread>

#include "engine/error.hpp"

namespace pdq::cli {

void printError(const std::string& message, const char* prefix) {
  std::fflush(stdout);
  std::fprintf(stderr, "%s%s\n", prefix, message.c_str());
  std::fflush(stderr);
}

Guard::Guard() {
  MPI_Comm_dup(MPI_COMM_WORLD, &failures_);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
}

Guard::~Guard() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized && failures_ != MPI_COMM_NULL) MPI_Comm_free(&failures_);
}

// A barrier on a communicator of its own, so it cannot match a collective call that
// healthy ranks are in; it completes only when every rank has failed.
bool Guard::everyRankFailed(double seconds) {
  MPI_Request request;
  MPI_Ibarrier(failures_, &request);
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int done = 0;
  while (true) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return true;
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

int Guard::run(const std::function<void()>& command) {
  std::string message;
  int code = Ok;
  try {
    command();
    return Ok;
  } catch (const InputError& e) {
    message = e.what();
    code = BadInput;
  } catch (const std::bad_alloc&) {
    message = "out of memory";
    code = RunFailed;
  } catch (const std::exception& e) {
    message = e.what();
    code = RunFailed;
  }
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // Ranks that fail alike (bad input, read alike by every rank) arrive within moments of
  // each other; a rank that waits longer than this is alone with its error (a file only
  // it writes, a check on its own particles), and the others wait for it in a collective
  // call: it ends the job.
  if (size == 1 || everyRankFailed(2.0)) {
    if (rank_ == 0) printError(message);
    return code;
  }
  printError("rank " + std::to_string(rank_) + ": " + message);
  MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}

}  // namespace pdq::cli
