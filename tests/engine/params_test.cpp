#include "engine/params.hpp"

#include <gtest/gtest.h>

#include "engine/error.hpp"

namespace pdq {
namespace {

TEST(Params, TypedReadsAndDefaults) {
  Params p("model 'x'");
  p.set("dt", "0.5", "in.toml", 3);
  p.set("steps", "100", "in.toml", 4);
  EXPECT_EQ(p.number("dt"), 0.5);
  EXPECT_EQ(p.integer("steps"), 100);
  EXPECT_EQ(p.number("E", 2.0), 2.0);
  EXPECT_NO_THROW(p.checkAllUsed());
}

TEST(Params, ErrorsNameFileLineAndSuggest) {
  Params p("model 'lj'");
  p.set("dtt", "0.5", "case.toml", 7);
  p.number("dt", 0.1);
  try {
    p.checkAllUsed();
    FAIL() << "unknown parameter accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.toml");
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find("did you mean 'dt'"), std::string::npos) << e.what();
  }
  Params q("m");
  q.set("E", "12x", "f.dat", 2);
  EXPECT_THROW(q.number("E"), InputError);
  q.set("E", "nan", "f.dat", 2);
  EXPECT_THROW(q.number("E"), InputError);
  q.set("E", "-1", "f.dat", 2);
  EXPECT_THROW(q.number("E", 1.0, 0.0, 10.0), InputError);
  EXPECT_THROW(q.number("missing"), InputError);
}

}  // namespace
}  // namespace pdq
