#pragma once
// Running the real pdq executable (env PDQ_EXE) from a test, alone or under mpirun, with
// its exit code, standard output and standard error. The child gets the environment
// without this test's own MPI job variables, so it starts as a job of its own.
#include <functional>
#include <string>
#include <vector>

namespace pdq::test {

struct Run {
  int code = -1;
  std::string out, err;
  std::string all() const { return out + err; }
};

// `pdq args...` in `cwd` (empty: the current folder); ranks > 0: under mpirun -np ranks.
Run runPdq(const std::vector<std::string>& args, const std::string& cwd = "", int ranks = 0);

// The same started in the background: `pid` is pdq's (or mpirun's) own process id.
struct Started {
  int pid = -1;
  std::string outPath, errPath;
};
Started startPdq(const std::vector<std::string>& args, const std::string& cwd = "", int ranks = 0);
Run waitPdq(const Started& started);  // waits for it to end
// `sh -c command` in `dir`, without this test's MPI job in its environment; its exit code
// (-1: it did not exit).
int runShell(const std::string& dir, const std::string& command);

// A new empty folder for one test.
std::string freshDir(const std::string& name);
std::string readFile(const std::string& path);
void writeFile(const std::string& path, const std::string& text);
// Every file under `dir` (relative paths, sorted).
std::vector<std::string> filesUnder(const std::string& dir);
std::string sourceDir();  // env PDQ_SOURCE_DIR

// Replaces every `from` in the file by `to` (a test failure if there is none).
void edit(const std::string& path, const std::string& from, const std::string& to);
// Steps of the rows of a history file's text (the number before the first ',' or ' ').
std::vector<long> rowSteps(const std::string& text);
long lastRowStep(const std::string& path);  // -1: no rows
// How often `what` occurs in `text` (overlapping occurrences counted).
int occurrences(const std::string& text, const std::string& what);
// The process ids of a process's children (the ranks under mpirun).
std::vector<int> children(int pid);
// Polls `ready` until it is true (true) or `seconds` have passed (false).
bool waitFor(const std::function<bool()>& ready, double seconds);

}  // namespace pdq::test
