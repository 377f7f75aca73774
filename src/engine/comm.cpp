#include "engine/comm.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <type_traits>

namespace pdq {

// comm.hpp holds the communicator as a void* so that it needs no <mpi.h>.
static_assert(std::is_pointer_v<MPI_Comm>, "pdq::Comm stores MPI_Comm as a pointer (Open MPI)");

namespace {
MPI_Comm mpi(void* comm) { return static_cast<MPI_Comm>(comm); }

// How a rank waits for the others. Within a step (a halo, a reduction behind a slightly
// busier rank) it polls for up to 2 ms, since a sleep there, woken late by the scheduler,
// slows every step of ranks with cores of their own; then it sleeps between polls, each
// sleep a quarter of the time waited so far (a wake-up costs CPU time too, and the wait
// overshoots by at most a quarter). Waiting for rank 0's own work (a broadcast after a
// serial solve or factorisation) it polls for 0.1 ms only and sleeps a sixteenth of the time
// waited: a rank that polls slows rank 0's work when the two share a physical core, and
// rank 0 cannot finish sending before the sleeper wakes (docs/quasi-static.md, "Solves in
// single precision"). Waiting by polling alone (MPI's own waits) would burn the CPU time a
// late rank needs when ranks share cores, and count the wait as work.
enum class Wait { WithinStep, ForRoot };

template <class Ready>
void poll(Ready&& ready, Wait wait) {
  using Clock = std::chrono::steady_clock;
  using us = std::chrono::microseconds;
  constexpr us kShortestNap(20), kLongestNap(5000);
  const us spin(wait == Wait::WithinStep ? 2000 : 100);
  const int share = wait == Wait::WithinStep ? 4 : 16;
  if (ready()) return;
  const auto start = Clock::now();
  while (Clock::now() - start < spin)
    if (ready()) return;
  while (!ready()) {
    const auto waited = std::chrono::duration_cast<us>(Clock::now() - start);
    std::this_thread::sleep_for(std::clamp(waited / share, kShortestNap, kLongestNap));
  }
}

void await(int n, MPI_Request* reqs, Wait wait = Wait::WithinStep) {
  poll(
      [&] {
        int done = 0;
        MPI_Testall(n, reqs, &done, MPI_STATUSES_IGNORE);
        return done != 0;
      },
      wait);
}

// MPI_Allreduce, waited for as above.
void allreduce(const void* in, void* out, int n, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  MPI_Request req;
  MPI_Iallreduce(in, out, n, type, op, comm, &req);
  await(1, &req);
}
}  // namespace

Comm::Comm() : Comm(MPI_COMM_WORLD) {}

Comm::Comm(void* mpiComm) : comm_(mpiComm) {
  MPI_Comm_rank(mpi(comm_), &rank_);
  MPI_Comm_size(mpi(comm_), &size_);
}

Comm::~Comm() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (owned_ && !finalized) {
    MPI_Comm c = mpi(comm_);
    MPI_Comm_free(&c);
  }
}

Comm::Comm(Comm&& o) noexcept
    : comm_(o.comm_),
      owned_(o.owned_),
      rank_(o.rank_),
      size_(o.size_),
      messages_(o.messages_),
      bytes_(o.bytes_) {
  o.owned_ = false;
}

Comm Comm::split(int colour) const {
  MPI_Comm sub;
  MPI_Comm_split(mpi(comm_), colour, rank_, &sub);
  Comm c(sub);
  c.owned_ = true;
  return c;
}

