#include "scenario/assignment.hpp"

#include <algorithm>
#include <cmath>

#include "engine/error.hpp"

namespace pdq {

Selection readSelection(const Params& p, const std::string& file) {
  Selection a;
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (!p.has(axes[k])) continue;
    const auto r = p.numbers(axes[k]);
    const int at = p.raw(axes[k])->line;
    if (r.size() != 2 || r[0] > r[1])
      throw InputError(file, at, std::string(axes[k]) + " needs a range [lo, hi] with lo <= hi");
    a.range[k] = std::make_pair(r[0], r[1]);
  }
  if (p.has("ids"))
    for (double v : p.numbers("ids")) {
      if (v < 0 || v != std::floor(v))
        throw InputError(file, p.raw("ids")->line, "ids must be whole numbers >= 0");
      a.ids.push_back(static_cast<Gid>(v));
    }
  std::sort(a.ids.begin(), a.ids.end());
  return a;
}

bool Selection::selects(const double* X, Gid id) const {
  bool in = ids.empty() || std::binary_search(ids.begin(), ids.end(), id);
  for (int d = 0; d < 3 && in; ++d)
    if (range[d]) in = X[d] >= range[d]->first && X[d] <= range[d]->second;
  return in;
}

std::vector<Gid> Selection::selected(const ParticleSet& ps) const {
  std::vector<Gid> out;
  for (std::size_t k = 0; k < ps.size(); ++k)
    if (selects(ps.fixedRow(k), ps.gid[k])) out.push_back(ps.gid[k]);
  std::sort(out.begin(), out.end());
  return out;
}

Assignment readAssignment(const Params& p, const std::string& file, int line) {
  Assignment a;
  a.file = file;
  a.line = line;
  if (!p.has("attribute"))
    throw InputError(file, line,
                     p.keys().empty() ? "this [[particles.set]] entry is empty (is its header "
                                        "written twice?); give attribute = \"...\" and its value"
                                      : "this [[particles.set]] entry needs attribute = \"...\" "
                                        "(the attribute it sets)");
  a.attribute = p.text("attribute");
  a.attributeLine = p.raw("attribute")->line;
  a.value = p.number("value", 0.0);
  if (p.has("gradient")) {
    const auto g = p.numbers("gradient");
    if (g.size() != 3)
      throw InputError(file, p.raw("gradient")->line,
                       "gradient needs 3 numbers (per unit X, Y, Z)");
    std::copy(g.begin(), g.end(), a.gradient.begin());
  }
  a.where = readSelection(p, file);
  p.checkAllUsed();
  return a;
}

std::vector<std::size_t> applyAssignments(ParticleSet& ps, const Schema& schema,
                                          const std::vector<Assignment>& entries) {
  std::vector<std::size_t> counts;
  for (const Assignment& a : entries) {
    const int fixedCol = schema.fixedIndex(a.attribute), alterCol = schema.alterIndex(a.attribute);
    if ((fixedCol >= 0 && fixedCol < 3) || (alterCol >= 0 && alterCol < 3))
      throw InputError(a.file, a.attributeLine,
                       "'" + a.attribute + "' is a position; positions come from the particles");
    if (fixedCol < 0 && alterCol < 0) {
      std::vector<std::string> names(schema.fixed.begin() + 3, schema.fixed.end());
      names.insert(names.end(), schema.alter.begin() + 3, schema.alter.end());
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      throw InputError(a.file, a.attributeLine,
                       "the model has no attribute '" + a.attribute + "'" +
                           suggestion(a.attribute, names) +
                           "; settable: " + (known.empty() ? "none" : known));
    }
    std::size_t selected = 0;
    for (std::size_t k = 0; k < ps.size(); ++k) {
      const double* X = ps.fixedRow(k);
      if (!a.where.selects(X, ps.gid[k])) continue;
      const double v = a.value + a.gradient[0] * X[0] + a.gradient[1] * X[1] + a.gradient[2] * X[2];
      if (fixedCol >= 0)
        ps.fixedRow(k)[fixedCol] = v;
      else
        ps.alterRow(k)[alterCol] = v;
      ++selected;
    }
    if (selected == 0)
      throw InputError(a.file, a.line,
                       "this [[particles.set]] entry selects no particle (check its x, y, z "
                       "ranges and ids against the particles' reference positions)");
    counts.push_back(selected);
  }
  return counts;
}

}  // namespace pdq
