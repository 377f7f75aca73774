#pragma once
// The only place that calls MPI. Point-to-point messages are counted (messages and bytes
// sent to other ranks) so a run can report them per step, as the thesis's Table 3.5.
// <mpi.h> is included by comm.cpp only, so models (and out-of-tree plugins) build without
// MPI's headers.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/exact_sum.hpp"

namespace pdq {

class Comm {
 public:
  // MPI must be initialised (see MpiSession). Comm() is MPI_COMM_WORLD, used by the pdq
  // command; tests run several simulations side by side on sub-communicators, passed as
  // an MPI_Comm (a pointer in Open MPI, hence void* here: comm.cpp checks it).
  Comm();
  explicit Comm(void* mpiComm);
  ~Comm();
  Comm(const Comm&) = delete;
  Comm& operator=(const Comm&) = delete;
  Comm(Comm&& o) noexcept;

  // The ranks of equal `colour` as a communicator of their own (in rank order), freed with
  // the returned Comm; collective over this one. Used to run independent simulations side
  // by side (the trials of a strength search).
  Comm split(int colour) const;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  // Sends `out` to `dest` and receives from `src` (either may be -1: nobody). The receive
  // size is learnt from the message itself, so this is exactly one message per call.
  void sendrecv(const std::vector<char>& out, int dest, std::vector<char>& in, int src, int tag);
  // Same with the receive size known in advance (the halo exchange).
  void sendrecvKnown(const double* out, std::size_t nOut, int dest, double* in, std::size_t nIn,
                     int src, int tag);

  double max(double v) const;
  std::vector<double> max(std::vector<double> v) const;  // element by element, one message
  double min(double v) const;
  long sum(long v) const;
  bool any(bool v) const;
  // Collective: how many of these ranks share this rank's node (its memory).
  int nodeSize() const;
  double sum(ExactSum& acc) const;  // exact, order-independent global sum
  void exactSum(ExactSum& acc) const;
  // Several exact sums in one message; accs[k] holds the global sum after the call.
  void exactSums(std::span<ExactSum> accs) const;
  // Gathers variable-length byte blocks on rank 0 (empty elsewhere).
  std::vector<std::vector<char>> gather(const std::vector<char>& block) const;
  // The same blocks in one buffer, rank r's at [starts[r], starts[r + 1]): no copy per block,
  // for the large ones (a checkpoint's bonds), and no limit on their size.
  std::vector<char> gather(const std::vector<char>& block, std::vector<std::size_t>& starts) const;
  std::vector<char> broadcast(std::vector<char> data) const;  // from rank 0
  void barrier() const;
  [[noreturn]] void abort(int code) const;

  std::uint64_t messages() const { return messages_; }
  std::uint64_t bytes() const { return bytes_; }

 private:
  void* comm_;          // the MPI_Comm
  bool owned_ = false;  // made by split(): freed on destruction
  int rank_ = 0, size_ = 1;
  std::uint64_t messages_ = 0, bytes_ = 0;
};

// RAII: MPI_Init_thread on construction (if not yet initialised), MPI_Finalize on exit.
// Only the main thread calls MPI, unless `threadMultiple` asks for MPI_THREAD_MULTIPLE
// (the pdq command's watchdog thread); threadMultiple() says whether MPI gave it.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv, bool threadMultiple = false);
  bool threadMultiple() const { return multiple_; }
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool owns_ = false, multiple_ = false;
};

}  // namespace pdq
