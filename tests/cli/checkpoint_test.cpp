// Checkpoints (io/checkpoint.hpp) and `pdq run --resume`: runs killed at random steps
// resume bitwise; damaged, cut-short, other-scenario and bond-less checkpoints are found
// (docs/reliability.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>

#include "engine/checksum.hpp"
#include "pdq_process.hpp"
#include "spring_case.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;
using testing::HasSubstr;

namespace {

std::string checkpointName(long step) {
  char name[40];
  std::snprintf(name, sizeof name, "checkpoint.%012ld.ckpt", step);
  return name;
}

// The newest checkpoint's step in `dir` (-1: none); read while a run writes there.
long newestCheckpoint(const std::string& dir) {
  long newest = -1;
  const std::regex name(R"(checkpoint\.(\d{12})\.ckpt)");
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    std::smatch m;
    if (std::regex_match(f, m, name)) newest = std::max(newest, std::stol(m[1]));
  }
  return newest;
}

// A problem to kill: its scenario in `dir`, and the steps of its load ramp (0: none).
struct Case {
  std::string scenario;
  long rampSteps;
};

// The breaking spring lattice (no loads: initial velocities), a checkpoint every 10 steps.
Case springLattice(const std::string& dir) {
  return {springCase(dir, 100, "checkpoint_every = 10\ncheckpoints_kept = 3\n"), 0};
}

// A PMB plate held at its left edge and pulled by forces on its right one, ramped over
// 100 steps and then held (it breaks in the hold).
Case pmbPlate(const std::string& dir) {
  const std::string sc = dir + "/plate.toml";
  writeFile(sc, R"(steps = 100
[model]
name = "pmb"
E = 1.0
horizon = 2.0
density = 1.0
dt = 0.5
critical_stretch = 0.01
lattice_spacing = 1.0

[loading]
ramp_time = 50

[particles]
generator = "square"
nx = 14
ny = 6
spacing = 1.0

[[particles.set]]
attribute = "volume"
value = 1.0

[[particles.set]]
attribute = "bc_x"
value = 1
x = [0, 1]

[[particles.set]]
attribute = "fx"
value = 0.05
x = [12, 13]

[output]
dir = "out"
globals_every = 5
history_every = 5
history_ids = [1, 84]
checkpoint_every = 10
checkpoints_kept = 3
)");
  return {sc, 100};
}

// The thesis's plate in tension (mplm2d), its ramp shortened to 300 steps.
Case mplmPlate(const std::string& dir) {
  const std::string sc = dir + "/tension.toml";
  const std::string text = readFile(sourceDir() + "/examples/mplm/tension_x.toml");
  const auto output = text.find("[output]"), strength = text.find("[strength]");
  writeFile(sc, text.substr(0, output) +
                    "[output]\ndir = \"out\"\nglobals_every = 5\ncheckpoint_every = 10\n"
                    "checkpoints_kept = 3\n\n" +
                    text.substr(strength));
  edit(sc, "ramp_time = 0.001356", "ramp_time = 5.424e-05");
  return {sc, 300};
}

// True once the process has ended (a zombie not yet waited for).
bool ended(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string id, name, state;
  in >> id >> name >> state;
  return !in || state == "Z";
}

