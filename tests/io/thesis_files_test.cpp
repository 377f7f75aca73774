// The thesis's input files: a problem written by writeThesisInput reads back the same, and
// each kind of bad input is reported with its file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/error.hpp"
#include "io/thesis_input.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

const std::string kDir = "out_thesis_files";

Problem writeSpringSet() {
  std::filesystem::remove_all(kDir);
  const Params mp = test::params({{"horizon", "1.5"}, {"dt", "0.02"}});
  Problem pb = makeProblem("spring", mp, {});
  pb.particles = test::cubicBlock(pb.model->schema(), 4, 3, 2, 0.5);
  pb.particles.alterRow(5)[3] = 0.1 / 3.0;  // a value that needs all 17 digits
  pb.run.procs = {2, 1, 1};
  pb.run.minCellSize = 1.6;
  pb.run.steps = 25;
  pb.output.restartEvery = 5;
  writeThesisInput(kDir, pb, mp);
  return pb;
}

void replaceLine(const std::string& file, int line, const std::string& text) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  lines.at(line - 1) = text;
  std::ofstream out(file);
  for (const auto& l : lines) out << l << "\n";
}

void expectError(const std::string& file, int line, const std::string& words) {
  try {
    readThesisInput(kDir);
    FAIL() << "accepted bad input: " << words;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(ThesisFiles, RoundTrip) {
  const Problem written = writeSpringSet();
  const Problem read = readThesisInput(kDir);
  EXPECT_EQ(read.modelName, "spring");
  EXPECT_EQ(read.run.procs, written.run.procs);
  EXPECT_EQ(read.run.minCellSize, 1.6);
  EXPECT_EQ(read.run.steps, 25);
  EXPECT_EQ(read.output.restartEvery, 5);
  EXPECT_EQ(read.particles.gid, written.particles.gid);
  EXPECT_EQ(read.particles.fixed, written.particles.fixed);
  EXPECT_EQ(read.particles.alter, written.particles.alter);  // bit for bit
}

TEST(ThesisFiles, BadInputNamesFileAndLine) {
  const std::string fixed = kDir + "/ParticleFixedAttrs.dat",
                    alter = kDir + "/ParticleAlterAttrs.dat", user = kDir + "/pdQUserInput.dat",
                    input = kDir + "/pdQInput.dat";
  struct Bad {
    std::string file;
    int line;
    std::string text, words;  // the line's new text, the message's words
  };
  const std::vector<Bad> cases = {
      {fixed, 3, "2 0.5 0.0x 0", "'0.0x' is not a number"},
      {fixed, 3, "2 0.5 0.0", "expected 4 numbers (id X Y Z), found 3"},
      {fixed, 4, "1 1.0 0 0", "duplicate global ID 1"},
      {alter, 2, "1 nan 0 0 0 0 0", "'nan' is not a finite number"},
      {alter, 2, "1 inf 0 0 0 0 0", "not a finite number"},
      {user, 1, "model sprong", "did you mean 'spring'"},
      {user, 2, "horizn 1.5", "unknown parameter 'horizn'"},
      {input, 2, "abc   # minimum cell size", "'abc' is not a number"},
      {input, 3, "-1   # number of time steps", "-1 time steps needs hold_time"},
      {input, 4, "hold_time 2", "as the number of steps or as hold_time (with steps -1), not both"},
  };
  for (const Bad& c : cases) {
    writeSpringSet();
    replaceLine(c.file, c.line, c.text);
    expectError(c.file, c.line, c.words);
  }
  writeSpringSet();
  std::filesystem::remove(alter);
  expectError(alter, 0, "cannot open");
}

}  // namespace
}  // namespace pdq
