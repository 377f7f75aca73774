// pdq strength through the executable on a thesis plate (examples/mplm/tension_x.toml):
// the report, the files it writes, a picture of a trial's damage by pdq post, the same
// trials on 1, 2 and 3 ranks (by the bisection and by the quasi-static method), and bad
// options refused with their name.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "pdq_process.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;
using ::testing::HasSubstr;

namespace {

std::string plate() { return sourceDir() + "/examples/mplm/tension_x.toml"; }

int lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(CliStrength, FindsTheTensionPlateStrengthAndWritesItsTrials) {
  const std::string dir = freshDir("strength_plate");
  auto r = runPdq({"strength", plate(), "--set", "max_trials=6"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.out, HasSubstr("failure mode: tension"));
  EXPECT_THAT(r.out, HasSubstr("classical: 2.757 MPa (tension)"));  // f_t = E ε_t
  EXPECT_THAT(r.out, HasSubstr("reference: 2.784 MPa"));
  const std::string out = dir + "/tension_x_out/strength";
  const std::string csv = readFile(out + "/trials.csv");
  EXPECT_EQ(lines(csv), 7);  // header + 6 trials
  // The bracket printed is a holding and a failing trial of the table, f_t within 5 %.
  const double ft = 24.86e9 * 1.109e-4 / 1e6;
  double lo = 0, hi = 0;
  ASSERT_EQ(std::sscanf(r.out.substr(r.out.find("\nstrength: ")).c_str(), "\nstrength: %lf to %lf",
                        &lo, &hi),
            2)
      << r.out;
  EXPECT_LT(lo, hi);
  EXPECT_NEAR(0.5 * (lo + hi), ft, 0.05 * ft + (hi - lo));
  EXPECT_THAT(readFile(out + "/strength.txt"), HasSubstr("failure mode: tension"));
  // Every trial's load-displacement history and final state; a failing one drawn by post.
  for (int k = 1; k <= 6; ++k) {
    const std::string t = out + "/trial_0" + std::to_string(k);
    EXPECT_TRUE(fs::exists(t + "/history.csv")) << t;
  }
  std::string restart;
  for (const auto& f : filesUnder(out + "/trial_02"))
    if (f.rfind("ParticleAlterAttrs.", 0) == 0) restart = out + "/trial_02/" + f;
  ASSERT_FALSE(restart.empty());
  r = runPdq({"post", "picture", plate(), "--restart", restart, "-o", "failed.png"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/failed.png").substr(1, 3), "PNG");
  r = runPdq({"post", "plot", out + "/trial_01/history.csv", "--x", "uy", "--y", "load_factor",
              "--x-scale", "1000", "-o", "curve.png"},
             dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/curve.png").substr(1, 3), "PNG");
}

TEST(CliStrength, SameTrialsOnAnyNumberOfRanks) {
  std::string first;
  for (int ranks : {1, 2, 3}) {
    SCOPED_TRACE(ranks);
    const std::string dir = freshDir("strength_ranks_" + std::to_string(ranks));
    const auto r = runPdq({"strength", plate(), "--set", "max_trials=4"}, dir, ranks);
    ASSERT_EQ(r.code, 0) << r.all();
    const std::string csv = readFile(dir + "/tension_x_out/strength/trials.csv");
    if (first.empty())
      first = csv;
    else
      EXPECT_EQ(csv, first);  // loads, displacements, broken counts: bit for bit
  }
}

// The quasi-static method on a small lattice runs on one rank while the others wait: every
// number of ranks reports the same strength, failure mode and trial, bit for bit.
TEST(CliStrength, QuasiStaticSameOnAnyNumberOfRanks) {
  std::string first, firstCsv;
  for (int ranks : {1, 2, 3}) {
    SCOPED_TRACE(ranks);
    const std::string dir = freshDir("strength_qs_ranks_" + std::to_string(ranks));
    const auto r = runPdq({"strength", plate(), "--set", "method=quasi_static"}, dir, ranks);
    ASSERT_EQ(r.code, 0) << r.all();
    const std::string out = dir + "/tension_x_out/strength";
    const std::string report = readFile(out + "/strength.txt");
    const auto at = report.find("strength: ");
    ASSERT_NE(at, std::string::npos) << report;
    const std::string line = report.substr(at, report.find('\n', at) - at);
    const std::string csv = readFile(out + "/trials.csv");
    EXPECT_TRUE(fs::exists(out + "/quasi_static/quasi_static.csv"));
    // Judged at the try beyond the peak, as the bisection judges its failing trial: the
    // brittle plate's last equilibrium has no interaction damaged past ω = ½ ("none").
    EXPECT_THAT(report, HasSubstr("failure mode: tension"));
    if (first.empty()) {
      first = line, firstCsv = csv;
    } else {
      EXPECT_EQ(line, first);
      EXPECT_EQ(csv, firstCsv);
    }
  }
}

// A quasi-static run that holds up to hi goes on towards twice hi, as the bisection widens
// its bracket: the plate (about 3 MPa) holds to hi = 1.6 MPa, then fails below 3.2.
TEST(CliStrength, QuasiStaticRaisesHiWhileTheMemberHolds) {
  const std::string dir = freshDir("strength_qs_raise");
  const auto r = runPdq(
      {"strength", plate(), "--set", "method=quasi_static", "--set", "lo=0.5", "--set", "hi=1.6"},
      dir);
  ASSERT_EQ(r.code, 0) << r.all();
  double lo = 0, hi = 0;
  const auto at = r.out.find("\nstrength: ");
  ASSERT_NE(at, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.substr(at).c_str(), "\nstrength: %lf to %lf", &lo, &hi), 2);
  EXPECT_GT(lo, 1.6);
  EXPECT_LT(lo, hi);
  EXPECT_LE(hi, 3.2);
  const std::string csv = readFile(dir + "/tension_x_out/strength/trials.csv");
  EXPECT_EQ(lines(csv), 3) << csv;  // header, the run that held to 1.6 MPa, the one that failed
  EXPECT_THAT(r.out, HasSubstr("1.6  holds"));
  // One run: one final state, the one the report names; the load path went on past 1.6 MPa
  // (its log says so) instead of starting again.
  const std::string qs = dir + "/tension_x_out/strength/quasi_static";
  std::string state;
  for (const auto& f : filesUnder(qs))
    if (f.rfind("ParticleAlterAttrs.", 0) == 0) {
      EXPECT_TRUE(state.empty()) << state << " and " << f;
      state = f;
    }
  EXPECT_THAT(r.out, HasSubstr("quasi_static/" + state + ")"));
  EXPECT_THAT(readFile(qs + "/debug.txt"),
              HasSubstr("load path raised after load step 10: towards 3.2"));
}

TEST(CliStrength, BadOptionsAreRefusedByName) {
  const std::string dir = freshDir("strength_bad");
  auto r = runPdq({"strength", plate(), "--set", "at_onse=2"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("did you mean 'at_once'"));
  r = runPdq({"strength", plate(), "--set", "lo=5", "--set", "hi=2"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("hi must exceed lo"));
  EXPECT_FALSE(fs::exists(dir + "/tension_x_out"));
  // A model parameter for the trials only, misspelt: named at its line before any trial.
  std::string text = readFile(plate());
  text += "\n[strength.model]\nsteel_rotary_inertia_scal = 10\n";
  writeFile(dir + "/typo.toml", text);
  const int line = lines(text);
  r = runPdq({"strength", "typo.toml"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("typo.toml:" + std::to_string(line)));
  EXPECT_THAT(r.err, HasSubstr("did you mean 'steel_rotary_inertia_scale'"));
  EXPECT_FALSE(fs::exists(dir + "/typo_out"));
}

}  // namespace