// Runs the case until its newest checkpoint reaches a step drawn from [lo, hi) by `seed`,
// kills it with SIGKILL (one rank of `ranks` under mpirun, whose job then ends), resumes it
// with --resume a few dozen steps past that checkpoint, and checks that its final
// checkpoint and histories are, byte for byte, those of a run never killed.
void killAndResume(Case (*make)(const std::string&), const std::string& name, int ranks,
                   unsigned seed, long lo, long hi) {
  SCOPED_TRACE(name + " np" + std::to_string(ranks) + " seed " + std::to_string(seed));
  const std::string dir =
      freshDir("kill_" + name + "_np" + std::to_string(ranks) + "_" + std::to_string(seed));
  const Case c = make(dir);
  std::mt19937 rng(seed);
  const long target = lo + static_cast<long>(rng() % static_cast<unsigned>(hi - lo));
  const std::string out = dir + "/out";
  const Started run = startPdq({"run", c.scenario, "-q", "--steps", "1000000"}, dir, ranks);
  waitFor([&] { return newestCheckpoint(out) >= target || ended(run.pid); }, 300);
  ASSERT_GE(newestCheckpoint(out), target) << "no checkpoint: " << waitPdq(run).all();
  const int victim = ranks > 0 ? children(run.pid).back() : run.pid;
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const Run killed = waitPdq(run);
  EXPECT_NE(killed.code, 0) << killed.all();
  const long at = newestCheckpoint(out);
  ASSERT_GE(at, target);
  const std::string end = std::to_string(at + 30);
  const auto resumed =
      runPdq({"run", c.scenario, "-q", "--steps", end, "--resume", "out"}, dir, ranks);
  ASSERT_EQ(resumed.code, 0) << resumed.all();
  const auto whole =
      runPdq({"run", c.scenario, "-q", "--steps", end, "--out", "whole"}, dir, ranks);
  ASSERT_EQ(whole.code, 0) << whole.all();
  const std::string last = "/" + checkpointName(at + 30);
  ASSERT_TRUE(fs::exists(out + last)) << last;
  EXPECT_TRUE(readFile(out + last) == readFile(dir + "/whole" + last)) << "final states differ";
  for (const char* f : {"/history.csv", "/timehist.dat"})
    if (fs::exists(dir + "/whole" + f)) {
      EXPECT_EQ(readFile(out + f), readFile(dir + "/whole" + f)) << f;
      EXPECT_EQ(lastRowStep(out + f), at + 30) << f;
    }
}

}  // namespace

TEST(Checkpoint, SpringKilledAtRandomStepsResumesBitwise) {
  for (unsigned seed : {1u, 2u}) killAndResume(springLattice, "spring", 0, seed, 20, 300);
  killAndResume(springLattice, "spring", 4, 3, 20, 300);
}

TEST(Checkpoint, PmbKilledInTheRampAndInTheHoldResumesBitwise) {
  killAndResume(pmbPlate, "pmb", 0, 4, 10, 90);  // the ramp: steps 1-100
  killAndResume(pmbPlate, "pmb", 4, 5, 10, 90);
  killAndResume(pmbPlate, "pmb", 0, 6, 110, 250);  // the hold
  killAndResume(pmbPlate, "pmb", 4, 7, 110, 250);
}

TEST(Checkpoint, Mplm2dKilledInTheRampAndInTheHoldResumesBitwise) {
  killAndResume(mplmPlate, "mplm2d", 0, 8, 20, 280);
  killAndResume(mplmPlate, "mplm2d", 4, 9, 20, 280);
  killAndResume(mplmPlate, "mplm2d", 0, 10, 310, 400);
  killAndResume(mplmPlate, "mplm2d", 4, 11, 310, 400);
}