void Comm::sendrecv(const std::vector<char>& out, int dest, std::vector<char>& in, int src,
                    int tag) {
  MPI_Request req[2] = {MPI_REQUEST_NULL, MPI_REQUEST_NULL};
  if (dest >= 0) {
    MPI_Isend(out.data(), static_cast<int>(out.size()), MPI_BYTE, dest, tag, mpi(comm_), &req[0]);
    if (dest != rank_) {
      ++messages_;
      bytes_ += out.size();
    }
  }
  in.clear();
  if (src >= 0) {
    // The size is learnt from the message's envelope before it is received.
    MPI_Status st;
    MPI_Message msg;
    poll(
        [&] {
          int found = 0;
          MPI_Improbe(src, tag, mpi(comm_), &found, &msg, &st);
          return found != 0;
        },
        Wait::WithinStep);
    int n = 0;
    MPI_Get_count(&st, MPI_BYTE, &n);
    in.resize(n);
    MPI_Imrecv(in.data(), n, MPI_BYTE, &msg, &req[1]);
  }
  await(2, req);
}

void Comm::sendrecvKnown(const double* out, std::size_t nOut, int dest, double* in, std::size_t nIn,
                         int src, int tag) {
  if (dest >= 0 && dest != rank_) {
    ++messages_;
    bytes_ += nOut * sizeof(double);
  }
  MPI_Request req[2];
  MPI_Irecv(in, static_cast<int>(nIn), MPI_DOUBLE, src >= 0 ? src : MPI_PROC_NULL, tag, mpi(comm_),
            &req[0]);
  MPI_Isend(out, static_cast<int>(nOut), MPI_DOUBLE, dest >= 0 ? dest : MPI_PROC_NULL, tag,
            mpi(comm_), &req[1]);
  await(2, req);
}

double Comm::max(double v) const {
  double r;
  allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MAX, mpi(comm_));
  return r;
}

std::vector<double> Comm::max(std::vector<double> v) const {
  allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_MAX, mpi(comm_));
  return v;
}

double Comm::min(double v) const {
  double r;
  allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MIN, mpi(comm_));
  return r;
}

long Comm::sum(long v) const {
  long r;
  allreduce(&v, &r, 1, MPI_LONG, MPI_SUM, mpi(comm_));
  return r;
}

