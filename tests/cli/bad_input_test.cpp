// Bad input: each case must stop before step 0 with a message naming the file and line and
// the problem, exit with code 1, and leave no output behind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>

#include "pdq_process.hpp"
#include "spring_case.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;
using testing::HasSubstr;
using testing::Not;

namespace {

struct Case {
  const char* name;
  std::function<void(const std::string& dir)> spoil;
  std::string expected;  // "file:line: problem" (part of the message)
};

// Line numbers below refer to the files springCase writes: the scenario's keys are at
// steps 2, [model] 4, name 5, critical_stretch 6, dt 7, horizon 8, fixed 11, alter 12,
// the first [[particles.set]] 14 (attribute 15), min_cell_size 32, [output] 34,
// dir 35, restart_every 36, history_ids 39; particle i of the files is on line i + 2.
const std::vector<Case> cases = {
    {"malformed number", [](auto d) { edit(d + "/fixed.dat", "\n5 5 0 0", "\n5 5 O 0"); },
     "fixed.dat:7: 'O' is not a number (column 3)"},
    {"missing number", [](auto d) { edit(d + "/fixed.dat", "\n5 5 0 0", "\n5 5 0"); },
     "fixed.dat:7: expected 4 numbers (id X Y Z), found 3"},
    {"wrong attribute count",
     [](auto d) { edit(d + "/alter.dat", "\n9 9 0 0 0 0 0", "\n9 9 0 0 0 0"); },
     "alter.dat:11: expected 7 numbers (id x y z vx vy vz), found 6"},
    {"duplicate id", [](auto d) { edit(d + "/fixed.dat", "\n6 6 0 0", "\n5 6 0 0"); },
     "fixed.dat:8: duplicate global ID 5"},
    {"nan coordinate", [](auto d) { edit(d + "/fixed.dat", "\n7 7 0 0", "\n7 nan 0 0"); },
     "fixed.dat:9: 'nan' is not a finite number (column 2)"},
    {"inf coordinate", [](auto d) { edit(d + "/alter.dat", "\n8 8 0 0", "\n8 8 -inf 0"); },
     "alter.dat:10: '-inf' is not a finite number (column 3)"},
    {"missing file", [](auto d) { edit(d + "/lattice.toml", "\"fixed.dat\"", "\"fixd.dat\""); },
     "lattice.toml:11: cannot read"},
    {"unknown model", [](auto d) { edit(d + "/lattice.toml", "\"spring\"", "\"sprung\""); },
     "lattice.toml:5: unknown model 'sprung' (did you mean 'spring'?)"},
    {"unknown parameter", [](auto d) { edit(d + "/lattice.toml", "dt = 0.05", "dT = 0.05"); },
     "lattice.toml:7: unknown parameter 'dT' for model 'spring' ([model]) (did you mean 'dt'?)"},
    {"parameter out of range", [](auto d) { edit(d + "/lattice.toml", "dt = 0.05", "dt = -0.05"); },
     "lattice.toml:7: parameter 'dt'"},
    {"parameter not a number",
     [](auto d) { edit(d + "/lattice.toml", "dt = 0.05", "dt = \"fast\""); },
     "lattice.toml:7: parameter 'dt' of model 'spring' ([model]): 'fast' is not a number"},
    {"cell size below horizon",
     [](auto d) { edit(d + "/lattice.toml", "min_cell_size = 1.5", "min_cell_size = 1.2"); },
     "lattice.toml:32: min_cell_size 1.2 is below the model's horizon 1.5"},
    {"not toml", [](auto d) { edit(d + "/lattice.toml", "dt = 0.05", "dt = 0.05 0.06"); },
     "lattice.toml:7: not valid TOML"},
    {"unknown table", [](auto d) { edit(d + "/lattice.toml", "[output]", "[outptu]"); },
     "lattice.toml:34: unknown parameter 'outptu' for the scenario (did you mean 'output'?)"},
    {"unknown output key",
     [](auto d) { edit(d + "/lattice.toml", "restart_every", "restart_evry"); },
     "lattice.toml:36: unknown parameter 'restart_evry' for [output] (did you mean "
     "'restart_every'?)"},
    {"unknown attribute", [](auto d) { edit(d + "/lattice.toml", "\"vx\"", "\"vq\""); },
     "lattice.toml:15: the model has no attribute 'vq'"},
    {"unknown history id", [](auto d) { edit(d + "/lattice.toml", "[0, 127]", "[0, 128]"); },
     "lattice.toml:39: history_ids: 128 is not a particle's ID"},
    {"missing steps", [](auto d) { edit(d + "/lattice.toml", "steps = 40", "stepz = 40"); },
     "lattice.toml: missing steps"},
    {"steps and hold_time",
     [](auto d) {
       edit(d + "/lattice.toml", "steps = 40\n", "steps = 40\n[loading]\nhold_time = 2\n");
     },
     "lattice.toml:2: give the run's length as steps = N or as [loading] hold_time, not both"},
};

}  // namespace

