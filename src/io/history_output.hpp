#pragma once
// Time histories: timehist.dat (chosen particles' alterable attributes every N steps, the
// thesis's file) and history.csv (the model's global values every N steps: loads,
// displacements, energies — what load-displacement curves are drawn from). Rows are
// collected on rank 0 and the files written atomically at the end of the run.
#include <string>
#include <vector>

#include "engine/output.hpp"
#include "engine/schema.hpp"

namespace pdq {

class TimeHistoryOutput final : public Output {
 public:
  TimeHistoryOutput(long every, std::vector<Gid> ids);
  void write(OutputContext& out) override;
  void finish(OutputContext& out) override;

 private:
  std::vector<Gid> ids_;
  std::string text_;
};

class GlobalsOutput final : public Output {
 public:
  explicit GlobalsOutput(long every) : Output(every) {}
  bool atEnd() const override { return true; }
  void write(OutputContext& out) override;
  void finish(OutputContext& out) override;

 private:
  std::string text_;
  long last_ = -1;
};

}  // namespace pdq
