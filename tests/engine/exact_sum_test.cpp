#include "engine/exact_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace pdq {
namespace {

TEST(ExactSum, OrderDoesNotMatter) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> v;
  for (int i = 0; i < 20000; ++i)
    v.push_back(std::ldexp(u(rng), static_cast<int>(rng() % 80) - 40));
  ExactSum a;
  for (double x : v) a.add(x);
  std::shuffle(v.begin(), v.end(), rng);
  ExactSum b, c;
  for (std::size_t i = 0; i < v.size(); ++i) (i % 3 ? b : c).add(v[i]);
  b += c;
  EXPECT_EQ(a.value(), b.value());
}

TEST(ExactSum, CancellationIsExact) {
  ExactSum s;
  s.add(1e100);
  s.add(1.0);
  s.add(-1e100);
  EXPECT_EQ(s.value(), 1.0);  // plain double addition gives 0
  ExactSum t;
  t.add(0.1);
  t.add(0.2);
  t.add(-0.3);
  // The exact sum of the three doubles is 2^-55 (0.1+0.2 rounds up in plain arithmetic).
  EXPECT_EQ(t.value(), std::ldexp(1.0, -55));
}

TEST(ExactSum, NegativeTotalsAndSpecials) {
  ExactSum s;
  s.add(-2.5);
  s.add(0.25);
  EXPECT_EQ(s.value(), -2.25);
  s.add(std::nan(""));
  EXPECT_TRUE(std::isnan(s.value()));
  ExactSum tiny;
  tiny.add(5e-324);
  tiny.add(5e-324);
  EXPECT_EQ(tiny.value(), 1e-323);
}

}  // namespace
}  // namespace pdq