int Comm::nodeSize() const {
  MPI_Comm node;
  MPI_Comm_split_type(mpi(comm_), MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  int size = 1;
  MPI_Comm_size(node, &size);
  MPI_Comm_free(&node);
  return size;
}

bool Comm::any(bool v) const {
  int x = v ? 1 : 0, r = 0;
  allreduce(&x, &r, 1, MPI_INT, MPI_MAX, mpi(comm_));
  return r != 0;
}

void Comm::exactSum(ExactSum& acc) const {
  acc.normalize();
  allreduce(MPI_IN_PLACE, acc.limbs().data(), ExactSum::kLimbs, MPI_INT64_T, MPI_SUM, mpi(comm_));
  allreduce(MPI_IN_PLACE, acc.specials().data(), 3, MPI_INT64_T, MPI_SUM, mpi(comm_));
  acc.normalize();
}

void Comm::exactSums(std::span<ExactSum> accs) const {
  constexpr std::size_t kWidth = ExactSum::kLimbs + 3;
  std::vector<std::int64_t> all(kWidth * accs.size());
  for (std::size_t k = 0; k < accs.size(); ++k) {
    accs[k].normalize();
    std::copy(accs[k].limbs().begin(), accs[k].limbs().end(), all.begin() + kWidth * k);
    std::copy(accs[k].specials().begin(), accs[k].specials().end(),
              all.begin() + kWidth * k + ExactSum::kLimbs);
  }
  allreduce(MPI_IN_PLACE, all.data(), static_cast<int>(all.size()), MPI_INT64_T, MPI_SUM,
            mpi(comm_));
  for (std::size_t k = 0; k < accs.size(); ++k) {
    std::copy_n(all.begin() + kWidth * k, ExactSum::kLimbs, accs[k].limbs().begin());
    std::copy_n(all.begin() + kWidth * k + ExactSum::kLimbs, 3, accs[k].specials().begin());
    accs[k].normalize();
  }
}

double Comm::sum(ExactSum& acc) const {
  exactSum(acc);
  return acc.value();
}

std::vector<char> Comm::gather(const std::vector<char>& block,
                               std::vector<std::size_t>& starts) const {
  // Sent rank by rank in pieces under MPI's int count, so that no size is too large.
  constexpr std::size_t kPiece = std::size_t{1} << 30;
  constexpr int kTag = 30011;
  unsigned long n = block.size();
  std::vector<unsigned long> counts(size_);
  MPI_Gather(&n, 1, MPI_UNSIGNED_LONG, counts.data(), 1, MPI_UNSIGNED_LONG, 0, mpi(comm_));
  starts.assign(1, 0);
  if (!root()) {
    for (std::size_t at = 0; at < block.size(); at += kPiece)
      MPI_Send(block.data() + at, static_cast<int>(std::min(kPiece, block.size() - at)), MPI_BYTE,
               0, kTag, mpi(comm_));
    return {};
  }
  for (int r = 0; r < size_; ++r) starts.push_back(starts.back() + counts[r]);
  std::vector<char> all(starts.back());
  std::copy(block.begin(), block.end(), all.begin());
  for (int r = 1; r < size_; ++r)
    for (std::size_t at = starts[r]; at < starts[r + 1]; at += kPiece)
      MPI_Recv(all.data() + at, static_cast<int>(std::min(kPiece, starts[r + 1] - at)), MPI_BYTE, r,
               kTag, mpi(comm_), MPI_STATUS_IGNORE);
  return all;
}

std::vector<std::vector<char>> Comm::gather(const std::vector<char>& block) const {
  std::vector<std::size_t> starts;
  const std::vector<char> all = gather(block, starts);
  std::vector<std::vector<char>> out;
  if (root())
    for (int r = 0; r < size_; ++r)
      out.emplace_back(all.begin() + starts[r], all.begin() + starts[r + 1]);
  return out;
}

// Waited for as for rank 0's own work: ranks waiting long for it (a quasi-static strength
// run on fewer ranks than the search has, the solves of its assembled stiffness) sleep
// instead of holding a core.
std::vector<char> Comm::broadcast(std::vector<char> data) const {
  long n = static_cast<long>(data.size());
  MPI_Request req;
  MPI_Ibcast(&n, 1, MPI_LONG, 0, mpi(comm_), &req);
  await(1, &req, Wait::ForRoot);
  data.resize(n);
  MPI_Ibcast(data.data(), static_cast<int>(n), MPI_BYTE, 0, mpi(comm_), &req);
  await(1, &req, Wait::ForRoot);
  return data;
}

void Comm::barrier() const { MPI_Barrier(mpi(comm_)); }

void Comm::abort(int code) const {
  MPI_Abort(mpi(comm_), code);
  std::abort();
}

namespace {
// Open MPI tries its UCX messaging layer first, and where UCX finds no network to drive (a
// laptop, this kind of virtual machine) it declines only after a search, and Open MPI takes its
// own layer over shared memory (ob1). When every rank is on this node (mpirun says so), or
// the process was started alone, that shared-memory layer serves, so unless the user chose
// a layer, it is asked for at once. Jobs over several nodes, or started by another launcher
// (srun), keep Open MPI's choice.
void preferSharedMemoryOnOneNode() {
  if (std::getenv("OMPI_MCA_pml")) return;
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const bool alone = !size && !std::getenv("PMIX_RANK") && !std::getenv("PMI_RANK") &&
                     !std::getenv("SLURM_PROCID");
  if (alone || (size && local && std::string(size) == local)) setenv("OMPI_MCA_pml", "ob1", 0);
}
}  // namespace

MpiSession::MpiSession(int* argc, char*** argv, bool threadMultiple) {
  int initialised = 0, provided = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    preferSharedMemoryOnOneNode();
    MPI_Init_thread(argc, argv, threadMultiple ? MPI_THREAD_MULTIPLE : MPI_THREAD_FUNNELED,
                    &provided);
    owns_ = true;
  } else {
    MPI_Query_thread(&provided);
  }
  multiple_ = provided >= MPI_THREAD_MULTIPLE;
}

MpiSession::~MpiSession() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (owns_ && !finalised) MPI_Finalize();
}

}  // namespace pdq
