// The supernodal solves (engine/supernodal_solve.hpp) on CHOLMOD's own factors: a 3D grid's
// matrix, whose nested-dissection tree is cut into two parts, solved on one thread and on
// two gives the same bits and the solution asked for to single precision; a dense matrix,
// one supernode that no cut splits, is solved alike.
#include "engine/supernodal_solve.hpp"

#include <cholmod.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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
  cholmod_triplet* T = cholmod_allocate_triplet(size, size, t.size(), -1, CHOLMOD_REAL, &c);
  auto* ti = static_cast<int*>(T->i);
  auto* tj = static_cast<int*>(T->j);
  auto* tx = static_cast<double*>(T->x);
  for (const Triplet& e : t) {
    ti[T->nnz] = e.row, tj[T->nnz] = e.col, tx[T->nnz] = e.value;
    ++T->nnz;
  }
  cholmod_sparse* K = cholmod_triplet_to_sparse(T, 0, &c);
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
  s.assign({static_cast<long>(L->n), static_cast<long>(L->nsuper), static_cast<const int*>(L->Perm),
            static_cast<const int*>(L->super), static_cast<const int*>(L->pi),
            static_cast<const int*>(L->s), static_cast<const int*>(L->px)},
           static_cast<const double*>(L->x));
  Solved r;
  r.shares = s.shares();
  r.one.resize(size);
  r.two.resize(size);
  s.solve(b.data(), r.one.data(), 1);
  s.solve(b.data(), r.two.data(), 2);
  for (int i = 0; i < size; ++i) r.error = std::max(r.error, std::fabs(r.one[i] - wanted[i]));
  cholmod_free_factor(&L, &c);
  cholmod_free_sparse(&K, &c);
  cholmod_free_triplet(&T, &c);
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

}  // namespace
}  // namespace pdq
