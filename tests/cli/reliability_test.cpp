// Runs that are killed, stopped by a signal or restarted: what they leave behind and how
// they continue (docs/reliability.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <thread>

#include "pdq_process.hpp"
#include "spring_case.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;
using testing::HasSubstr;
using testing::Not;

namespace {

// The breaking spring lattice for `steps` steps, with rows every 50 steps and restart
// files every 500 (long enough a run to be killed in the middle).
std::string longCase(const std::string& dir, long steps) {
  const std::string sc = springCase(dir, steps);
  edit(sc, "restart_every = 10", "restart_every = 500");
  edit(sc, "globals_every = 5", "globals_every = 50");
  edit(sc, "history_every = 5", "history_every = 50");
  return sc;
}

// The newest step of ParticleAlterAttrs.<step>.rst in `dir`, -1 if none.
long newestRestart(const std::string& dir) {
  long newest = -1;
  const std::regex name(R"(ParticleAlterAttrs\.(\d+)\.rst)");
  std::error_code ec;  // the run renames files as we look
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    std::smatch m;
    if (std::regex_match(f, m, name)) newest = std::max(newest, std::stol(m[1]));
  }
  return newest;
}

// Kills a run (one rank killed with SIGKILL; under mpirun the job then ends) once it has
// written a restart file at step >= `after`, and checks that its histories hold every
// row up to that restart step, each a row of the uninterrupted run; then restarts it in
// the same folder and checks the histories equal the uninterrupted run's.
void killAndResume(int ranks, long kSteps) {
  const std::string dir = freshDir("kill_np" + std::to_string(ranks));
  const std::string sc = longCase(dir, kSteps);
  auto whole = runPdq({"run", sc, "-q", "--out", "whole"}, dir, ranks);
  ASSERT_EQ(whole.code, 0) << whole.all();
  const std::string wholeHist = readFile(dir + "/whole/history.csv");
  const std::string wholeTime = readFile(dir + "/whole/timehist.dat");
  ASSERT_EQ(rowSteps(wholeHist).size(), static_cast<std::size_t>(kSteps / 50 + 1));

  const Started run = startPdq({"run", sc, "-q"}, dir, ranks);
  const std::string out = dir + "/out";
  ASSERT_TRUE(waitFor([&] { return newestRestart(out) >= kSteps / 4; }, 120)) << "no restart";
  const int victim = ranks > 0 ? children(run.pid).back() : run.pid;
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const Run killed = waitPdq(run);
  EXPECT_NE(killed.code, 0) << killed.all();
  const long at = newestRestart(out);
  ASSERT_LT(at, kSteps) << "the run ended before it was killed";
  // Every row up to the newest restart file is there, whole and as in the full run.
  const std::string hist = readFile(out + "/history.csv");
  const std::string time = readFile(out + "/timehist.dat");
  EXPECT_GE(lastRowStep(out + "/history.csv"), at);
  EXPECT_GE(lastRowStep(out + "/timehist.dat"), at);
  EXPECT_EQ(wholeHist.substr(0, hist.size()), hist);
  EXPECT_EQ(wholeTime.substr(0, time.size()), time);
  // debug.txt and timing.out are as of a restart file (the kill may come between the
  // newest one and them).
  EXPECT_THAT(readFile(out + "/debug.txt"), HasSubstr("owned"));
  EXPECT_THAT(readFile(out + "/timing.out"), HasSubstr("(0 to "));

  const auto resumed = runPdq(
      {"run", sc, "-q", "--restart", "out/ParticleAlterAttrs." + std::to_string(at) + ".rst"}, dir,
      ranks);
  ASSERT_EQ(resumed.code, 0) << resumed.all();
  EXPECT_EQ(readFile(out + "/history.csv"), wholeHist);
  EXPECT_EQ(readFile(out + "/timehist.dat"), wholeTime);
  const std::string last = "/ParticleAlterAttrs." + std::to_string(kSteps) + ".rst";
  EXPECT_EQ(readFile(out + last), readFile(dir + "/whole" + last));
  // timing.out keeps the killed run's table and adds the restarted one's.
  const std::string timing = readFile(out + "/timing.out");
  EXPECT_THAT(timing, HasSubstr("(0 to "));
  EXPECT_THAT(timing, HasSubstr("(" + std::to_string(at) + " to " + std::to_string(kSteps) + ")"));
  EXPECT_THAT(readFile(out + "/debug.txt"), HasSubstr("restarted at step " + std::to_string(at)));
}

}  // namespace

