#pragma once
// Solves with a supernodal Cholesky factor L Lᵀ = P K Pᵀ laid out as CHOLMOD lays it out,
// its values held in single precision: the factor is the quasi-static relaxation's
// preconditioner, which converges on a residual computed in double whatever the factor's
// rounding, and the solves, which stream the whole factor twice, read half the bytes
// (docs/quasi-static.md, "Solves in single precision"). The arithmetic is double.
//
// The elimination tree is cut into two parts that share no supernode's update, with the
// supernodes above both (the separators) left to the end, so that two threads can take the
// parts at once ("Two parts of the elimination tree"). Every sum runs in an order fixed by
// the factor alone: the same bits with one thread or two.
#include <array>
#include <vector>

namespace pdq {

class HelperThread;

// A supernodal factor's arrays, as CHOLMOD's cholmod_factor holds them (read, not kept).
struct SupernodalLayout {
  long n = 0, nsuper = 0;
  const int* perm = nullptr;   // row k of the factor is unknown perm[k]
  const int* super = nullptr;  // supernode s holds columns super[s] .. super[s + 1] − 1
  const int* pi = nullptr;     // and rows rows[pi[s]] .. rows[pi[s + 1] − 1] (ascending)
  const int* rows = nullptr;
  const int* px = nullptr;  // its dense block, rows × columns by columns, at values[px[s]]
};

class SupernodalSolve {
 public:
  SupernodalSolve();
  ~SupernodalSolve();
  SupernodalSolve(const SupernodalSolve&) = delete;
  SupernodalSolve& operator=(const SupernodalSolve&) = delete;
  // Copies the structure and, in single precision, each column from its diagonal down;
  // finds the two parts (none when the tree has no cut that would save a fifth of a
  // solve's work).
  void assign(const SupernodalLayout& L, const double* values);
  // x = K⁻¹ b, both in the unknowns' order; with a helper and the tree cut, part two on the
  // helper's thread.
  void solve(const double* b, double* x, HelperThread* helper);
  // The shares of the factor's entries in part one, part two and above them (all in the
  // last when the tree is not cut).
  std::array<double, 3> shares() const;

 private:
  struct Deferred {
    int row;
    double value;
  };
  // Forward (L y' = y) over supernodes [s0, s1); with `later`, the updates of rows from
  // `limit` on are kept there, in order, instead of added to y.
  void forward(long s0, long s1, std::vector<double>& w, std::vector<Deferred>* later, int limit);
  void backward(long s0, long s1, std::vector<double>& w);  // Lᵀ y'' = y', s1 − 1 down to s0
  long work(long s0, long s1) const { return workBefore_[s1] - workBefore_[s0]; }

  long n_ = 0, nsuper_ = 0;
  std::vector<int> perm_, super_, pi_, rows_;
  std::vector<float> values_;        // per supernode, its columns from the diagonal down
  std::vector<long> packed_;         // where each supernode starts in values_
  std::vector<long> workBefore_;     // the entries of supernodes [0, s)
  long cut_ = 0, top_ = 0;           // parts [0, cut_) and [cut_, top_); [top_, nsuper_) after
  std::vector<double> y_, w0_, w1_;  // the solve's unknowns (factor order) and workspaces
  std::vector<Deferred> later_;
};

}  // namespace pdq