namespace {

// A checkpoint's parts (name, text) and header bytes, by the layout in io/checkpoint.hpp.
struct Parsed {
  std::string header;  // magic and the fixed fields before the part count
  std::vector<std::pair<std::string, std::string>> parts;
};

Parsed parse(const std::string& bytes) {
  Parsed p;
  const std::size_t head = 8 + 8 + 3 * 8 + 8;
  p.header = bytes.substr(0, head);
  std::size_t at = head;
  auto get = [&](auto v) {
    std::memcpy(&v, bytes.data() + at, sizeof v);
    at += sizeof v;
    return v;
  };
  const auto n = get(std::uint32_t{});
  for (std::uint32_t k = 0; k < n; ++k) {
    const auto nameLength = get(std::uint32_t{});
    std::string name = bytes.substr(at, nameLength);
    at += nameLength;
    const auto length = get(std::uint64_t{});
    p.parts.emplace_back(name, bytes.substr(at, length));
    at += length;
  }
  return p;
}

// The bytes of a checkpoint with these parts and a correct checksum.
std::string build(const Parsed& p) {
  std::string b = p.header;
  auto put = [&](auto v) { b.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(static_cast<std::uint32_t>(p.parts.size()));
  for (const auto& [name, text] : p.parts) {
    put(static_cast<std::uint32_t>(name.size()));
    b += name;
    put(static_cast<std::uint64_t>(text.size()));
    b += text;
  }
  put(pdq::crc32(b.data(), b.size()));
  return b;
}

}  // namespace

TEST(Checkpoint, DamagedOnesAreSkippedWithAWarningNamingThem) {
  const std::string dir = freshDir("damaged_checkpoints");
  const std::string sc = springCase(dir, 100, "checkpoint_every = 20\ncheckpoints_kept = 5\n");
  ASSERT_EQ(runPdq({"run", sc, "-q", "--out", "whole"}, dir).code, 0);
  const std::string wholeEnd = readFile(dir + "/whole/" + checkpointName(100));
  const std::string good100 = readFile(dir + "/whole/" + checkpointName(100));
  const std::string good80 = readFile(dir + "/whole/" + checkpointName(80));
  for (long s : {20, 40, 60, 80, 100})
    ASSERT_TRUE(fs::exists(dir + "/whole/" + checkpointName(s))) << s;
  std::string flipped = good100;
  flipped[flipped.size() / 2] ^= 0x10;
  Parsed noBonds = parse(good100);
  ASSERT_EQ(noBonds.parts.size(), 3u);  // state, bond codes, particles
  ASSERT_EQ(noBonds.parts[1].first, "bond codes");
  Parsed cutBonds = noBonds, oneSided = noBonds;
  noBonds.parts.erase(noBonds.parts.begin() + 1);
  // The bond codes are checked as strictly as a bonds file: the first bond's partner made
  // an ID no particle has (its code rewritten, by the layout in io/checkpoint.hpp), or the
  // part cut short.
  std::string& codes = oneSided.parts[1].second;
  std::size_t at = 0;
  std::uint32_t attributes;
  std::memcpy(&attributes, codes.data(), sizeof attributes);
  at += sizeof attributes;
  for (std::uint32_t c = 0; c < attributes; ++c)
    at += 1 + 8 * static_cast<unsigned char>(codes[at]);
  at += 2 * sizeof(std::uint64_t);  // the counts of particles and bonds
  auto varint = [&] {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      const auto byte = static_cast<unsigned char>(codes[at++]);
      v |= std::uint64_t{byte & 0x7FU} << shift;
      if (!(byte & 0x80)) return v;
    }
  };
  varint();  // the first particle's ID
  varint();  // its bond count
  const std::size_t first = at;
  const std::uint64_t code = varint();
  ASSERT_EQ(code >> 1 & 1, 0u);                 // the partner's ID above the particle's
  const std::uint64_t moved = code + 4 * 1000;  // the partner's ID 1000 higher, the flag kept
  std::string bytes;
  for (std::uint64_t v = moved;; v >>= 7) {
    bytes += static_cast<char>((v & 0x7F) | (v >= 0x80 ? 0x80 : 0));
    if (v < 0x80) break;
  }
  codes.replace(first, at - first, bytes);
  cutBonds.parts[1].second.pop_back();
  struct Spoilt {
    const char* name;
    std::string newest;  // checkpoint 100 as spoilt
    std::string expected;
  };
  const std::vector<Spoilt> cases = {
      {"cut short", good100.substr(0, good100.size() * 2 / 3), "cut short"},
      {"cut in its header", good100.substr(0, 30), "cut short"},
      {"empty", "", "cut short: 0 bytes"},
      {"a flipped bit", flipped, "damaged: its CRC-32 is"},
      {"no bonds", build(noBonds), "[Bonds.100.rst]: missing: "},
      {"a bond to no particle", build(oneSided), "[Bonds.100.rst]:1: partner "},
      {"bond codes cut short", build(cutBonds), "damaged: its bond codes "},
  };
  for (const Spoilt& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string out = dir + "/out";
    fs::remove_all(out);
    fs::create_directories(out);
    writeFile(out + "/" + checkpointName(80), good80);
    writeFile(out + "/" + checkpointName(100), c.newest);
    const auto r = runPdq({"run", sc, "-q", "--resume", "out", "--steps", "100"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
    EXPECT_THAT(r.err, HasSubstr("pdq: warning: out/" + checkpointName(100)));
    EXPECT_THAT(r.err, HasSubstr(c.expected));
    EXPECT_THAT(r.err, HasSubstr("; skipped"));
    // Resumed from step 80, to the same end as the whole run.
    EXPECT_EQ(readFile(out + "/" + checkpointName(100)), wholeEnd);
    EXPECT_EQ(readFile(out + "/ParticleAlterAttrs.100.rst"),
              readFile(dir + "/whole/ParticleAlterAttrs.100.rst"));
  }
  // None valid: an error naming each, nothing run.
  const std::string out = dir + "/out";
  fs::remove_all(out);
  fs::create_directories(out);
  writeFile(out + "/" + checkpointName(80), good80.substr(0, 100));
  writeFile(out + "/" + checkpointName(100), flipped);
  const auto none = runPdq({"run", sc, "-q", "--resume", "out"}, dir);
  EXPECT_EQ(none.code, 1) << none.all();
  EXPECT_THAT(none.err, HasSubstr("error: out: no valid checkpoint to resume from:"));
  EXPECT_THAT(none.err, HasSubstr(checkpointName(80) + ": cut short"));
  EXPECT_THAT(none.err, HasSubstr(checkpointName(100) + ": damaged"));
  EXPECT_FALSE(fs::exists(out + "/history.csv"));
  const auto empty = runPdq({"run", sc, "-q", "--resume", "whole_not_there"}, dir);
  EXPECT_EQ(empty.code, 1) << empty.all();
  EXPECT_THAT(empty.err, HasSubstr("no checkpoint (checkpoint.<step>.ckpt) to resume from"));
}

TEST(Checkpoint, AnotherScenarioIsRefusedUnlessForced) {
  const std::string dir = freshDir("other_scenario");
  const std::string sc = springCase(dir, 60, "checkpoint_every = 20\n");
  ASSERT_EQ(runPdq({"run", sc, "-q", "--steps", "40"}, dir).code, 0);
  const std::string text = readFile(sc);
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"critical_stretch = 0.02", "critical_stretch = 0.03"}, {"dt = 0.05", "dt = 0.04"}}) {
    SCOPED_TRACE(to);
    writeFile(sc, text);
    edit(sc, from, to);
    const auto r = runPdq({"run", sc, "-q", "--resume", "out"}, dir);
    EXPECT_EQ(r.code, 1) << r.all();
    EXPECT_THAT(r.err, HasSubstr(checkpointName(40) +
                                 ": written by a run of another scenario (its input has "
                                 "changed since); start afresh, or continue anyway with --force"));
    EXPECT_FALSE(fs::exists(dir + "/out/" + checkpointName(60))) << "it ran";
  }
  // The particles' file it names counts too.
  writeFile(sc, text);
  const std::string alter = readFile(dir + "/alter.dat");
  edit(dir + "/alter.dat", "\n5 5 0 0 0 0 0\n", "\n5 5.001 0 0 0 0 0\n");
  EXPECT_EQ(runPdq({"run", sc, "-q", "--resume", "out"}, dir).code, 1);
  writeFile(dir + "/alter.dat", alter);
  // Forced with another time step: it continues with the new one.
  edit(sc, "dt = 0.05", "dt = 0.04");
  const auto forced = runPdq({"run", sc, "-q", "--resume", "out", "--force"}, dir);
  EXPECT_EQ(forced.code, 0) << forced.all();
  EXPECT_THAT(readFile(dir + "/out/State.60.rst"), HasSubstr("dt 0.040000000000000001\n"));
  const auto bad = runPdq({"run", sc, "-q", "--force"}, dir);
  EXPECT_EQ(bad.code, 2) << bad.all();
}

