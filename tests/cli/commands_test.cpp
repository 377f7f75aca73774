// Every pdq subcommand through the real executable: exit codes, messages, files written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "pdq_process.hpp"
#include "spring_case.hpp"

namespace fs = std::filesystem;
using pdq::test::filesUnder;
using pdq::test::freshDir;
using pdq::test::readFile;
using pdq::test::runPdq;
using pdq::test::springCase;
using pdq::test::writeFile;
using testing::HasSubstr;

TEST(Cli, HelpListsEverySubcommand) {
  const auto r = runPdq({"--help"});
  EXPECT_EQ(r.code, 0) << r.all();
  for (const char* cmd : {"run", "prep", "post", "strength", "info", "list"})
    EXPECT_THAT(r.out, HasSubstr(cmd));
  const auto run = runPdq({"run", "--help"});
  EXPECT_EQ(run.code, 0);
  for (const char* opt : {"--restart", "--plugin", "--steps", "--quiet", "--verbose", "--out"})
    EXPECT_THAT(run.out, HasSubstr(opt));
}

TEST(Cli, UnknownCommandsAndOptionsSuggestTheNearest) {
  auto r = runPdq({"rn", "x.toml"});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("unknown command 'rn'"));
  EXPECT_THAT(r.err, HasSubstr("did you mean 'run'"));
  const std::string dir = freshDir("unknown_option");
  const std::string sc = springCase(dir, 10);
  r = runPdq({"run", sc, "--stpes", "3"});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("unknown option '--stpes'"));
  EXPECT_THAT(r.err, HasSubstr("did you mean '--steps'"));
  r = runPdq({"post", "pictrue", sc});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("did you mean 'picture'"));
  r = runPdq({"run"});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("input"));
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(Cli, ListNamesModelsAndGenerators) {
  const auto r = runPdq({"list"});
  EXPECT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.out, HasSubstr("spring"));
  EXPECT_THAT(r.out, HasSubstr("generators"));
  // Each generator's page: its parameters with their defaults and the order of its IDs.
  for (const char* g : {"square", "cubic", "fcc", "mplm_plate", "mplm_beam", "mplm3d_beam"}) {
    SCOPED_TRACE(g);
    const auto page = runPdq({"list", "--generator", g});
    EXPECT_EQ(page.code, 0) << page.all();
    EXPECT_THAT(page.out, HasSubstr(std::string(g) + ": "));
    EXPECT_THAT(page.out, HasSubstr("default"));
    EXPECT_THAT(page.out, HasSubstr("  IDs "));
  }
  EXPECT_THAT(runPdq({"list", "--generator", "square"}).out,
              HasSubstr("IDs         from first_id, X fastest, then Y"));
  const auto wrong = runPdq({"list", "--generator", "squar"});
  EXPECT_EQ(wrong.code, 1);
  EXPECT_THAT(wrong.err, HasSubstr("unknown generator 'squar' (did you mean 'square'?)"));
}