TEST(Reliability, KilledRunKeepsItsHistoriesAndRestartContinuesThem) { killAndResume(0, 20000); }
TEST(Reliability, KilledRankOfTwoKeepsHistoriesAndRestartContinuesThem) { killAndResume(2, 4000); }

TEST(Reliability, RestartDropsRowsAfterItsStep) {
  // A finished run restarted from an earlier step rewrites the rows after it, once.
  const std::string dir = freshDir("rerun");
  const std::string sc = springCase(dir, 40);
  ASSERT_EQ(runPdq({"run", sc, "-q"}, dir).code, 0);
  const std::string hist = readFile(dir + "/out/history.csv");
  const std::string time = readFile(dir + "/out/timehist.dat");
  const auto r = runPdq({"run", sc, "-q", "--restart", "out/ParticleAlterAttrs.20.rst"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/out/history.csv"), hist);
  EXPECT_EQ(readFile(dir + "/out/timehist.dat"), time);
  // A history of other columns in the folder is not continued.
  writeFile(dir + "/out/history.csv", "step,time,something_else\n0,0,1\n");
  const auto other = runPdq({"run", sc, "-q", "--restart", "out/ParticleAlterAttrs.20.rst"}, dir);
  EXPECT_EQ(other.code, 1) << other.all();
  EXPECT_THAT(other.err, HasSubstr("history.csv:1: its columns are not this run's"));
}

namespace {

// The step in "stopped at step N by ..." of pdq's message, -1 if none.
long stoppedAt(const std::string& err) {
  std::smatch m;
  return std::regex_search(err, m, std::regex(R"(stopped at step (\d+) by)")) ? std::stol(m[1])
                                                                              : -1;
}

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Starts a long run, sends `sig` once it is stepping (to one rank under mpirun, or to
// mpirun itself), and checks that pdq stops within 5 s with exit code 4, a checkpoint at
// the step it names and its histories up to there. With `resume`, the run resumed from it
// ends with the bits (and histories) of an uninterrupted run.
void stopBySignal(int ranks, int sig, bool toOneRank, bool resume) {
  const std::string dir = freshDir("signal_np" + std::to_string(ranks) + "_" + std::to_string(sig));
  const std::string sc = longCase(dir, 100000000);
  const std::string out = dir + "/out";
  const Started run = startPdq({"run", sc, "-q"}, dir, ranks);
  ASSERT_TRUE(waitFor([&] { return newestRestart(out) >= 500; }, 120)) << "not stepping";
  const int target = ranks > 0 && toOneRank ? children(run.pid).back() : run.pid;
  const auto sent = std::chrono::steady_clock::now();
  ASSERT_EQ(kill(target, sig), 0);
  const Run r = waitPdq(run);
  EXPECT_LT(secondsSince(sent), 5.0);
  EXPECT_EQ(r.code, 4) << r.all();
  const long at = stoppedAt(r.err);
  ASSERT_GT(at, 0) << r.all();
  EXPECT_THAT(r.err, HasSubstr("; continue with: pdq run " + sc + " --resume out"));
  char name[40];
  std::snprintf(name, sizeof name, "/checkpoint.%012ld.ckpt", at);
  EXPECT_TRUE(fs::exists(out + name)) << name;
  EXPECT_EQ(lastRowStep(out + "/history.csv"), at / 50 * 50);
  if (!resume) return;
  const std::string end = std::to_string(at + 1000);
  const auto whole = runPdq({"run", sc, "-q", "--steps", end, "--out", "whole"}, dir, ranks);
  ASSERT_EQ(whole.code, 0) << whole.all();
  const auto resumed = runPdq({"run", sc, "-q", "--steps", end, "--resume", "out"}, dir, ranks);
  ASSERT_EQ(resumed.code, 0) << resumed.all();
  for (const std::string& f : {"/ParticleAlterAttrs." + end + ".rst", "/Bonds." + end + ".rst",
                               std::string("/history.csv"), std::string("/timehist.dat")})
    EXPECT_EQ(readFile(out + f), readFile(dir + "/whole" + f)) << f;
}

}  // namespace

TEST(Reliability, SigtermWritesACheckpointThatContinuesBitwise) {
  stopBySignal(0, SIGTERM, false, true);
}
TEST(Reliability, SigintSighupSigusr1StopAlike) {
  for (int sig : {SIGINT, SIGHUP, SIGUSR1}) {
    SCOPED_TRACE(sig);
    stopBySignal(0, sig, false, false);
  }
}
TEST(Reliability, SigtermToOneRankOfTwoStopsBothAtTheSameStep) {
  stopBySignal(2, SIGTERM, true, true);
}
TEST(Reliability, Sigusr1ToMpirunIsForwardedAndStopsTheJob) {
  stopBySignal(2, SIGUSR1, false, false);
}

// A realistically large run: a PMB block of 21,952 particles and 2.4 million bonds (some
// 100 MB as the rows of a bonds file). SIGTERM once it is
// stepping: it stops within 5 s with a checkpoint a resumed run reads without a warning.
TEST(Reliability, SigtermToALargeRunWritesItsCheckpointWithin5s) {
  const std::string dir = freshDir("signal_large");
  writeFile(dir + "/block.toml", R"(steps = 100000000
[model]
name = "pmb"
E = 1.0
density = 1.0
horizon = 3.0
dt = 0.2
critical_stretch = 0.005
lattice_spacing = 1.0
surface_correction = true

[particles]
generator = "cubic"
nx = 28
ny = 28
nz = 28

[[particles.set]]
attribute = "vx"
value = 0
gradient = [1e-4, 0, 0]

[output]
dir = "out"
globals_every = 5
final_restart = false
)");
  const std::string out = dir + "/out";
  const Started run = startPdq({"run", "block.toml", "-q"}, dir);
  ASSERT_TRUE(waitFor([&] { return lastRowStep(out + "/history.csv") >= 5; }, 300))
      << "not stepping";
  const auto sent = std::chrono::steady_clock::now();
  ASSERT_EQ(kill(run.pid, SIGTERM), 0);
  const auto r = waitPdq(run);
  EXPECT_LT(secondsSince(sent), 5.0);
  EXPECT_EQ(r.code, 4) << r.all();
  const long at = stoppedAt(r.err);
  ASSERT_GT(at, 0) << r.all();
  char name[40];
  std::snprintf(name, sizeof name, "/checkpoint.%012ld.ckpt", at);
  ASSERT_TRUE(fs::exists(out + name)) << name;
  const auto resumed = runPdq(
      {"run", "block.toml", "-q", "--resume", "out", "--steps", std::to_string(at + 1)}, dir);
  EXPECT_EQ(resumed.code, 0) << resumed.all();
  EXPECT_THAT(resumed.err, Not(HasSubstr("warning"))) << resumed.all();
}

TEST(Reliability, MaxWallTimeStopsBeforeTheLimitWithACheckpoint) {
  const std::string dir = freshDir("wall_time");
  const std::string sc = longCase(dir, 100000000);
  const auto started = std::chrono::steady_clock::now();
  const auto r = runPdq({"run", sc, "-q", "--max-wall-time", "4s"}, dir);
  const double took = secondsSince(started);
  EXPECT_EQ(r.code, 4) << r.all();
  EXPECT_THAT(r.err, HasSubstr("by the wall-time limit (--max-wall-time)"));
  EXPECT_LT(took, 4.0 + 1.0);  // the process itself stopped before 4 s; this adds its launch
  EXPECT_GT(took, 2.0);
  const long at = stoppedAt(r.err);
  char name[40];
  std::snprintf(name, sizeof name, "/out/checkpoint.%012ld.ckpt", at);
  EXPECT_TRUE(fs::exists(dir + name)) << name;
  const auto bad = runPdq({"run", sc, "--max-wall-time", "1h30"}, dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_THAT(bad.err, HasSubstr("--max-wall-time: '1h30' is not a duration"));
}

namespace {

// Runs an unstable variant of the spring lattice, with a restart file and a checkpoint
// every step, on `ranks`; expects it to end with exit code 3 and one message matching
// `pattern` (its first group the step), no restart file or checkpoint of that step and
// the previous step's as the newest, and no output holding a non-finite number. Returns
// the standard error.
std::string expectUnstable(const std::string& name, int ranks,
                           const std::vector<std::pair<std::string, std::string>>& edits,
                           const std::string& pattern, const std::string& extra = "",
                           std::string* folder = nullptr) {
  const std::string dir = freshDir(name + "_np" + std::to_string(ranks));
  if (folder) *folder = dir;
  const std::string sc = springCase(dir, 3000, extra);
  edit(sc, "restart_every = 10", "restart_every = 1\ncheckpoint_every = 1\ncheckpoints_kept = 3");
  for (const auto& [from, to] : edits) edit(sc, from, to);
  const auto r = runPdq({"run", sc, "-q"}, dir, ranks);
  EXPECT_EQ(r.code, 3) << r.all();
  EXPECT_EQ(occurrences(r.err, "pdq: error"), 1) << r.err;
  std::smatch m;
  if (!std::regex_search(r.err, m, std::regex("error: step (\\d+): " + pattern))) {
    ADD_FAILURE() << r.err;
    return r.err;
  }
  const long at = std::stol(m[1]);
  EXPECT_THAT(r.err, HasSubstr("the run is unstable: lower the time step (dt = "));
  const std::string out = dir + "/out/";
  if (at > 1) {
    EXPECT_TRUE(fs::exists(out + "ParticleAlterAttrs." + std::to_string(at - 1) + ".rst"));
    char ckpt[64];
    std::snprintf(ckpt, sizeof ckpt, "checkpoint.%012ld.ckpt", at - 1);
    EXPECT_TRUE(fs::exists(out + ckpt)) << ckpt;
  }
  for (const auto& f : filesUnder(out)) {
    std::smatch s;
    const std::regex stepOf(
        R"((?:ParticleAlterAttrs|Bonds|State)\.(\d+)\.rst|checkpoint\.(\d+)\.ckpt)");
    if (std::regex_match(f, s, stepOf)) {
      EXPECT_LT(std::stol(s[1].matched ? s[1].str() : s[2].str()), at) << f << " written";
    }
    const std::string text = readFile(out + f);
    EXPECT_EQ(text.find("nan"), std::string::npos) << f;
    EXPECT_EQ(text.find("inf"), std::string::npos) << f;
  }
  return r.err;
}

}  // namespace

TEST(Reliability, NonFiniteValuesStopTheRunInTheirStep) {
  // Unbreakable springs so stiff, and masses so light, that the first stretch gives an
  // infinite acceleration.
  for (int ranks : {0, 2}) {
    SCOPED_TRACE(ranks);
    const std::string err = expectUnstable(
        "nonfinite", ranks,
        {{"critical_stretch = 0.02", "critical_stretch = 0\nstiffness = 1e300\nmass = 1e-300"}},
        R"(particle \d+ at \(inf, inf, 0\) has non-finite x y vx vy)");
    EXPECT_THAT(err, HasSubstr("lower the time step (dt = 0.05)"));
  }
}

namespace {

// Unbreakable springs stepped a little above their stable step (about 0.75), started a
// thousand times slower than the breaking lattice, so that the motion, growing step by
// step, is caught while it is still small: before two bonded particles move apart by the
// horizon in a step.
std::vector<std::pair<std::string, std::string>> growingSprings() {
  return {{"dt = 0.05", "dt = 0.8"},
          {"critical_stretch = 0.02", "critical_stretch = 0"},
          {"value = -0.375", "value = -0.000375"},
          {"gradient = [0.05, 0, 0]", "gradient = [0.00005, 0, 0]"},
          {"value = -0.0375", "value = -0.0000375"},
          {"gradient = [0.005, 0, 0]", "gradient = [0.000005, 0, 0]"},
          {"value = -0.0175", "value = -0.0000175"},
          {"gradient = [0, 0.005, 0]", "gradient = [0, 0.000005, 0]"}};
}

}  // namespace

TEST(Reliability, MotionGrowingStepByStepStopsTheRun) {
  // Unbreakable springs stepped a little above their stable step (about 0.75): the fastest
  // particle goes back and forth, further each step, and is stopped before any value is
  // non-finite.
  for (int ranks : {0, 2}) {
    SCOPED_TRACE(ranks);
    const std::string err = expectUnstable(
        "growing", ranks, growingSprings(),
        R"(particle \d+ at \([-0-9.e]+, [-0-9.e]+, 0\) moved [0-9.e+-]+ in the last step: the fastest particle has gone back and forth at every step since step \d+)");
    EXPECT_THAT(err, HasSubstr("so the motion grows without bound"));
    EXPECT_THAT(err, Not(HasSubstr("non-finite")));
  }
}

TEST(Reliability, BondedParticleJumpingFurtherThanTheHorizonStopsTheRun) {
  // One particle of the spring lattice (horizon 1.5) started at vx = 100: at dt = 0.05 it
  // moves 5 in the first step, away from partners it is still bonded to; stopped in that
  // step, on one rank and on two (its partners ghosts there, some of them).
  for (int ranks : {0, 2}) {
    SCOPED_TRACE(ranks);
    const std::string err = expectUnstable(
        "jump", ranks, {},
        R"(particle 53 at \(10, 2.99[0-9]*, 0\) moved 5 in the last step, [0-9.]+ relative to particle \d+, to which it is still bonded: more than the horizon 1.5)",
        "\n[[particles.set]]\nattribute = \"vx\"\nvalue = 100\nx = [5, 5]\ny = [3, 3]\n");
    EXPECT_THAT(err, HasSubstr("error: step 1: "));
  }
}

TEST(Reliability, GrowthCountIsCheckpointedAndResumedAlike) {
  // The growing springs stop once the fastest particle has bounced, further each time, at
  // three steps in a row: the checkpoint of the step before holds a count of two. Resumed
  // from it (on 1 and 2 ranks) the run stops at the same step with the same words, as a
  // run that lost the count would not.
  std::string dir;
  const std::string err =
      expectUnstable("growth_resumed", 0, growingSprings(),
                     R"(particle \d+ at .* so the motion grows without bound)", "", &dir);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(err, m, std::regex(R"(pdq: error: step (\d+): [^\n]*)"))) << err;
  const std::string stop = m[0];
  const long at = std::stol(m[1]);
  char ckpt[64];
  std::snprintf(ckpt, sizeof ckpt, "/out/checkpoint.%012ld.ckpt", at - 1);
  EXPECT_THAT(readFile(dir + ckpt), HasSubstr("\nchecks 2 "));
  for (int ranks : {0, 2}) {
    SCOPED_TRACE(ranks);
    const std::string copy = "resumed_np" + std::to_string(ranks);
    fs::remove_all(dir + "/" + copy);
    fs::copy(dir + "/out", dir + "/" + copy);
    const auto r = runPdq({"run", "lattice.toml", "-q", "--resume", copy}, dir, ranks);
    EXPECT_EQ(r.code, 3) << r.all();
    EXPECT_THAT(r.err, HasSubstr(stop));
  }
}

TEST(Reliability, GrowthVerdictOfAShufflingModelDoesNotDependOnItsRestartFiles) {
  // An LJ crystal stepped far above its stable step: the growth check stops it at the
  // same step with the same words whether restart files (each forcing a shuffle, which
  // reorders the particles and may move them to another rank) are written every step or
  // never, on 1 and 2 ranks. A check that lost the particle it follows at each shuffle
  // never saw it bounce with restart files every step.
  const std::string dir = freshDir("growth_shuffled");
  writeFile(dir + "/lj.toml", R"(steps = 100
[model]
name = "lj"
epsilon = 1.0
sigma = 1.0
mass = 1.0
cutoff = 2.5
skin = 0.3
dt = 0.2
[particles]
generator = "fcc"
cells = [6, 6, 6]
density = 0.8442
temperature = 1e-8
seed = 87287
[decomposition]
periodic = [true, true, true]
[output]
restart_every = EVERY
)");
  std::string first;
  for (int ranks : {0, 2})
    for (const char* every : {"1000", "1"}) {
      SCOPED_TRACE(std::to_string(ranks) + " ranks, restart files every " + every);
      const std::string name = "lj_np" + std::to_string(ranks) + "_" + every + ".toml";
      fs::copy_file(dir + "/lj.toml", dir + "/" + name, fs::copy_options::overwrite_existing);
      edit(dir + "/" + name, "EVERY", every);
      const auto r = runPdq({"run", name, "-q", "-o", "out_" + name}, dir, ranks);
      EXPECT_EQ(r.code, 3) << r.all();
      std::smatch m;
      ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(pdq: error: step \d+: [^\n]*)")))
          << r.err;
      EXPECT_THAT(m.str(), HasSubstr("so the motion grows without bound"));
      if (first.empty()) first = m.str();
      EXPECT_EQ(m.str(), first);
    }
}

TEST(Reliability, MplmUnstableStepIsStoppedNamingItsStableStep) {
  // The plate at 1.6 times its stable step: stopped within a few steps of the start, with
  // the stable step in the hint.
  const std::string dir = freshDir("mplm_unstable");
  const std::string sc = dir + "/tension.toml";
  writeFile(sc, readFile(sourceDir() + "/examples/mplm/tension_x.toml"));
  edit(sc, "dt = 1.808e-7", "dt = 6e-6");
  const auto r = runPdq({"run", sc, "-q", "--steps", "200"}, dir, 2);
  EXPECT_EQ(r.code, 3) << r.all();
  EXPECT_THAT(r.err, HasSubstr("so the motion grows without bound"));
  EXPECT_THAT(r.err,
              HasSubstr("lower the time step (dt = 6e-06; the model's stable step is 3.672"));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(error: step (\d+): particle)"))) << r.err;
  EXPECT_LT(std::stol(m[1]), 20);
}

namespace {

// Runs the scenario `sc` (in `dir`) two steps as it is, with no warning, then with the
// edit `dt` (a time step above the stable one), expecting `warning` on standard error.
void expectDtWarning(const std::string& dir, const std::string& sc,
                     const std::pair<std::string, std::string>& dt, const std::string& warning) {
  const auto fine = runPdq({"run", sc, "-q", "--steps", "2"}, dir);
  EXPECT_EQ(fine.code, 0) << fine.all();
  EXPECT_EQ(fine.err, "");
  edit(sc, dt.first, dt.second);
  const auto r = runPdq({"run", sc, "-q", "--steps", "2", "--out", "fast"}, dir);
  EXPECT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.err, HasSubstr(warning));
  // The limit is the stable step itself: 1.2 times it is warned of (a run seen to shatter
  // there), 0.9 times it is not.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(exceeds the stable time step (\S+) s)")))
      << r.err;
  const double stable = std::stod(m[1]);
  std::string now = dt.second.substr(dt.second.find("dt = "));
  for (const double f : {1.2, 0.9}) {
    SCOPED_TRACE(f);
    std::ostringstream next;
    next << std::setprecision(17) << "dt = " << f * stable;
    edit(sc, now, next.str());
    now = next.str();
    const auto run = runPdq({"run", sc, "-q", "--steps", "2", "--out", "near"}, dir);
    EXPECT_EQ(run.code, 0) << run.all();
    if (f > 1)
      EXPECT_THAT(run.err, HasSubstr("exceeds the stable time step"));
    else
      EXPECT_EQ(run.err, "");
  }
}

}  // namespace

TEST(Reliability, MplmWarnsOnStandardErrorWhenDtExceedsItsStableStep) {
  const std::string dir = freshDir("mplm_dt");
  const std::string sc = dir + "/tension.toml";
  writeFile(sc, readFile(sourceDir() + "/examples/mplm/tension_x.toml"));
  expectDtWarning(dir, sc, {"dt = 1.808e-7", "dt = 1e-5"},
                  "pdq: warning: mplm2d: dt = 1e-05 s exceeds the stable time step 3.672e-06 s");
}

TEST(Reliability, Mplm3dWarnsOnStandardErrorWhenDtExceedsItsStableStep) {
  const std::string dir = freshDir("mplm3d_dt");
  const std::string sc = dir + "/cantilever.toml";
  writeFile(sc, readFile(sourceDir() + "/examples/mplm/cantilever3d.toml"));
  edit(sc, "length = 2.0", "length = 0.4");  // a short member: a quick set-up
  edit(sc, "depth = 0.35", "depth = 0.15");
  expectDtWarning(dir, sc, {"name = \"mplm3d\"", "name = \"mplm3d\"\ndt = 1e-4"},
                  "pdq: warning: mplm3d: dt = 0.0001 s exceeds the stable time step ");
}

TEST(Reliability, RestartFilesAreReadStrictly) {
  const std::string dir = freshDir("strict_restart");
  const std::string sc = springCase(dir, 40);
  ASSERT_EQ(runPdq({"run", sc, "-q"}, dir).code, 0);
  const std::string bonds = readFile(dir + "/out/Bonds.20.rst");
  // The lines of Bonds.20.rst: two header lines, then "owner partner dead ...".
  std::vector<std::string> lines;
  {
    std::istringstream in(bonds);
    for (std::string l; std::getline(in, l);) lines.push_back(l + "\n");
  }
  ASSERT_GT(lines.size(), 10u);
  auto joined = [&](std::size_t from, std::size_t to) {
    std::string t;
    for (std::size_t k = from; k < to; ++k) t += lines[k];
    return t;
  };
  const std::string third = lines[2];  // the first bond, line 3
  const auto sp = third.find(' ');
  const auto sp2 = third.find(' ', sp + 1);
  const std::string owner = third.substr(0, sp), partner = third.substr(sp + 1, sp2 - sp - 1);
  struct Case {
    const char* name;
    std::string text;  // the new Bonds.20.rst; empty: none
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"missing", "", "Bonds.20.rst: missing: "},
      {"empty", joined(0, 2), "Bonds.20.rst: has 0 bonds but"},
      {"truncated at a line", joined(0, lines.size() / 2), "(cut short?)"},
      {"truncated in a line", joined(0, 5) + lines[5].substr(0, 4), "Bonds.20.rst:6: expected"},
      {"one-sided", joined(0, 2) + owner + " 127" + third.substr(sp2) + joined(3, lines.size()),
       "Bonds.20.rst:3: the bond " + owner + "-127 has no partner line 127 " + owner +
           " (one-sided)"},
      {"self bond",
       joined(0, 2) + owner + " " + owner + third.substr(sp2) + joined(3, lines.size()),
       "Bonds.20.rst:3: particle " + owner + " is bonded to itself"},
      {"unknown partner",
       joined(0, 2) + owner + " 999999" + third.substr(sp2) + joined(3, lines.size()),
       "Bonds.20.rst:3: partner 999999 is not a particle of the problem"},
      {"dead flag 2",
       joined(0, 2) + owner + " " + partner + " 2" + third.substr(sp2 + 2) +
           joined(3, lines.size()),
       "Bonds.20.rst:3: the dead flag is 2; it must be 0 or 1"},
      {"another step", "# pdq bonds: step 10\n" + joined(1, lines.size()),
       "Bonds.20.rst:1: not the bonds of step 20"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    if (c.text.empty())
      fs::remove(dir + "/out/Bonds.20.rst");
    else
      writeFile(dir + "/out/Bonds.20.rst", c.text);
    const auto r = runPdq(
        {"run", sc, "-q", "--restart", "out/ParticleAlterAttrs.20.rst", "--out", "again"}, dir);
    EXPECT_EQ(r.code, 1) << r.all();
    EXPECT_THAT(r.err, HasSubstr(c.expected));
    EXPECT_THAT(r.err, testing::Not(HasSubstr("minimum cell size")));
    EXPECT_FALSE(fs::exists(dir + "/again")) << "something was written";
  }
  writeFile(dir + "/out/Bonds.20.rst", bonds);
  const auto good = runPdq(
      {"run", sc, "-q", "--restart", "out/ParticleAlterAttrs.20.rst", "--out", "again"}, dir);
  EXPECT_EQ(good.code, 0) << good.all();
  EXPECT_EQ(readFile(dir + "/again/ParticleAlterAttrs.40.rst"),
            readFile(dir + "/out/ParticleAlterAttrs.40.rst"));
}

namespace {

// The rank (OMPI_COMM_WORLD_RANK) of a process under mpirun, -1 if unknown.
int rankOf(int pid) {
  const std::string env = readFile("/proc/" + std::to_string(pid) + "/environ");
  const std::string key = std::string("OMPI_COMM_WORLD_RANK=");
  for (std::size_t at = 0; at < env.size(); at = env.find('\0', at) + 1) {
    if (env.compare(at, key.size(), key) == 0) return std::stoi(env.substr(at + key.size()));
    if (env.find('\0', at) == std::string::npos) break;
  }
  return -1;
}

}  // namespace

TEST(Reliability, StoppedRankOfFourEndsTheJobNamingIt) {
  // SIGSTOP leaves a process alive, so MPI does not notice it: the watchdog does.
  const std::string dir = freshDir("stopped_rank");
  const std::string sc = longCase(dir, 100000000);
  const Started run = startPdq({"run", sc, "-q"}, dir, 4);
  ASSERT_TRUE(waitFor([&] { return newestRestart(dir + "/out") >= 500; }, 120)) << "not stepping";
  int victim = -1;
  for (int pid : children(run.pid))
    if (rankOf(pid) == 2) victim = pid;
  ASSERT_GT(victim, 0);
  const auto stopped = std::chrono::steady_clock::now();
  ASSERT_EQ(kill(victim, SIGSTOP), 0);
  const auto r = waitPdq(run);
  EXPECT_LT(secondsSince(stopped), 10);
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("pdq: error: rank 2 has given no sign of life for"));
  EXPECT_THAT(r.err, HasSubstr("it is stopped"));
}

TEST(Reliability, FileErrorOnOneRankEndsTheJobAtOnceWithItsReason) {
  // Rank 0 alone writes restart files; one it cannot write (a folder holds its name) ends
  // the job at once, the others being in the next step's exchange, with the reason.
  const std::string dir = freshDir("one_rank_error");
  const std::string sc = springCase(dir, 100000000);
  writeFile(dir + "/out/ParticleAlterAttrs.20.rst/keep", "");
  const auto started = std::chrono::steady_clock::now();
  const auto r = runPdq({"run", sc, "-q"}, dir, 2);
  EXPECT_LT(secondsSince(started), 10);
  EXPECT_EQ(r.code, 3) << r.all();
  EXPECT_THAT(r.err, HasSubstr("rank 0: cannot rename"));
  EXPECT_THAT(r.err, HasSubstr("ParticleAlterAttrs.20.rst: Is a directory"));
  EXPECT_EQ(occurrences(r.err, "pdq: error:"), 1) << r.err;
}

TEST(Reliability, OutputFolderUnderAFileIsReportedOnceWithTheCause) {
  const std::string dir = freshDir("folder_under_file");
  const std::string sc = springCase(dir, 40);
  edit(sc, "dir = \"out\"", "dir = \"plain/out\"");
  writeFile(dir + "/plain", "a file\n");
  const auto r = runPdq({"run", sc, "-q"}, dir, 2);
  EXPECT_EQ(r.code, 3) << r.all();
  EXPECT_THAT(r.err, HasSubstr("pdq: error: cannot create the folder plain/out: plain is a file, "
                               "not a folder"));
  EXPECT_EQ(occurrences(r.err, "pdq: error:"), 1) << r.err;
  EXPECT_THAT(r.err, Not(HasSubstr("filesystem error")));
}

// A restart's interaction damage outside [0, 1] (omega_t = 7 in its Bonds file) is refused
// rather than run with a negative stiffness.
TEST(Reliability, MplmRestartWithDamageOutOfRangeIsRefused) {
  const std::string dir = freshDir("damage_range");
  writeFile(dir + "/plate.toml", R"(steps = 4
[model]
name = "mplm2d"
[particles]
generator = "mplm_plate"
width = 0.06
height = 0.06
[output]
restart_every = 2
)");
  ASSERT_EQ(runPdq({"run", "plate.toml", "-q", "--out", "out"}, dir).code, 0);
  const std::string bonds = readFile(dir + "/out/Bonds.2.rst");
  // The first bond (line 3): "owner partner dead omega_t ...": its omega_t made 7.
  const auto line = bonds.find('\n', bonds.find('\n') + 1) + 1;
  std::size_t at = line;
  for (int k = 0; k < 3; ++k) at = bonds.find(' ', at) + 1;
  const std::string edited = bonds.substr(0, at) + "7" + bonds.substr(bonds.find(' ', at));
  writeFile(dir + "/out/Bonds.2.rst", edited);
  const auto r = runPdq(
      {"run", "plate.toml", "-q", "--restart", "out/ParticleAlterAttrs.2.rst", "--out", "again"},
      dir);
  EXPECT_EQ(r.code, 1) << r.all();
  EXPECT_THAT(r.err, HasSubstr("has an interaction whose damage omega_t or omega_c is outside "
                               "[0, 1]"));
  writeFile(dir + "/out/Bonds.2.rst", bonds);
  EXPECT_EQ(runPdq({"run", "plate.toml", "-q", "--restart", "out/ParticleAlterAttrs.2.rst", "--out",
                    "again"},
                   dir)
                .code,
            0);
}

TEST(Reliability, RankThrowingAloneInTheTimeLoopEndsTheJobNamingIt) {
  // Particle 15 (X = 15, on rank 2 of 3 along X) flies out of the domain; only its rank
  // sees it (when it migrates), the others wait for it in the shuffle's exchange.
  const std::string dir = freshDir("rank_throws_alone");
  const std::string sc =
      springCase(dir, 100000, "\n[[particles.set]]\nattribute = \"vx\"\nvalue = 10\nids = [15]\n");
  edit(sc, "horizon = 1.5", "horizon = 1.5\nshuffle = true");
  edit(sc, "min_cell_size = 1.5", "min_cell_size = 1.5\nprocs = [3, 1, 1]");
  const auto started = std::chrono::steady_clock::now();
  const auto r = runPdq({"run", sc, "-q"}, dir, 3);
  EXPECT_LT(secondsSince(started), 10);
  EXPECT_EQ(r.code, 3) << r.all();
  EXPECT_THAT(r.err, HasSubstr("pdq: error: rank 2: step "));
  EXPECT_THAT(r.err, HasSubstr(": particle 15 left the domain along X"));
  EXPECT_EQ(occurrences(r.err, "pdq: error:"), 1) << r.err;
}

TEST(Reliability, InputErrorSeenByOneRankIsReportedOnce) {
  // A particle without volume: only the rank that owns it finds it, in the model's set-up.
  const std::string dir = freshDir("one_rank_input_error");
  const std::string sc = dir + "/plate.toml";
  writeFile(sc, readFile(sourceDir() + "/examples/pmb/notched_plate.toml") +
                    "\n[[particles.set]]\nattribute = \"volume\"\nvalue = 0\nids = [5]\n");
  const auto started = std::chrono::steady_clock::now();
  const auto r = runPdq({"run", sc, "-q", "--steps", "2"}, dir, 3);
  EXPECT_LT(secondsSince(started), 10);
  EXPECT_EQ(r.code, 1) << r.all();
  EXPECT_THAT(r.err, HasSubstr("particle 5 has volume 0; every particle needs a positive volume"));
  EXPECT_THAT(r.err, HasSubstr("plate.toml:"));
  EXPECT_EQ(occurrences(r.err, "pdq: error:"), 1) << r.err;
}
