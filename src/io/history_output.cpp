#include "io/history_output.hpp"

#include <algorithm>
#include <cstdio>

#include "engine/atomic_file.hpp"
#include "engine/model.hpp"
#include "io/gather.hpp"

namespace pdq {

TimeHistoryOutput::TimeHistoryOutput(long every, std::vector<Gid> ids)
    : Output(every), ids_(std::move(ids)) {
  std::sort(ids_.begin(), ids_.end());
}

void TimeHistoryOutput::write(OutputContext& out) {
  const Particles& P = out.ctx.particles;
  const int nA = P.schema().nAlter();
  if (text_.empty() && out.comm.root()) {
    text_ = "# step time id";
    for (const auto& n : P.schema().alter) text_ += " " + n;
    text_ += "\n";
  }
  std::vector<double> rows;
  for (std::size_t i = 0; i < P.owned(); ++i)
    if (std::binary_search(ids_.begin(), ids_.end(), P.gid(i))) {
      rows.push_back(static_cast<double>(P.gid(i)));
      rows.insert(rows.end(), P.alter(i), P.alter(i) + nA);
    }
  const auto all = gatherSortedRows(out.comm, rows, 1 + nA);
  if (!out.comm.root()) return;
  for (std::size_t r = 0; r < all.size() / (1 + nA); ++r) {
    text_ += std::to_string(out.step) + " " + numberText(out.ctx.time()) + " " +
             std::to_string(static_cast<Gid>(all[r * (1 + nA)]));
    for (int c = 0; c < nA; ++c) text_ += " " + numberText(all[r * (1 + nA) + 1 + c]);
    text_ += "\n";
  }
}

void TimeHistoryOutput::finish(OutputContext& out) {
  if (out.comm.root() && !text_.empty()) writeFileAtomically(out.outDir + "/timehist.dat", text_);
}

void GlobalsOutput::write(OutputContext& out) {
  if (out.step == last_) return;
  last_ = out.step;
  const std::vector<double> v = out.model.globalValues(out.ctx);  // collective
  if (!out.comm.root()) return;
  if (text_.empty()) {
    text_ = "step,time";
    for (const auto& n : out.model.globals()) text_ += "," + n;
    text_ += "\n";
  }
  text_ += std::to_string(out.step) + "," + numberText(out.ctx.time());
  for (double x : v) text_ += "," + numberText(x);
  text_ += "\n";
}

void GlobalsOutput::finish(OutputContext& out) {
  if (out.comm.root() && !text_.empty()) writeFileAtomically(out.outDir + "/history.csv", text_);
}

}  // namespace pdq
