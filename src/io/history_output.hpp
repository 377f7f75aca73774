#pragma once
// Time histories: timehist.dat (chosen particles' alterable attributes every N steps, the
// thesis's file) and history.csv (the model's global values every N steps: loads,
// displacements, energies — what load-displacement curves are drawn from). Rank 0 appends
// each step's rows to the file as they are made, so a run stopped at any moment keeps
// every row up to its last output step. A restarted run continues the files of its output
// folder: it keeps their rows up to the restart step and appends the rest.
#include <string>
#include <vector>

#include "engine/atomic_file.hpp"
#include "engine/output.hpp"
#include "engine/schema.hpp"

namespace pdq {

class TimeHistoryOutput final : public Output {
 public:
  TimeHistoryOutput(long every, std::vector<Gid> ids);
  void begin(OutputContext& out, bool resumed) override;
  void write(OutputContext& out) override;

 private:
  std::vector<Gid> ids_;
  AppendFile file_;
  long last_ = -1;  // the last step with rows in the file
};

class GlobalsOutput final : public Output {
 public:
  explicit GlobalsOutput(long every) : Output(every) {}
  bool atEnd() const override { return true; }
  void begin(OutputContext& out, bool resumed) override;
  void write(OutputContext& out) override;

 private:
  AppendFile file_;
  long last_ = -1;
};

}  // namespace pdq