TEST(CliBadInput, ScenarioCasesNameFileAndLineAndWriteNothing) {
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string dir = freshDir("bad_input");
    const std::string sc = springCase(dir, 40);
    c.spoil(dir);
    const auto before = filesUnder(dir);
    const auto r = runPdq({"run", sc}, dir);
    EXPECT_EQ(r.code, 1) << r.all();
    EXPECT_THAT(r.err, HasSubstr(c.expected));
    EXPECT_THAT(r.err, HasSubstr("pdq: error: "));
    EXPECT_EQ(filesUnder(dir), before) << "files were written";
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
}

TEST(CliBadInput, ThesisFilesNameFileAndLine) {
  const std::string dir = freshDir("bad_input_dat");
  const std::string sc = springCase(dir, 40);
  ASSERT_EQ(runPdq({"prep", sc, "-o", "dat"}, dir).code, 0);
  const std::string input = readFile(dir + "/dat/pdQInput.dat");
  const std::string user = readFile(dir + "/dat/pdQUserInput.dat");
  struct DatCase {
    const char* name;
    std::function<void()> spoil;
    std::string expected;
  };
  // The line of pdQInput.dat that holds history_ids, and the line after the last.
  const auto idsAt = input.find("history_ids");
  ASSERT_NE(idsAt, std::string::npos) << input;
  const std::string idsLine =
      std::to_string(std::count(input.begin(), input.begin() + idsAt, '\n') + 1);
  const std::string endLine = std::to_string(std::count(input.begin(), input.end(), '\n') + 1);
  auto appendLine = [&](const std::string& l) {
    writeFile(dir + "/dat/pdQInput.dat", readFile(dir + "/dat/pdQInput.dat") + l + "\n");
  };
  auto ids = [&](const std::string& v) {
    return DatCase{"history_ids",
                   [&, v] { edit(dir + "/dat/pdQInput.dat", "history_ids 0", "history_ids " + v); },
                   "pdQInput.dat:" + idsLine + ": history_ids: " + v + " is not a particle's ID"};
  };
  std::vector<DatCase> datCases = {
      {"unknown parameter", [&] { edit(dir + "/dat/pdQUserInput.dat", "dt ", "dT "); },
       "pdQUserInput.dat:3: unknown parameter 'dT'"},
      {"unknown model", [&] { edit(dir + "/dat/pdQUserInput.dat", "spring", "sprin"); },
       "pdQUserInput.dat:1: unknown model 'sprin' (did you mean 'spring'?)"},
      {"malformed number", [&] { edit(dir + "/dat/pdQInput.dat", "0 0 0", "0 x 0"); },
       "pdQInput.dat:1: 'x' is not a number"},
      {"cell size below horizon", [&] { edit(dir + "/dat/pdQInput.dat", "1.5 ", "1.25 "); },
       "pdQInput.dat:2: the minimum cell size 1.25 is below the model's horizon 1.5"},
      {"missing file", [&] { fs::remove(dir + "/dat/ParticleAlterAttrs.dat"); },
       "ParticleAlterAttrs.dat: cannot open the file"},
  };
  for (const char* d : {"4", "7", "-1"})
    datCases.push_back({"dimension", [&, d] { appendLine(std::string("dimension ") + d); },
                        "pdQInput.dat:" + endLine +
                            ": dimension must be 1, 2 or 3 (or 0: from "
                            "the particles), not " +
                            d});
  for (const char* v : {"99999", "-3", "1e+30", "1800.5"}) datCases.push_back(ids(v));
  for (const auto& c : datCases) {
    SCOPED_TRACE(c.name);
    writeFile(dir + "/dat/pdQInput.dat", input);
    writeFile(dir + "/dat/pdQUserInput.dat", user);
    if (!fs::exists(dir + "/dat/ParticleAlterAttrs.dat")) {
      ASSERT_EQ(runPdq({"prep", sc, "-o", "dat"}, dir).code, 0);
    }
    c.spoil();
    const auto r = runPdq({"run", "dat", "--out", "out"}, dir);
    EXPECT_EQ(r.code, 1) << r.all();
    EXPECT_THAT(r.err, HasSubstr(c.expected));
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
}

TEST(CliBadInput, MissingScenarioAndPlugin) {
  const std::string dir = freshDir("bad_input_missing");
  auto r = runPdq({"run", "nowhere.toml"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("nowhere.toml: cannot read the scenario"));
  writeFile(dir + "/not_a_library.so", "text");
  r = runPdq({"list", "--plugin", "not_a_library.so"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("not_a_library.so: cannot load plugin"));
  EXPECT_TRUE(filesUnder(dir) == std::vector<std::string>{"not_a_library.so"});
}

// The quasi-static solver's keys: each bad value names its file and line.
TEST(CliBadInput, SolverKeysNameFileAndLine) {
  const std::string scenario = R"([model]
name = "mplm2d"
[particles]
generator = "mplm_plate"
width = 0.1
height = 0.12
[solver]
kind = "quasi_static"
tolerance = 1e-6
max_iterations = 100000
load_steps = 2
[output]
dir = "out"
)";
  struct SolverCase {
    const char* name;
    std::string from, to, expected;
    bool writesNothing = true;
  };
  const std::vector<SolverCase> solverCases = {
      {"zero tolerance", "tolerance = 1e-6", "tolerance = 0",
       "qs.toml:9: tolerance must be positive"},
      {"negative tolerance", "tolerance = 1e-6", "tolerance = -1e-6",
       "qs.toml:9: tolerance must be positive"},
      {"unknown kind", "\"quasi_static\"", "\"quasistatic\"", "qs.toml:8: "},
      {"no load steps", "load_steps = 2", "load_steps = 0",
       "qs.toml:11: load_steps must be at least 1"},
      {"steps with the quasi-static solver", "[model]", "steps = 10\n[model]",
       "qs.toml:1: the quasi-static solver's run is its [solver] load_steps"},
      {"quasi-static keys with the dynamic solver", "\"quasi_static\"", "\"dynamic\"",
       "qs.toml:9: tolerance is a quasi-static solver parameter"},
      {"too few iterations", "max_iterations = 100000", "max_iterations = 3",
       "qs.toml:10: load step 1 (load factor 0.000488281) did not converge in 3 iterations", false},
      {"displacement control on no particle", "load_steps = 2",
       "load_steps = 2\n[solver.control]\naxis = \"y\"\ndisplacement = -1e-4\nx = [5, 6]",
       "qs.toml:13: [solver.control] selects no particle"},
      {"displacement control without its displacement", "load_steps = 2",
       "load_steps = 2\n[solver.control]\naxis = \"y\"\nx = [0, 0.01]",
       "qs.toml:13: the displacement control needs both axis"},
      {"negative max_broken", "load_steps = 2", "load_steps = 2\nmax_broken = -1",
       "qs.toml:12: max_broken must be >= 0"},
      {"negative peak_tolerance", "load_steps = 2", "load_steps = 2\npeak_tolerance = -0.02",
       "qs.toml:12: peak_tolerance must be >= 0"},
      {"unknown fictitious masses", "load_steps = 2", "load_steps = 2\nmasses = \"heavy\"",
       "qs.toml:12: "},
  };
  for (const auto& c : solverCases) {
    SCOPED_TRACE(c.name);
    const std::string dir = freshDir("bad_input_solver");
    std::string text = scenario;
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, c.from.size(), c.to);
    writeFile(dir + "/qs.toml", text);
    const auto r = runPdq({"run", "qs.toml"}, dir);
    EXPECT_EQ(r.code, 1) << r.all();
    EXPECT_THAT(r.err, HasSubstr(c.expected));
    if (c.name == std::string("unknown kind")) {
      EXPECT_THAT(r.err, HasSubstr("quasi_static"));
    }
    if (c.writesNothing) {
      EXPECT_FALSE(fs::exists(dir + "/out"));
    }
  }
}

// Sizes checked before allocation, typos, generators' limits and pictures' keys: each
// message names the file and line of the true cause.
// PMB on a square lattice (δ = 3.1 spacings), ten particles pushed.
const std::string pmbSquare = R"(steps = 10
[model]
name = "pmb"
E = 1e9
horizon = 3.1
density = 1000
dt = 1e-6
[particles]
generator = "square"
nx = 20
ny = 10
[[particles.set]]
attribute = "vx"
value = 1
x = [0, 0]
)";

