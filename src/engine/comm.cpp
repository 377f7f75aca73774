#include "engine/comm.hpp"

#include <mpi.h>

#include <algorithm>
#include <type_traits>

namespace pdq {

// comm.hpp holds the communicator as a void* so that it needs no <mpi.h>.
static_assert(std::is_pointer_v<MPI_Comm>, "pdq::Comm stores MPI_Comm as a pointer (Open MPI)");

namespace {
MPI_Comm mpi(void* comm) { return static_cast<MPI_Comm>(comm); }
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
  MPI_Request req = MPI_REQUEST_NULL;
  if (dest >= 0) {
    MPI_Isend(out.data(), static_cast<int>(out.size()), MPI_BYTE, dest, tag, mpi(comm_), &req);
    if (dest != rank_) {
      ++messages_;
      bytes_ += out.size();
    }
  }
  in.clear();
  if (src >= 0) {
    MPI_Status st;
    MPI_Probe(src, tag, mpi(comm_), &st);
    int n = 0;
    MPI_Get_count(&st, MPI_BYTE, &n);
    in.resize(n);
    MPI_Recv(in.data(), n, MPI_BYTE, src, tag, mpi(comm_), MPI_STATUS_IGNORE);
  }
  MPI_Wait(&req, MPI_STATUS_IGNORE);
}

void Comm::sendrecvKnown(const double* out, std::size_t nOut, int dest, double* in, std::size_t nIn,
                         int src, int tag) {
  if (dest >= 0 && dest != rank_) {
    ++messages_;
    bytes_ += nOut * sizeof(double);
  }
  MPI_Sendrecv(out, static_cast<int>(nOut), MPI_DOUBLE, dest >= 0 ? dest : MPI_PROC_NULL, tag, in,
               static_cast<int>(nIn), MPI_DOUBLE, src >= 0 ? src : MPI_PROC_NULL, tag, mpi(comm_),
               MPI_STATUS_IGNORE);
}

double Comm::max(double v) const {
  double r;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MAX, mpi(comm_));
  return r;
}

std::vector<double> Comm::max(std::vector<double> v) const {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_MAX,
                mpi(comm_));
  return v;
}

double Comm::min(double v) const {
  double r;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MIN, mpi(comm_));
  return r;
}

long Comm::sum(long v) const {
  long r;
  MPI_Allreduce(&v, &r, 1, MPI_LONG, MPI_SUM, mpi(comm_));
  return r;
}

bool Comm::any(bool v) const {
  int x = v ? 1 : 0, r = 0;
  MPI_Allreduce(&x, &r, 1, MPI_INT, MPI_MAX, mpi(comm_));
  return r != 0;
}

void Comm::exactSum(ExactSum& acc) const {
  acc.normalize();
  MPI_Allreduce(MPI_IN_PLACE, acc.limbs().data(), ExactSum::kLimbs, MPI_INT64_T, MPI_SUM,
                mpi(comm_));
  MPI_Allreduce(MPI_IN_PLACE, acc.specials().data(), 3, MPI_INT64_T, MPI_SUM, mpi(comm_));
  acc.normalize();
}

double Comm::sum(ExactSum& acc) const {
  exactSum(acc);
  return acc.value();
}

std::vector<std::vector<char>> Comm::gather(const std::vector<char>& block) const {
  int n = static_cast<int>(block.size());
  std::vector<int> counts(size_), displs(size_);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, mpi(comm_));
  std::vector<char> all;
  if (root()) {
    for (int r = 1; r < size_; ++r) displs[r] = displs[r - 1] + counts[r - 1];
    all.resize(size_ ? displs[size_ - 1] + counts[size_ - 1] : 0);
  }
  MPI_Gatherv(block.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, 0,
              mpi(comm_));
  std::vector<std::vector<char>> out;
  if (root())
    for (int r = 0; r < size_; ++r)
      out.emplace_back(all.begin() + displs[r], all.begin() + displs[r] + counts[r]);
  return out;
}

std::vector<char> Comm::broadcast(std::vector<char> data) const {
  long n = static_cast<long>(data.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, mpi(comm_));
  data.resize(n);
  MPI_Bcast(data.data(), static_cast<int>(n), MPI_BYTE, 0, mpi(comm_));
  return data;
}

void Comm::barrier() const { MPI_Barrier(mpi(comm_)); }

void Comm::abort(int code) const {
  MPI_Abort(mpi(comm_), code);
  std::abort();
}

MpiSession::MpiSession(int* argc, char*** argv, bool threadMultiple) {
  int initialised = 0, provided = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
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
