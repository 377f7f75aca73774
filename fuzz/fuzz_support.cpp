#include "fuzz_support.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "scenario/scenario.hpp"
#include "spring_case.hpp"

namespace pdq::fuzz {

namespace fs = std::filesystem;

namespace {
struct Folder {
  std::string path;
  Folder() {
    path = (fs::temp_directory_path() / ("pdq_fuzz." + std::to_string(getpid()))).string();
    fs::create_directories(path);
  }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};
}  // namespace

const std::string& workDir() {
  static const Folder folder;
  return folder.path;
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

std::vector<std::string> split(const std::uint8_t* data, std::size_t size, std::size_t parts) {
  const std::string all(reinterpret_cast<const char*>(data), size), cut = "\n%%\n";
  std::vector<std::string> out;
  std::size_t from = 0;
  while (out.size() + 1 < parts) {
    const auto at = all.find(cut, from);
    if (at == std::string::npos) break;
    out.push_back(all.substr(from, at - from + 1));
    from = at + cut.size();
  }
  out.push_back(all.substr(std::min(from, all.size())));
  out.resize(parts);
  return out;
}

void limitMemory() { setenv("PDQ_MEMORY_LIMIT", "200M", 1); }

const std::string& springCase() {
  static const std::string path = [] {
    limitMemory();
    const test::SpringCaseTexts t = test::springCaseTexts(20);
    writeFile(workDir() + "/fixed.dat", t.fixed);
    writeFile(workDir() + "/alter.dat", t.alter);
    writeFile(workDir() + "/lattice.toml", t.scenario);
    return workDir() + "/lattice.toml";
  }();
  return path;
}

Problem& springProblem() {
  static Scenario sc = readScenario(springCase());
  static const ParticleSet particles = sc.problem.particles;
  static const RunConfig run = sc.problem.run;
  sc.problem.particles = particles;
  sc.problem.run = run;
  return sc.problem;
}

}  // namespace pdq::fuzz
