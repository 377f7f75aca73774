#include "studies/strength_journal.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/atomic_file.hpp"
#include "engine/checksum.hpp"
#include "engine/error.hpp"

namespace pdq::strength {

namespace {

const std::string kHead = "# pdq strength journal: search ";

std::string hex(std::uint64_t v, int digits) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%0*llx", digits, static_cast<unsigned long long>(v));
  return buf;
}

}  // namespace

std::string journalPath(const std::string& strengthDir) { return strengthDir + "/journal.txt"; }

std::uint64_t searchHash(std::uint64_t scenario, const Params& options) {
  std::uint64_t h = hash64(hex(scenario, 16));
  for (const auto& k : options.keys()) h = hash64(k + "=" + options.raw(k)->text + "\n", h);
  return h;
}

void writeJournal(const std::string& path, std::uint64_t search, const std::vector<Trial>& trials) {
  std::string text = kHead + hex(search, 16) + "\n";
  text += "# trial\tload\tholds\tu_hold\tu_mid\tu_end\tbroken_mid\tbroken_end\tsteps\tmode\n";
  for (const Trial& t : trials) {
    text += std::to_string(t.index);
    for (double v : {t.load, t.holds ? 1.0 : 0.0, t.uHold, t.uMid, t.uEnd, t.brokenMid, t.brokenEnd,
                     static_cast<double>(t.steps)})
      text += "\t" + numberText(v);
    text += "\t" + t.mode + "\n";
  }
  text += "# crc32 " + hex(crc32(text.data(), text.size()), 8) + "\n";
  AtomicFile f(path);
  f.stream() << text;
  f.commit(true);
}

std::vector<Trial> readJournal(const std::string& path, std::uint64_t search, bool force) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "no journal of a strength search to resume from");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const auto last = text.rfind("# crc32 ");
  if (last == std::string::npos || text.size() != last + 8 + 8 + 1 ||
      text.substr(last + 8, 8) != hex(crc32(text.data(), last), 8))
    throw InputError(path, 0, "damaged or cut short (its CRC-32 does not match)");
  std::istringstream lines(text.substr(0, last));
  std::string line;
  std::getline(lines, line);
  if (line.rfind(kHead, 0) != 0) throw InputError(path, 1, "not a pdq strength journal");
  if (line.substr(kHead.size()) != hex(search, 16) && !force)
    throw InputError(path, 1,
                     "written by a search of another scenario or with other options; start "
                     "afresh, or continue anyway with --force");
  std::vector<Trial> trials;
  for (int n = 2; std::getline(lines, line); ++n) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string w; std::getline(fields, w, '\t');) f.push_back(w);
    if (f.size() != 10) throw InputError(path, n, "expected 10 fields separated by tabs");
    std::vector<double> v;
    for (int k = 0; k < 9; ++k) {
      std::size_t used = 0;
      double x = 0;
      try {
        x = std::stod(f[k], &used);
      } catch (const std::exception&) {
      }
      if (used != f[k].size() || f[k].empty())
        throw InputError(path, n, "'" + f[k] + "' is not a number");
      v.push_back(x);
    }
    Trial t;
    t.index = static_cast<int>(v[0]);
    t.load = v[1];
    t.holds = v[2] != 0;
    t.uHold = v[3];
    t.uMid = v[4];
    t.uEnd = v[5];
    t.brokenMid = v[6];
    t.brokenEnd = v[7];
    t.steps = static_cast<long>(v[8]);
    t.mode = f[9];
    trials.push_back(std::move(t));
  }
  return trials;
}

}  // namespace pdq::strength
