// The supernodal factorisation and solves (engine/supernodal_factor.hpp,
// engine/supernodal_solve.hpp) on CHOLMOD's analyses. A 3D grid's matrix: its factor on one
// thread and on two is the same bits and CHOLMOD's own factor to round-off, its large
// supernodes cut in two; a matrix that is not positive definite is told. The solves: the
// grid's nested-dissection tree is cut into two parts, solved on one thread and on two gives
// the same bits and the solution asked for to single precision; a dense matrix, one
// supernode that no cut splits, is solved alike. The helper thread waits for both jobs
// whatever they throw.
#include <cholmod.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include "engine/helper_thread.hpp"
#include "engine/supernodal_factor.hpp"
#include "engine/supernodal_solve.hpp"

namespace pdq {
namespace {

// The lower half of a symmetric positive definite matrix, as (row, column, value).
struct Triplet {
  int row, col;
  double value;
};

// K = 7-point Laplacian of an n³ grid with 3 coupled DOFs a point, plus 0.1 on the diagonal.
std::vector<Triplet> gridMatrix(int n, int& size) {
  const int d = 3;
  auto at = [&](int x, int y, int z, int k) { return d * ((z * n + y) * n + x) + k; };
  std::vector<Triplet> t;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int k = 0; k < d; ++k) {
          const int i = at(x, y, z, k);
          t.push_back({i, i, 6.1 + 0.5 * k});
          if (k > 0) t.push_back({i, at(x, y, z, k - 1), 0.3});
          if (x > 0) t.push_back({i, at(x - 1, y, z, k), -1.0});
          if (y > 0) t.push_back({i, at(x, y - 1, z, k), -1.0});
          if (z > 0) t.push_back({i, at(x, y, z - 1, k), -1.0});
        }
  size = d * n * n * n;
  return t;
}

// A dense matrix: 4 + n on the diagonal, 1 elsewhere.
std::vector<Triplet> denseMatrix(int n, int& size) {
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) t.push_back({i, j, i == j ? 4.0 + n : 1.0});
  size = n;
  return t;
}

// The lower half by compressed columns (CHOLMOD's).
cholmod_sparse* sparse(const std::vector<Triplet>& t, int size, cholmod_common& c) {
  cholmod_triplet* T = cholmod_allocate_triplet(size, size, t.size(), -1, CHOLMOD_REAL, &c);
  auto* ti = static_cast<int*>(T->i);
  auto* tj = static_cast<int*>(T->j);
  auto* tx = static_cast<double*>(T->x);
  for (const Triplet& e : t) {
    ti[T->nnz] = e.row, tj[T->nnz] = e.col, tx[T->nnz] = e.value;
    ++T->nnz;
  }
  cholmod_sparse* K = cholmod_triplet_to_sparse(T, 0, &c);
  cholmod_free_triplet(&T, &c);
  return K;
}

SupernodalLayout layout(const cholmod_factor* L) {
  return {static_cast<long>(L->n),          static_cast<long>(L->nsuper),
          static_cast<const int*>(L->Perm), static_cast<const int*>(L->super),
          static_cast<const int*>(L->pi),   static_cast<const int*>(L->s),
          static_cast<const int*>(L->px)};
}

struct Factored {
  bool ok = false, okTwo = false;
  std::vector<double> one, two, cholmod;  // on one thread, on two, CHOLMOD's
  double cutShare = 0;
};

Factored factorBoth(const std::vector<Triplet>& t, int size) {
  cholmod_common c;
  cholmod_start(&c);
  c.print = 0;
  c.supernodal = CHOLMOD_SUPERNODAL;
  cholmod_sparse* K = sparse(t, size, c);
  cholmod_factor* L = cholmod_analyze(K, &c);
  EXPECT_TRUE(L->is_super);
  Factored r;
  SupernodalFactor f;
  f.analyse(layout(L), static_cast<const int*>(K->p), static_cast<const int*>(K->i));
  const std::size_t entries = static_cast<const int*>(L->px)[L->nsuper];
  r.ok = f.factorise(static_cast<const double*>(K->x), nullptr);
  r.one.assign(f.values(), f.values() + entries);
  HelperThread helper;
  r.okTwo = f.factorise(static_cast<const double*>(K->x), &helper);
  r.two.assign(f.values(), f.values() + entries);
  r.cutShare = f.cutShare();
  cholmod_factorize(K, L, &c);
  if (c.status == CHOLMOD_OK) {
    const auto* x = static_cast<const double*>(L->x);
    r.cholmod.assign(x, x + entries);
  }
  cholmod_free_factor(&L, &c);
  cholmod_free_sparse(&K, &c);
  cholmod_finish(&c);
  return r;
}