TEST(Cli, InfoDescribesTheProblemAndWritesNothing) {
  const std::string dir = freshDir("info");
  const std::string sc = springCase(dir, 40);
  const auto before = filesUnder(dir);
  const auto r = runPdq({"info", sc, "--ranks", "4"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.out, HasSubstr("model         spring"));
  EXPECT_THAT(r.out, HasSubstr("particles     128"));
  // 16 x 8 lattice, horizon 1.5: 15*8 + 16*7 axial + 2*15*7 diagonal springs.
  EXPECT_THAT(r.out, HasSubstr("bonds         442 "));
  EXPECT_THAT(r.out, HasSubstr("time step     0.05"));
  EXPECT_THAT(r.out, HasSubstr("dimension     2D"));
  EXPECT_THAT(r.out, HasSubstr("on 4 ranks"));
  EXPECT_THAT(r.out, HasSubstr("memory"));
  EXPECT_EQ(filesUnder(dir), before);
}

TEST(Cli, RunWritesItsOutputsAndReportsProgress) {
  const std::string dir = freshDir("run");
  const std::string sc = springCase(dir, 40);
  const auto r = runPdq({"run", sc}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  // Not a terminal: plain log lines, the last one at the last step.
  EXPECT_THAT(r.out, HasSubstr("step 0/40"));
  EXPECT_THAT(r.out, HasSubstr("step 40/40 (100%)"));
  EXPECT_THAT(r.out, HasSubstr("particle-steps/s"));
  const auto files = filesUnder(dir + "/out");
  for (const char* f : {"ParticleAlterAttrs.10.rst", "ParticleAlterAttrs.40.rst", "timing.out",
                        "debug.txt", "timehist.dat", "history.csv"})
    EXPECT_NE(std::find(files.begin(), files.end(), f), files.end()) << f;
  // history.csv: globals at steps 0, 5, ..., 40 and a header.
  const std::string hist = readFile(dir + "/out/history.csv");
  EXPECT_THAT(hist, HasSubstr("broken_bonds"));
  // Springs of the upper half broke.
  EXPECT_EQ(std::count(hist.begin(), hist.end(), '\n'), 10) << hist;

  const auto quiet = runPdq({"run", sc, "-q", "--out", "quiet"}, dir);
  EXPECT_EQ(quiet.code, 0) << quiet.all();
  EXPECT_EQ(quiet.out, "");
  const auto verbose = runPdq({"run", sc, "--verbose", "--out", "verbose", "--steps", "5"}, dir);
  EXPECT_EQ(verbose.code, 0) << verbose.all();
  EXPECT_THAT(verbose.out, HasSubstr("particles     128"));
  EXPECT_THAT(verbose.out, HasSubstr("total"));  // the timing table
  EXPECT_TRUE(fs::exists(dir + "/verbose/ParticleAlterAttrs.5.rst"));
  const auto both = runPdq({"run", sc, "-q", "-v"}, dir);
  EXPECT_EQ(both.code, 2);
}

TEST(Cli, RestartContinuesBitwise) {
  const std::string dir = freshDir("restart");
  const std::string sc = springCase(dir, 30);
  ASSERT_EQ(runPdq({"run", sc, "-q"}, dir).code, 0);
  const std::string whole = readFile(dir + "/out/ParticleAlterAttrs.30.rst");
  const std::string wholeBonds = readFile(dir + "/out/Bonds.30.rst");
  ASSERT_FALSE(whole.empty());
  fs::copy(dir + "/out", dir + "/first");
  fs::remove_all(dir + "/out");
  const auto r = runPdq(
      {"run", sc, "-q", "--restart", "first/ParticleAlterAttrs.10.rst", "--out", "second"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/second/ParticleAlterAttrs.30.rst"), whole);
  EXPECT_EQ(readFile(dir + "/second/Bonds.30.rst"), wholeBonds);

  const auto past = runPdq({"run", sc, "--restart", "first/ParticleAlterAttrs.30.rst", "--steps",
                            "20", "--out", "third"},
                           dir);
  EXPECT_EQ(past.code, 1);
  EXPECT_THAT(past.err, HasSubstr("beyond the run's last step 20"));
  EXPECT_FALSE(fs::exists(dir + "/third"));
}

TEST(Cli, PrepWritesTheThesisFiles) {
  const std::string dir = freshDir("prep");
  const std::string sc = springCase(dir, 20);
  const auto r = runPdq({"prep", sc, "-o", "dat"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.out, HasSubstr("128 particles"));
  EXPECT_EQ(filesUnder(dir + "/dat"),
            (std::vector<std::string>{"ParticleAlterAttrs.dat", "ParticleFixedAttrs.dat",
                                      "pdQInput.dat", "pdQUserInput.dat"}));
  const std::string user = readFile(dir + "/dat/pdQUserInput.dat");
  EXPECT_THAT(user, HasSubstr("model spring"));
  EXPECT_THAT(user, HasSubstr("critical_stretch 0.02"));
  // The velocities set by [[particles.set]] are in the alterable file: particle 127 is
  // at X = 15 in the upper half, vx = 0.05 (15 - 7.5).
  const std::string alter = readFile(dir + "/dat/ParticleAlterAttrs.dat");
  EXPECT_THAT(alter, HasSubstr("\n127 15 7 0 0.375 "));
}

// A quasi-static run that cut back has more load steps than `load_steps`; pdq post
// picture draws any of them (here a run of 4 load steps drawn from a scenario that says 2).
TEST(Cli, PostDrawsAnyQuasiStaticLoadStep) {
  const std::string dir = freshDir("post_quasi_static");
  const auto scenario = [](int loadSteps) {
    return "[model]\nname = \"mplm2d\"\ndamage = false\n[particles]\n"
           "generator = \"mplm_plate\"\nwidth = 0.1\nheight = 0.12\n[solver]\n"
           "kind = \"quasi_static\"\ntolerance = 1e-4\nload_steps = " +
           std::to_string(loadSteps) + "\n[output]\nrestart_every = 1\n";
  };
  writeFile(dir + "/four.toml", scenario(4));
  ASSERT_EQ(runPdq({"run", "four.toml", "-q", "--out", "out"}, dir).code, 0);
  writeFile(dir + "/two.toml", scenario(2));
  const auto r = runPdq({"post", "picture", "two.toml", "--restart", "out/ParticleAlterAttrs.4.rst",
                         "-o", "four.png"},
                        dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.out, HasSubstr("step 4"));
  EXPECT_EQ(readFile(dir + "/four.png").substr(1, 3), "PNG");
}

TEST(Cli, PostDrawsPicturesAndPlots) {
  const std::string dir = freshDir("post");
  const std::string sc =
      springCase(dir, 20, "\n[output.picture]\ncolour_by = \"damage\"\nwidth = 800\n");
  ASSERT_EQ(runPdq({"run", sc, "-q"}, dir).code, 0);
  const std::string png = readFile(dir + "/out/damage_000020.png");
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  // From the last restart file, the picture the run drew, to the byte.
  auto r = runPdq({"post", "picture", sc, "-o", "again.png"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.out, HasSubstr("step 20"));
  EXPECT_TRUE(readFile(dir + "/again.png") == png);
  // Other options on the command line: a different picture, in the output folder.
  r = runPdq({"post", "picture", sc, "--set", "magnification=5", "--set", "name=big"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  const std::string big = readFile(dir + "/out/big_000020.png");
  EXPECT_EQ(big.substr(1, 3), "PNG");
  EXPECT_FALSE(big == png);
  r = runPdq(
      {"post", "picture", sc, "--restart", "out/ParticleAlterAttrs.10.rst", "-o", "early.svg"},
      dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(readFile(dir + "/early.svg"), HasSubstr("<svg"));
  r = runPdq({"post", "picture", sc, "--set", "colour_by=damag"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("did you mean 'damage'"));

  r = runPdq(
      {"post", "plot", "out/history.csv", "-x", "step", "-y", "broken_bonds", "-o", "broken.png"},
      dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/broken.png").substr(1, 3), "PNG");
  r = runPdq({"post", "plot", "out/history.csv", "-y", "broken_bond"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("did you mean 'broken_bonds'"));
  EXPECT_FALSE(fs::exists(dir + "/out/history.png"));
  // Labels: one per curve, or an error that counts them.
  r = runPdq({"post", "plot", "out/history.csv", "-x", "step", "-y", "broken_bonds", "--label",
              "broken springs", "--y-scale", "0.5", "-o", "labelled.png"},
             dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_FALSE(readFile(dir + "/labelled.png") == readFile(dir + "/broken.png"));
  r = runPdq({"post", "plot", "out/history.csv", "-x", "step", "-y", "broken_bonds", "--label", "a",
              "--label", "b", "-o", "two.png"},
             dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("--label given 2 time(s) for 1 curve(s)"));
  EXPECT_FALSE(fs::exists(dir + "/two.png"));
}

TEST(Cli, StrengthWithoutAStrengthSpecSaysSo) {
  const std::string dir = freshDir("strength");
  const std::string sc = springCase(dir, 20);
  const auto r = runPdq({"strength", sc}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("model spring declares no strength spec"));
  EXPECT_FALSE(fs::exists(dir + "/out"));
}