TEST(CliBadInput, SizesTyposAndGeneratorsNameTheTrueCause) {
  const std::string& pmb = pmbSquare;
  const std::string plate = R"(steps = 10
[model]
name = "mplm2d"
[particles]
generator = "mplm_plate"
width = 0.1
height = 0.12
)";
  const std::string beam = R"(steps = 10
[model]
name = "mplm2d"
[particles]
generator = "mplm_beam"
span = 1.0
)";
  struct SizeCase {
    const char* name;
    std::string scenario, from, to, expected, memory = "";
  };
  const std::vector<SizeCase> sizeCases = {
      {"a missing key's typo", pmb, "horizon", "horizn",
       "pb.toml:5: unknown parameter 'horizn' for model 'pmb' ([model]) (did you mean "
       "'horizon'? it is missing)"},
      {"no suggestion of another parameter", pmb, "E = 1e9", "E = 1e9\nnu = 0.25",
       "pb.toml:5: unknown parameter 'nu' for model 'pmb' ([model])\n"},
      {"duplicated set header", pmb, "[[particles.set]]", "[[particles.set]]\n[[particles.set]]",
       "pb.toml:12: this [[particles.set]] entry is empty (is its header written twice?)"},
      {"10^10 particles", pmb, "nx = 20", "nx = 1e9",
       "pb.toml:9: generator 'square': the lattice would make about 1e+10 particles"},
      {"beyond an axis's count", pmb, "nx = 20", "nx = 1e10",
       "pb.toml:10: nx = 10000000000 exceeds the largest count along an axis, 2147483647"},
      {"more than the memory given", pmb, "nx = 20\nny = 10", "nx = 1000\nny = 1000",
       "this machine has 1 MB available", "1M"},
      {"a 1e9 m beam", beam, "span = 1.0", "span = 1e9", "pb.toml:5: generator 'mplm_beam': "},
      {"a plate of no height", plate, "height = 0.12", "height = 0.0",
       "pb.toml:7: height = 0 m is less than the lattice's stride"},
  };
  for (const auto& c : sizeCases) {
    SCOPED_TRACE(c.name);
    const std::string dir = freshDir("bad_input_sizes");
    writeFile(dir + "/pb.toml", c.scenario);
    edit(dir + "/pb.toml", c.from, c.to);
    if (!c.memory.empty()) setenv("PDQ_MEMORY_LIMIT", c.memory.c_str(), 1);
    const auto started = std::chrono::steady_clock::now();
    const auto r = runPdq({"run", "pb.toml"}, dir);
    unsetenv("PDQ_MEMORY_LIMIT");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
              10);
    EXPECT_EQ(r.code, 1) << r.all();
    EXPECT_THAT(r.err + "\n", HasSubstr(c.expected));
    EXPECT_THAT(r.err, Not(HasSubstr("did you mean 'E'")));
  }
  // The square lattice gives PMB's particles their volume, and pdq info counts what each
  // [[particles.set]] selects.
  const std::string dir = freshDir("bad_input_sizes_ok");
  writeFile(dir + "/pb.toml", pmb);
  const auto info = runPdq({"info", "pb.toml"}, dir);
  EXPECT_EQ(info.code, 0) << info.all();
  EXPECT_THAT(info.out, HasSubstr("particles.set pb.toml:12: vx on 10 particles"));
}

