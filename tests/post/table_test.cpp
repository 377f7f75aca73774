// Reading text tables for plots: headers, separators, and errors that name the line.
#include "post/table.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "engine/error.hpp"

namespace pdq {
namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(Table, HeaderFromCommentOrFirstLine) {
  write("hist.dat", "# pdq history\n# step time load\n0 0 0\n10 1e-3 2.5\n\n20 2e-3 -4\n");
  const post::Table t = post::readTable("hist.dat");
  EXPECT_EQ(t.names, (std::vector<std::string>{"step", "time", "load"}));
  EXPECT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.column("load"), (std::vector<double>{0, 2.5, -4}));
  EXPECT_EQ(t.column("time")[1], 1e-3);
  write("ld.csv", "displacement,load\n0,0\n0.5,+12\n");
  const post::Table c = post::readTable("ld.csv");
  EXPECT_EQ(c.names, (std::vector<std::string>{"displacement", "load"}));
  EXPECT_EQ(c.column("load")[1], 12);
  write("plain.txt", "1 2\n3 4\n");
  EXPECT_EQ(post::readTable("plain.txt").names, (std::vector<std::string>{"1", "2"}));
}

TEST(Table, ErrorsNameTheLine) {
  write("short.dat", "# a b\n1 2\n3\n");
  try {
    post::readTable("short.dat");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
  }
  write("word.dat", "a b\n1 x2\n");
  try {
    post::readTable("word.dat");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("'x2'"), std::string::npos);
  }
  write("hist.dat", "# step load\n0 1\n");
  try {
    post::readTable("hist.dat").column("laod");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'load'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(post::readTable("missing.dat"), InputError);
  write("empty.dat", "# nothing\n");
  EXPECT_THROW(post::readTable("empty.dat"), InputError);
}

}  // namespace
}  // namespace pdq