namespace {

// The trials recorded in a strength search's journal.
int journalTrials(const std::string& path) {
  std::ifstream in(path);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty() && line[0] != '#';
  return n;
}

}  // namespace

TEST(Checkpoint, StrengthSearchKilledBetweenTrialsResumesWithoutRerunningThem) {
  const std::string dir = freshDir("strength_resume");
  const std::string plate = sourceDir() + "/examples/mplm/tension_x.toml";
  const std::vector<std::string> search = {"strength", plate,          "--set", "max_trials=3",
                                           "--set",    "at_once=1",    "--set", "time_scale=0.3",
                                           "--set",    "hold_length=1"};
  const std::string out = dir + "/tension_x_out/strength";
  const Started run = startPdq(search, dir);
  waitFor([&] { return journalTrials(out + "/journal.txt") >= 1 || ended(run.pid); }, 300);
  ASSERT_EQ(kill(run.pid, SIGKILL), 0);
  waitPdq(run);
  const int done = journalTrials(out + "/journal.txt");
  ASSERT_GE(done, 1);
  ASSERT_LT(done, 3) << "the search ended before it was killed";
  const auto firstRun = fs::last_write_time(out + "/trial_01/history.csv");
  const std::string firstHistory = readFile(out + "/trial_01/history.csv");

  // Other options: another search, refused.
  auto other = search;
  other[3] = "max_trials=4";
  other.insert(other.end(), {"--resume", "tension_x_out"});
  const auto refused = runPdq(other, dir);
  EXPECT_EQ(refused.code, 1) << refused.all();
  EXPECT_THAT(refused.err, HasSubstr("journal.txt:1: written by a search of another scenario or "
                                     "with other options"));

  auto again = search;
  again.insert(again.end(), {"--resume", "tension_x_out"});
  const auto resumed = runPdq(again, dir);
  ASSERT_EQ(resumed.code, 0) << resumed.all();
  EXPECT_EQ(occurrences(resumed.out, "(done before: from journal.txt)"), done) << resumed.out;
  EXPECT_EQ(journalTrials(out + "/journal.txt"), 3);
  EXPECT_EQ(occurrences(readFile(out + "/trials.csv"), "\n"), 4);  // header and three trials
  EXPECT_TRUE(fs::exists(out + "/trial_03/history.csv"));
  // The finished trial was not run again: its outputs are untouched.
  EXPECT_EQ(fs::last_write_time(out + "/trial_01/history.csv"), firstRun);
  EXPECT_EQ(readFile(out + "/trial_01/history.csv"), firstHistory);
}

