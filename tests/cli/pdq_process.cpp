#include "pdq_process.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace pdq::test {

namespace fs = std::filesystem;

namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// This process's environment minus the variables of its own MPI job.
std::vector<std::string> cleanEnvironment() {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string v = *e;
    bool job = false;
    for (const char* prefix : {"OMPI_", "PMIX_", "OPAL_", "PRTE_", "HYDRA_", "PMI_"})
      job |= v.rfind(prefix, 0) == 0;
    if (!job) env.push_back(v);
  }
  return env;
}

// `/bin/sh -c cmd` with stdin /dev/null, in the clean environment: a child that inherited
// this test's MPI job variables would take itself for one of its ranks and abort in MPI_Init.
pid_t spawnShell(std::string cmd, const posix_spawn_file_actions_t& actions) {
  std::vector<std::string> env = cleanEnvironment();
  std::vector<char*> envp;
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  std::string sh = "/bin/sh", dashC = "-c";
  char* argv[] = {sh.data(), dashC.data(), cmd.data(), nullptr};
  pid_t pid = 0;
  return posix_spawn(&pid, "/bin/sh", &actions, nullptr, argv, envp.data()) == 0 ? pid : -1;
}

}  // namespace

std::string sourceDir() {
  const char* s = std::getenv("PDQ_SOURCE_DIR");
  return s ? s : PDQ_SOURCE_DIR_DEFAULT;
}

Started startPdq(const std::vector<std::string>& args, const std::string& cwd, int ranks) {
  const char* exe = std::getenv("PDQ_EXE");
  std::string cmd;
  if (!cwd.empty()) cmd += "cd " + quote(cwd) + " && ";
  cmd += "exec ";
  if (ranks > 0)
    // Oversubscribed ranks yield while they wait, as in tests/CMakeLists.txt: busy-polling
    // ranks on a loaded machine would otherwise starve the ones with work to do.
    cmd += quote(PDQ_MPIEXEC) +
           " --oversubscribe --allow-run-as-root --mca mpi_yield_when_idle 1 "
           "-x OMP_WAIT_POLICY=PASSIVE -np " +
           std::to_string(ranks) + " ";
  cmd += quote(exe ? exe : PDQ_EXE_DEFAULT);
  for (const auto& a : args) cmd += " " + quote(a);
  static int serial = 0;
  const std::string base = fs::temp_directory_path().string() + "/pdq_cli_" +
                           std::to_string(getpid()) + "_" + std::to_string(serial++);
  Started s;
  s.outPath = base + ".out";
  s.errPath = base + ".err";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, s.outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, s.errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  s.pid = spawnShell(cmd, actions);
  posix_spawn_file_actions_destroy(&actions);
  return s;
}

int runShell(const std::string& dir, const std::string& command) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  const pid_t pid = spawnShell("cd " + quote(dir) + " && " + command, actions);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (pid <= 0 || waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

Run waitPdq(const Started& s) {
  Run r;
  if (s.pid > 0) {
    int status = 0;
    waitpid(s.pid, &status, 0);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  r.out = readFile(s.outPath);
  r.err = readFile(s.errPath);
  fs::remove(s.outPath);
  fs::remove(s.errPath);
  return r;
}

Run runPdq(const std::vector<std::string>& args, const std::string& cwd, int ranks) {
  return waitPdq(startPdq(args, cwd, ranks));
}

std::string freshDir(const std::string& name) {
  const fs::path d = fs::current_path() / ("cli_work") / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void writeFile(const std::string& path, const std::string& text) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

std::vector<std::string> filesUnder(const std::string& dir) {
  std::vector<std::string> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out.push_back(fs::relative(e.path(), dir).string());
  std::sort(out.begin(), out.end());
  return out;
}

void edit(const std::string& path, const std::string& from, const std::string& to) {
  std::string text = readFile(path);
  ASSERT_NE(text.find(from), std::string::npos) << from << " not in " << path;
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  writeFile(path, text);
}

std::vector<long> rowSteps(const std::string& text) {
  std::vector<long> steps;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) steps.push_back(std::stol(line));
  return steps;
}

long lastRowStep(const std::string& path) {
  const auto s = rowSteps(readFile(path));
  return s.empty() ? -1 : s.back();
}

std::vector<int> children(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  std::vector<int> out;
  for (int c; in >> c;) out.push_back(c);
  return out;
}

bool waitFor(const std::function<bool()>& ready, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

int occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace pdq::test