TEST(SupernodalFactor, GridFactorIsTheSameBitsOnOneThreadOrTwoAndCholmodsToRoundOff) {
  ASSERT_TRUE(SupernodalFactor::blasFromTwoThreads())
      << "the BLAS is not OpenBLAS's pthreads build (Debian's libopenblas0-pthread): "
         "the factorisation would take one thread";
  int size = 0;
  const std::vector<Triplet> t = gridMatrix(14, size);
  const Factored r = factorBoth(t, size);
  ASSERT_TRUE(r.ok);
  ASSERT_TRUE(r.okTwo);
  EXPECT_GT(r.cutShare, 0.5) << "the separators' supernodes are cut in two";
  EXPECT_TRUE(r.one == r.two) << "two threads gave other bits";
  ASSERT_EQ(r.cholmod.size(), r.one.size());
  double most = 0, differs = 0;
  for (std::size_t k = 0; k < r.one.size(); ++k) {
    most = std::max(most, std::fabs(r.cholmod[k]));
    differs = std::max(differs, std::fabs(r.one[k] - r.cholmod[k]));
  }
  EXPECT_LT(differs, 1e-13 * most);
}

TEST(SupernodalFactor, MatrixNotPositiveDefiniteIsTold) {
  int size = 0;
  std::vector<Triplet> t = gridMatrix(14, size);
  for (Triplet& e : t)
    if (e.row == e.col && e.row == size - 5) e.value = -1;  // a negative pivot near the end
  const Factored r = factorBoth(t, size);
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.okTwo);
  EXPECT_TRUE(r.cholmod.empty()) << "CHOLMOD agrees";
}

struct Solved {
  std::vector<double> one, two;  // on one thread and on two
  std::array<double, 3> shares{};
  double error = 0;  // the largest |x − wanted| of `one`
};

Solved solveBoth(const std::vector<Triplet>& t, int size) {
  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = CHOLMOD_SUPERNODAL;
  c.final_ll = 1;
  cholmod_sparse* K = sparse(t, size, c);
  cholmod_factor* L = cholmod_analyze(K, &c);
  cholmod_factorize(K, L, &c);
  EXPECT_EQ(c.status, CHOLMOD_OK);
  EXPECT_TRUE(L->is_super);

  // b = K wanted.
  std::vector<double> wanted(size), b(size, 0.0);
  for (int i = 0; i < size; ++i) wanted[i] = std::sin(0.37 * i + 1.3);
  for (const Triplet& e : t) {
    b[e.row] += e.value * wanted[e.col];
    if (e.row != e.col) b[e.col] += e.value * wanted[e.row];
  }

  SupernodalSolve s;
  s.assign(layout(L), static_cast<const double*>(L->x));
  Solved r;
  r.shares = s.shares();
  r.one.resize(size);
  r.two.resize(size);
  HelperThread helper;
  s.solve(b.data(), r.one.data(), nullptr);
  s.solve(b.data(), r.two.data(), &helper);
  for (int i = 0; i < size; ++i) r.error = std::max(r.error, std::fabs(r.one[i] - wanted[i]));
  cholmod_free_factor(&L, &c);
  cholmod_free_sparse(&K, &c);
  cholmod_finish(&c);
  return r;
}

void expectSameBitsToSinglePrecision(const Solved& r) {
  EXPECT_TRUE(r.one == r.two) << "two threads gave other bits";
  // Single-precision values of a well-conditioned factor: about 1e-7 of the solution.
  EXPECT_LT(r.error, 1e-5);
  EXPECT_GT(r.error, 1e-13) << "the solves were expected to read the factor in single precision";
}

TEST(SupernodalSolve, GridTreeCutInTwoPartsSolvesTheSameBitsOnOneThreadOrTwo) {
  int size = 0;
  const std::vector<Triplet> t = gridMatrix(14, size);
  const Solved r = solveBoth(t, size);
  // Nested dissection halves the grid: each part holds a good share of the factor.
  EXPECT_GT(r.shares[0], 0.25);
  EXPECT_GT(r.shares[1], 0.25);
  EXPECT_LT(r.shares[2], 0.4);
  EXPECT_NEAR(r.shares[0] + r.shares[1] + r.shares[2], 1.0, 1e-12);
  expectSameBitsToSinglePrecision(r);
}

TEST(SupernodalSolve, OneSupernodeIsNotCutAndSolvesAlike) {
  int size = 0;
  const std::vector<Triplet> t = denseMatrix(40, size);
  const Solved r = solveBoth(t, size);
  EXPECT_EQ(r.shares[0], 0.0);
  EXPECT_EQ(r.shares[1], 0.0);
  EXPECT_EQ(r.shares[2], 1.0);
  expectSameBitsToSinglePrecision(r);
}

// The helper thread waits for both jobs whatever they throw, and gives back what they threw.
TEST(HelperThread, BothJobsFinishAndWhatEitherThrewIsRethrown) {
  HelperThread helper;
  int done = 0;
  auto slow = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    done = 1;
  };
  EXPECT_THROW(helper.together([] { throw std::runtime_error("one"); }, slow), std::runtime_error);
  EXPECT_EQ(done, 1) << "the helper's job had not finished when together() returned";
  EXPECT_THROW(helper.together([] {}, [] { throw std::logic_error("other"); }), std::logic_error);
  int both = 0;
  helper.together([&] { both += 1; }, [&] { both += 2; });
  EXPECT_EQ(both, 3) << "the helper serves again after a job threw";
}

}  // namespace
}  // namespace pdq
