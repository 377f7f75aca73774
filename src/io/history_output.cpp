#include "io/history_output.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/error.hpp"
#include "engine/model.hpp"
#include "io/gather.hpp"

namespace pdq {

namespace {

// Opens a history file for appending on rank 0; collective. A fresh run starts it with
// `header`. A resumed run keeps the file's rows up to and including `step` (rows after it,
// and a last line cut short by a kill, are dropped) and returns the last step kept, whose
// rows must not be written again; -1 when there is none.
long openRows(OutputContext& out, const std::string& name, const std::string& header, bool resumed,
              AppendFile& file) {
  const std::string path = out.outDir + "/" + name;
  std::string problem;
  long last = -1;
  if (out.comm.root()) {
    if (resumed && std::filesystem::exists(path)) {
      std::ifstream in(path, std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      const std::string text = ss.str();
      std::string kept;
      std::size_t at = 0;
      while (at < text.size()) {
        const std::size_t nl = text.find('\n', at);
        if (nl == std::string::npos) break;  // cut short
        const std::string line = text.substr(at, nl - at + 1);
        if (at == 0) {
          if (line != header) {
            problem = "its columns are not this run's; move it away or choose another --out";
            break;
          }
        } else {
          char* end = nullptr;
          const long s = std::strtol(line.c_str(), &end, 10);
          if (end == line.c_str() || (*end != ' ' && *end != ',') || s > out.step) break;
          last = s;
        }
        kept += line;
        at = nl + 1;
      }
      if (problem.empty()) writeFileAtomically(path, kept);
    } else {
      writeFileAtomically(path, header);
    }
    if (problem.empty()) file.open(path);
  }
  if (out.comm.any(!problem.empty()))
    throw InputError(path, 1, problem.empty() ? "cannot continue this history" : problem);
  return static_cast<long>(out.comm.max(static_cast<double>(last)));  // every rank skips alike
}

}  // namespace

TimeHistoryOutput::TimeHistoryOutput(long every, std::vector<Gid> ids)
    : Output(every), ids_(std::move(ids)) {
  std::sort(ids_.begin(), ids_.end());
}

void TimeHistoryOutput::begin(OutputContext& out, bool resumed) {
  std::string header = "# step time id";
  for (const auto& n : out.ctx.particles.schema().alter) header += " " + n;
  last_ = openRows(out, "timehist.dat", header + "\n", resumed, file_);
}

void TimeHistoryOutput::write(OutputContext& out) {
  if (out.step <= last_) return;
  last_ = out.step;
  const Particles& P = out.ctx.particles;
  const int nA = P.schema().nAlter();
  std::vector<double> rows;
  for (std::size_t i = 0; i < P.owned(); ++i)
    if (std::binary_search(ids_.begin(), ids_.end(), P.gid(i))) {
      rows.push_back(static_cast<double>(P.gid(i)));
      rows.insert(rows.end(), P.alter(i), P.alter(i) + nA);
    }
  const auto all = gatherSortedRows(out.comm, rows, 1 + nA);
  if (!out.comm.root()) return;
  std::string text;
  for (std::size_t r = 0; r < all.size() / (1 + nA); ++r) {
    text += std::to_string(out.step) + " " + numberText(out.ctx.time()) + " " +
            std::to_string(static_cast<Gid>(all[r * (1 + nA)]));
    for (int c = 0; c < nA; ++c) text += " " + numberText(all[r * (1 + nA) + 1 + c]);
    text += "\n";
  }
  file_.write(text);
}

void GlobalsOutput::begin(OutputContext& out, bool resumed) {
  std::string header = "step,time";
  for (const auto& n : out.model.globals()) header += "," + n;
  last_ = openRows(out, "history.csv", header + "\n", resumed, file_);
}

void GlobalsOutput::write(OutputContext& out) {
  if (out.step <= last_) return;
  last_ = out.step;
  const std::vector<double> v = out.model.globalValues(out.ctx);  // collective
  if (!out.comm.root()) return;
  std::string text = std::to_string(out.step) + "," + numberText(out.ctx.time());
  for (double x : v) text += "," + numberText(x);
  file_.write(text + "\n");
}

}  // namespace pdq