TEST(Checkpoint, AReusedFolderKeepsNothingStale) {
  const std::string dir = freshDir("reused_folder");
  const std::string sc = springCase(dir, 100, "checkpoint_every = 20\n");
  ASSERT_EQ(runPdq({"run", sc, "-q"}, dir).code, 0);
  const std::string out = dir + "/out";
  ASSERT_TRUE(fs::exists(out + "/ParticleAlterAttrs.100.rst"));
  ASSERT_TRUE(fs::exists(out + "/" + checkpointName(100)));
  // What a kill while writing leaves (of a process that is gone), and a later step's file.
  writeFile(out + "/history.csv.tmp.2147483646", "step,time\n");
  writeFile(out + "/ParticleAlterAttrs.500.rst", readFile(out + "/ParticleAlterAttrs.100.rst"));
  // Started afresh for 50 steps: nothing of the earlier run after step 50 is left.
  ASSERT_EQ(runPdq({"run", sc, "-q", "--steps", "50"}, dir).code, 0);
  EXPECT_FALSE(fs::exists(out + "/history.csv.tmp.2147483646"));
  EXPECT_THAT(readFile(out + "/debug.txt"), HasSubstr("removed history.csv.tmp.2147483646"));
  for (long s : {60, 100, 500})
    EXPECT_FALSE(fs::exists(out + "/ParticleAlterAttrs." + std::to_string(s) + ".rst")) << s;
  EXPECT_FALSE(fs::exists(out + "/Bonds.100.rst"));
  EXPECT_FALSE(fs::exists(out + "/State.100.rst"));
  EXPECT_FALSE(fs::exists(out + "/" + checkpointName(100)));
  EXPECT_TRUE(fs::exists(out + "/" + checkpointName(50)));
  EXPECT_EQ(lastRowStep(out + "/history.csv"), 50);
  // Restarted from step 20's restart file: the files after 20 are this run's again.
  writeFile(out + "/ParticleAlterAttrs.500.rst", readFile(out + "/ParticleAlterAttrs.50.rst"));
  ASSERT_EQ(
      runPdq({"run", sc, "-q", "--steps", "30", "--restart", "out/ParticleAlterAttrs.20.rst"}, dir)
          .code,
      0);
  EXPECT_FALSE(fs::exists(out + "/ParticleAlterAttrs.500.rst"));
  EXPECT_FALSE(fs::exists(out + "/ParticleAlterAttrs.50.rst"));
  EXPECT_FALSE(fs::exists(out + "/" + checkpointName(50)));
  EXPECT_TRUE(fs::exists(out + "/ParticleAlterAttrs.20.rst"));
  EXPECT_TRUE(fs::exists(out + "/" + checkpointName(30)));
}