// PDQ_SIMD, which caps the peridynamic kernels' vector width, refuses a width it does not
// know, as bad input, and the run writes nothing.
TEST(CliBadInput, UnknownSimdWidth) {
  const std::string dir = freshDir("bad_input_simd");
  writeFile(dir + "/pb.toml", pmbSquare);
  setenv("PDQ_SIMD", "avx1024", 1);
  const auto r = runPdq({"run", "pb.toml"}, dir);
  unsetenv("PDQ_SIMD");
  EXPECT_EQ(r.code, 1) << r.all();
  EXPECT_THAT(r.err, HasSubstr("PDQ_SIMD=avx1024: expected portable, avx2 or avx512"));
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename(), "pb.toml") << "nothing written";
}

// pdq info estimates the sizes from the scenario before anything is made: a problem far
// too large for the memory given is answered with the estimate, not made; on small ones
// the estimate agrees with the counts of the problem made (particles within 2 %, bonds
// within 10 %: the lattices' faces and an MPLM member's steel links are estimated).
TEST(CliBadInput, InfoEstimatesSizesBeforeMakingTheProblem) {
  std::string pmb = pmbSquare;
  const std::string square = "generator = \"square\"\nnx = 20\nny = 10";
  pmb.replace(pmb.find(square), square.size(), "generator = \"cubic\"\nnx = 10\nny = 9\nnz = 8");
  const std::string dir = freshDir("info_estimate");
  writeFile(dir + "/big.toml", pmb);
  edit(dir + "/big.toml", "nx = 10\nny = 9\nnz = 8", "nx = 500\nny = 500\nnz = 400");
  setenv("PDQ_MEMORY_LIMIT", "1G", 1);
  const auto big = runPdq({"info", "big.toml"}, dir);
  unsetenv("PDQ_MEMORY_LIMIT");
  EXPECT_EQ(big.code, 0) << big.all();
  EXPECT_THAT(big.out, HasSubstr("  particles   100000000\n"));
  EXPECT_THAT(big.out, HasSubstr("1 GB available: it does not fit"));
  EXPECT_THAT(big.out, HasSubstr("not made      it would not fit in the memory available"));
  EXPECT_THAT(big.out, Not(HasSubstr("time step")));  // nothing was set up

  // The estimate ("  particles   N") against the problem made ("particles     N").
  auto number = [](const std::string& out, const std::string& label) {
    const auto at = out.find(label);
    return at == std::string::npos ? -1.0 : std::stod(out.substr(at + label.size()));
  };
  const std::string mplm2d = "steps = 5\n[model]\nname = \"mplm2d\"\n[particles]\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"pmb cubic", pmb},
      {"pmb square",
       "steps = 5\n[model]\nname = \"pmb\"\nE = 1e9\nhorizon = 3.1\n"
       "density = 1000\ndt = 1e-6\n[particles]\ngenerator = \"square\"\n"
       "nx = 30\nny = 20\n"},
      {"spring square",
       "steps = 5\n[model]\nname = \"spring\"\nhorizon = 1.5\n"
       "[particles]\ngenerator = \"square\"\nnx = 16\nny = 8\n"},
      {"lj fcc",
       "steps = 5\n[model]\nname = \"lj\"\n[particles]\ngenerator = \"fcc\"\n"
       "cells = [4, 4, 4]\ndensity = 0.8442\n"},
      {"mplm plate", mplm2d + "generator = \"mplm_plate\"\nwidth = 0.1\nheight = 0.12\n"},
      {"mplm plate along y", mplm2d + "generator = \"mplm_plate\"\norientation = \"y\"\n"},
      {"mplm beam", mplm2d + "generator = \"mplm_beam\"\nspan = 0.6\ndepth = 0.2\n"
                             "bar_diameter = 0.012\nstirrup_diameter = 0.008\n"},
      {"mplm3d beam",
       "steps = 5\n[model]\nname = \"mplm3d\"\n[particles]\n"
       "generator = \"mplm3d_beam\"\nlength = 0.3\ndepth = 0.2\nwidth = 0.12\n"
       "bar_size = \"#13\"\nbar_cover = 0.03\nstirrup_size = \"#10\"\n"
       "stirrup_spacing = 0.1\n"},
  };
  for (const auto& [name, scenario] : cases) {
    SCOPED_TRACE(name);
    writeFile(dir + "/small.toml", scenario);
    const auto r = runPdq({"info", "small.toml"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
    const double particles = number(r.out, "\nparticles     ");
    EXPECT_GT(particles, 0) << r.out;
    EXPECT_NEAR(number(r.out, "  particles   "), particles, 0.02 * particles) << r.out;
    const double bonds = number(r.out, "\nbonds         ");
    if (name == "lj fcc") {
      EXPECT_THAT(r.out, HasSubstr("  bonds       none"));
    } else {
      EXPECT_GT(bonds, 0) << r.out;
      EXPECT_NEAR(number(r.out, "  bonds       "), bonds, 0.1 * bonds) << r.out;
    }
    EXPECT_THAT(r.out, HasSubstr("  cells       "));
  }
}

TEST(CliBadInput, PicturesNameTheirFileLineAndTrueCause) {
  const std::string dir = freshDir("bad_input_picture");
  const std::string sc = springCase(dir, 40);
  // A restart file whose step no long holds is not pdq's: it is passed over.
  writeFile(dir + "/out/ParticleAlterAttrs.99999999999999999999.rst", "");
  auto r = runPdq({"post", "picture", sc}, dir);
  EXPECT_EQ(r.code, 1) << r.all();
  EXPECT_THAT(r.err, HasSubstr("no restart file (ParticleAlterAttrs.<step>.rst) in out"));
  // bond_damage's line with the scenario's name, not the table's.
  const std::string text = readFile(sc) + "[output.picture]\nbond_damage = \"nothing\"\n";
  writeFile(sc, text);
  const std::string line = std::to_string(std::count(text.begin(), text.end(), '\n'));
  r = runPdq({"run", sc}, dir);
  EXPECT_EQ(r.code, 1) << r.all();
  EXPECT_THAT(r.err, HasSubstr("lattice.toml:" + line + ": no bond attribute 'nothing'"));
}

// 3D members (mplm3d, the mplm3d_beam generator): each bad value stops with the file, the
// line and the reason, exit 1, and nothing written.
TEST(CliBadInput, Member3dNamesFileAndLineAndWritesNothing) {
  const std::string particles = R"(generator = "mplm3d_beam"
length = 0.3
depth = 0.2
width = 0.12
bar_size = "#13"
bar_cover = 0.03
stirrup_size = "#10"
stirrup_spacing = 0.1
stirrup_cover = 0.02
)";
  const std::string head = "steps = 5\n[model]\nname = \"mplm3d\"\n[particles]\n";
  const std::string scenario = head + particles + "[output]\ndir = \"out\"\n";
  struct MemberCase {
    const char* name;
    std::string from, to, expected;
  };
  const std::vector<MemberCase> memberCases = {
      {"lattice that does not fit the box", "width = 0.12", "width = 0.01",
       "m3.toml:8: the lattice does not fit the box"},
      {"bar outside the section", "bar_cover = 0.03", "bar_y = [0.3]\nbar_z = [0.06]",
       "m3.toml:10: bar 1 (centroid y = 0.3 m, z = 0.06 m, diameter 0.0127 m) lies outside"},
      {"stirrup spacing below s", "stirrup_spacing = 0.1", "stirrup_spacing = 0.015",
       "m3.toml:12: stirrup_spacing 0.015 m is below the lattice spacing"},
      {"bar cover over half the section", "bar_cover = 0.03", "bar_cover = 0.07",
       "m3.toml:10: bar_cover 0.07 m is larger than half the section"},
      {"stirrup cover over half the section", "stirrup_cover = 0.02", "stirrup_cover = 0.06",
       "m3.toml:13: stirrup_cover 0.06 m is larger than half the section"},
      {"2D particle set for the 3D model", particles,
       "generator = \"square\"\nnx = 5\nny = 5\nspacing = 0.02\n",
       "m3.toml:5: mplm3d needs a 3D problem"},
      {"2D generator for the 3D model", particles, "generator = \"mplm_beam\"\n",
       "m3.toml:5: this generator makes MPLM particles; use it with model mplm2d"},
      {"3D generator for the 2D model", "\"mplm3d\"", "\"mplm2d\"",
       "m3.toml:5: mplm3d_beam makes 3D MPLM particles; use it with model mplm3d"},
      {"3D particle set for the 2D model", head + particles,
       "steps = 5\n[model]\nname = \"mplm2d\"\n[particles]\ngenerator = \"cubic\"\nnx = 3\n"
       "ny = 3\nnz = 3\nspacing = 0.02\n",
       "m3.toml:5: mplm2d needs a 2D problem"},
  };
  {
    // The member as written runs.
    const std::string dir = freshDir("bad_input_3d");
    writeFile(dir + "/m3.toml", scenario);
    const auto r = runPdq({"run", "m3.toml", "-q"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
  }
  for (const auto& c : memberCases) {
    SCOPED_TRACE(c.name);
    const std::string dir = freshDir("bad_input_3d");
    writeFile(dir + "/m3.toml", scenario);
    edit(dir + "/m3.toml", c.from, c.to);
    const auto before = filesUnder(dir);
    const auto r = runPdq({"run", "m3.toml"}, dir);
    EXPECT_EQ(r.code, 1) << r.all();
    EXPECT_THAT(r.err, HasSubstr(c.expected));
    EXPECT_EQ(filesUnder(dir), before) << "files were written";
  }
}
