#include "engine/registry.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

#include "engine/model.hpp"

namespace pdq {

// A kind of its own, so that the test's registrations leave the real tables alone.
using Thing = std::function<int()>;
template <>
Registry<Thing>::Table& Registry<Thing>::table() {
  static Table t{"thing"};
  return t;
}

namespace {

using testing::HasSubstr;

TEST(Registry, FindsByNameAndSuggestsTheNearest) {
  Registry<Thing>::add("alpha", "the first", [] { return 1; });
  Registry<Thing>::add("beta", "the second", [] { return 2; });
  EXPECT_EQ(Registry<Thing>::get("beta")(), 2);
  try {
    Registry<Thing>::get("alpah", "case.toml", 4);
    FAIL() << "unknown name accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.toml");
    EXPECT_EQ(e.line(), 4);
    EXPECT_THAT(e.what(), HasSubstr("unknown thing 'alpah' (did you mean 'alpha'?)"));
    EXPECT_THAT(e.what(), HasSubstr("known: alpha, beta"));
  }
  const auto all = Registry<Thing>::list();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].second, "the first");
}

// Runs after the test above (gtest keeps the order within a file): a second "alpha" is
// refused, the first stays, and every look-up afterwards reports the clash.
TEST(Registry, RefusesADuplicateName) {
  EXPECT_FALSE(Registry<Thing>::add("alpha", "an impostor", [] { return 3; }));
  try {
    Registry<Thing>::get("alpha");
    FAIL() << "duplicate registration went unnoticed";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("thing 'alpha' is registered twice (\"the first\" and "
                                    "\"an impostor\")"));
  }
  EXPECT_THROW(Registry<Thing>::list(), Error);
}

TEST(Registry, BuiltInModelsAreUnique) {
  // list() would throw had two models claimed one name.
  EXPECT_FALSE(ModelRegistry::list().empty());
}

}  // namespace
}  // namespace pdq