TEST(Checkpoint, BatchScriptsResumeAndSubmitThemselvesAgain) {
  // tools/pdq.slurm and tools/pdq.pbs with stand-ins for the batch system's commands that
  // run pdq here and record what would be submitted.
  const std::string dir = freshDir("batch_scripts");
  springCase(dir, 100000000, "checkpoint_every = 500\n");
  const char* exe = std::getenv("PDQ_EXE");
  const std::string bin = dir + "/bin";
  fs::create_directories(bin);
  const std::vector<std::pair<std::string, std::string>> fakes = {
      {"pdq", "exec '" + std::string(exe ? exe : PDQ_EXE_DEFAULT) + "' \"$@\""},
      {"srun", "exec \"$@\""},
      {"mpirun", "while [ \"$1\" != pdq ]; do shift; done; exec \"$@\""},
      {"sbatch", "echo \"sbatch $*\" >> submitted.txt"},
      {"qsub", "echo \"qsub $*\" >> submitted.txt"},
      {"scontrol", "echo '   Command=/cluster/jobs/pdq.slurm'"}};
  for (const auto& [name, body] : fakes) {
    writeFile(bin + "/" + name, "#!/bin/bash\n" + body + "\n");
    fs::permissions(bin + "/" + name, fs::perms::owner_all, fs::perm_options::add);
  }
  writeFile(dir + "/nodes", "localhost\n");
  const std::string env = "PATH='" + bin + "':$PATH PDQ_OUT=out ";
  const std::string slurm = env + "SLURM_NTASKS=1 SLURM_JOB_ID=7 bash '" + sourceDir() +
                            "/tools/pdq.slurm' lattice.toml --max-wall-time 3s";
  // The first job starts the run, stops before its time is up and submits the next.
  EXPECT_EQ(runShell(dir, slurm + " > first.log 2>&1"), 0) << readFile(dir + "/first.log");
  EXPECT_THAT(readFile(dir + "/first.log"), HasSubstr("stopped at step"));
  EXPECT_EQ(readFile(dir + "/submitted.txt"),
            "sbatch --export=ALL,PDQ_OUT=out,PDQ_SUBMISSION=2 /cluster/jobs/pdq.slurm "
            "lattice.toml --max-wall-time 3s\n");
  const long first = newestCheckpoint(dir + "/out");
  EXPECT_GT(first, 0);
  // The next resumes from the checkpoint, and with the last submission allowed stops there.
  EXPECT_EQ(runShell(dir, "PDQ_SUBMISSION=2 PDQ_MAX_SUBMISSIONS=2 " + slurm + " > second.log 2>&1"),
            4);
  EXPECT_THAT(readFile(dir + "/second.log"),
              HasSubstr("resuming from out/" + checkpointName(first)));
  EXPECT_GT(newestCheckpoint(dir + "/out"), first);
  const long second = newestCheckpoint(dir + "/out");
  // PBS: the same through --max-wall-time, submitting itself with qsub.
  fs::remove(dir + "/submitted.txt");
  EXPECT_EQ(runShell(dir, env +
                              "SCENARIO=lattice.toml PBS_NODEFILE=nodes PBS_O_WORKDIR=. "
                              "PDQ_SUBMISSION=3 PDQ_WALL_TIME=3s PDQ_SCRIPT=/jobs/pdq.pbs bash '" +
                              sourceDir() + "/tools/pdq.pbs' > third.log 2>&1"),
            0)
      << readFile(dir + "/third.log");
  EXPECT_THAT(readFile(dir + "/third.log"),
              HasSubstr("resuming from out/" + checkpointName(second)));
  EXPECT_EQ(readFile(dir + "/submitted.txt"),
            "qsub -v SCENARIO=lattice.toml,PDQ_OUT=out,PDQ_SUBMISSION=4,PDQ_SCRIPT=/jobs/pdq.pbs,"
            "PDQ_WALL_TIME=3s,PDQ_OPTIONS= /jobs/pdq.pbs\n");
  EXPECT_GT(newestCheckpoint(dir + "/out"), second);
}

// A quasi-static run writes checkpoints on wall time too (at load steps, the ranks agreeing
// as at time steps), and resuming from one ends as the uninterrupted run.
TEST(Checkpoint, QuasiStaticRunsCheckpointOnWallTime) {
  const std::string dir = freshDir("quasi_static_minutes");
  writeFile(dir + "/qs.toml", R"([output]
checkpoint_minutes = 1e-9   # at every load step
checkpoints_kept = 10
[solver]
load_steps = 3
kind = "quasi_static"
max_iterations = 100000
tolerance = 1e-6
[model]
name = "mplm2d"
[particles]
height = 0.12
width = 0.1
generator = "mplm_plate"
)");
  ASSERT_EQ(runPdq({"run", "qs.toml", "-q", "--out", "whole"}, dir).code, 0);
  for (long s : {1, 2, 3}) EXPECT_TRUE(fs::exists(dir + "/whole/" + checkpointName(s))) << s;
  fs::create_directories(dir + "/out");
  fs::copy_file(dir + "/whole/" + checkpointName(2), dir + "/out/" + checkpointName(2));
  const auto r = runPdq({"run", "qs.toml", "-q", "--resume", "out"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/out/" + checkpointName(3)),
            readFile(dir + "/whole/" + checkpointName(3)));
}
