#include "io/restart.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"
#include "io/gather.hpp"
#include "io/text_table.hpp"

namespace pdq {

static void appendNumber(std::string& line, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, " %.17g", v);
  line += buf;
}

std::string restartPath(const std::string& dir, long step) {
  return dir + "/ParticleAlterAttrs." + std::to_string(step) + ".rst";
}

std::string bondRestartPath(const std::string& dir, long step) {
  return dir + "/Bonds." + std::to_string(step) + ".rst";
}

std::string stateRestartPath(const std::string& dir, long step) {
  return dir + "/State." + std::to_string(step) + ".rst";
}

std::string fixedRestartPath(const std::string& dir, long step) {
  return dir + "/ParticleFixedAttrs." + std::to_string(step) + ".rst";
}

// A shuffling model in a periodic box has its reference positions wrapped with its
// current ones; only then do the fixed attributes change, and only then are they saved.
static bool fixedChange(const OutputContext& out) {
  const auto& p = out.ctx.domain().periodic;
  return out.model.shuffles() && (p[0] || p[1] || p[2]);
}

static void appendRows(std::string& text, const std::vector<double>& rows, int width) {
  std::string line;
  for (std::size_t r = 0; r < rows.size() / width; ++r) {
    const double* row = &rows[r * width];
    line = std::to_string(static_cast<Gid>(row[0]));
    for (int c = 1; c < width; ++c) appendNumber(line, row[c]);
    text += line;
    text += '\n';
  }
}

RestartNames restartNames(const std::string& dir, long step) {
  return {restartPath(dir, step), stateRestartPath(dir, step), fixedRestartPath(dir, step),
          bondRestartPath(dir, step)};
}

namespace {

// Particles per piece of the restart's gathers: rank 0 holds the rows and text of one piece
// at a time, not of the whole problem.
constexpr long kPieceParticles = 8192;

// Rows of the owned particles gathered to rank 0 by pieces of the ID range (about
// kPieceParticles particles each) and handed to `take` there in ID order; collective.
// `order`: the owned particles in ID order; `rows(i, out)` appends particle i's rows.
void gatherByPieces(const OutputContext& out, const std::vector<std::size_t>& order, int width,
                    int keyColumns,
                    const std::function<void(std::size_t, std::vector<double>&)>& rows,
                    const std::function<void(const std::vector<double>&)>& take) {
  const Particles& P = out.ctx.particles;
  const long total = out.comm.sum(static_cast<long>(P.owned()));
  const auto maxId = static_cast<Gid>(
      out.comm.max(order.empty() ? 0.0 : static_cast<double>(P.gid(order.back()))));
  const long pieces = std::max(1L, (total + kPieceParticles - 1) / kPieceParticles);
  const Gid span = maxId / pieces + 1;
  std::vector<double> buf;
  std::size_t k = 0;
  for (long p = 0; p < pieces; ++p) {
    const Gid hi = p + 1 == pieces ? maxId + 1 : (p + 1) * span;
    buf.clear();
    while (k < order.size() && P.gid(order[k]) < hi) rows(order[k++], buf);
    const auto all = gatherSortedRows(out.comm, buf, width, keyColumns);
    if (out.comm.root()) take(all);
  }
}

}  // namespace

void restartParts(OutputContext& out, bool bonds, const RestartSink& sink) {
  using enum RestartPart;
  const Particles& P = out.ctx.particles;
  const Bonds& B = out.ctx.bonds;
  const Schema& s = P.schema();
  const int nA = s.nAlter(), nB = B.nAttr(), nF = s.nFixed();
  const bool withFixed = fixedChange(out);
  const long nBondsTotal = out.comm.sum(static_cast<long>(B.count()));
  const bool root = out.comm.root();
  // In ID order (each particle's bonds are in partner order), so that the rows are merged
  // rather than sorted on rank 0.
  std::vector<std::size_t> order(P.owned());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return P.gid(a) < P.gid(b); });
  std::string text, line;
  if (root) {
    // Global values, the same on every rank.
    auto row = [&](const char* key, const std::vector<double>& values) {
      line = key;
      for (double v : values) appendNumber(line, v);
      text += line + "\n";
    };
    text = "# pdq state: step " + std::to_string(out.step) + "\n";
    row("dt", {out.ctx.dt()});
    row("integrator", out.ctx.integrator().state());
    row("model", out.model.saveState());
    if (!out.checks.empty()) row("checks", out.checks);
    text += "bonds " + std::to_string(nBondsTotal) + "\n";  // so a lost or cut bonds file is seen
    sink(STATE, text);
  }
  // A file of one row per particle: its ID, then the `n` numbers at `row(i)`.
  auto perParticle = [&](RestartPart part, const std::string& header, int n, auto row) {
    if (root) sink(part, header);
    gatherByPieces(
        out, order, 1 + n, 1,
        [&](std::size_t i, std::vector<double>& r) {
          r.push_back(static_cast<double>(P.gid(i)));
          r.insert(r.end(), row(i), row(i) + n);
        },
        [&](const std::vector<double>& rows) {
          text.clear();
          appendRows(text, rows, 1 + n);
          sink(part, text);
        });
  };
  if (withFixed) {
    std::string header =
        "# pdq fixed attributes: step " + std::to_string(out.step) + "\n# columns: id";
    for (const auto& n : s.fixed) header += " " + n;
    perParticle(FIXED, header + "\n", nF, [&](std::size_t i) { return P.fixed(i); });
  }
  if (nBondsTotal && bonds) {
    if (root) {
      text = "# pdq bonds: step " + std::to_string(out.step) + "\n# columns: id partner dead";
      for (const auto& n : s.bond) text += " " + n;
      sink(BONDS, text + "\n");
    }
    gatherByPieces(
        out, order, 3 + nB, 2,
        [&](std::size_t i, std::vector<double>& r) {
          for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
            r.push_back(static_cast<double>(P.gid(i)));
            r.push_back(static_cast<double>(B.partnerGid(b)));
            r.push_back(B.alive(b) ? 0 : 1);
            r.insert(r.end(), B.attr(b), B.attr(b) + nB);
          }
        },
        [&](const std::vector<double>& rows) {
          text.clear();
          for (std::size_t r = 0; r < rows.size() / (3 + nB); ++r) {
            const double* row = &rows[r * (3 + nB)];
            line = std::to_string(static_cast<Gid>(row[0])) + " " +
                   std::to_string(static_cast<Gid>(row[1])) + (row[2] != 0 ? " 1" : " 0");
            for (int c = 0; c < nB; ++c) appendNumber(line, row[3 + c]);
            text += line + "\n";
          }
          sink(BONDS, text);
        });
  }
  std::ostringstream header;
  header << "# pdq restart: step " << out.step << " time " << out.ctx.time() << "\n# columns: id";
  for (const auto& n : s.alter) header << " " << n;
  perParticle(PARTICLES, header.str() + "\n", nA, [&](std::size_t i) { return P.alter(i); });
}

void removeRestartFiles(const std::string& dir, long step) {
  for (const char* kind : {"ParticleAlterAttrs.", "Bonds.", "State.", "ParticleFixedAttrs."})
    removeStepFiles(dir, kind, ".rst", step);
}

void RestartOutput::begin(OutputContext& out, bool resumed) {
  // A reused folder: an earlier run's files after this run's start would look newest.
  if (out.comm.root()) removeRestartFiles(out.outDir, resumed ? out.step : -1);
}

void RestartOutput::write(OutputContext& out) {
  if (out.step == lastWritten_) return;
  lastWritten_ = out.step;
  // Each file written as its pieces arrive (rank 0 never holds a whole one), and put in
  // place when the next begins; the particle file last: it always has its state and bond
  // files beside it.
  const RestartNames n = restartNames(out.outDir, out.step);
  const std::string* names[] = {&n.state, &n.fixed, &n.bonds, &n.particles};
  std::unique_ptr<AtomicFile> file;
  int current = -1;
  restartParts(out, true, [&](RestartPart part, const std::string& text) {
    if (static_cast<int>(part) != current) {
      if (file) file->commit();
      current = static_cast<int>(part);
      file = std::make_unique<AtomicFile>(*names[current]);
    }
    file->stream().write(text.data(), static_cast<std::streamsize>(text.size()));
  });
  if (file) file->commit();
}

static long stepOfHeader(const std::string& text, const std::string& path) {
  const std::string line = text.substr(0, text.find('\n'));
  const std::string tag = "# pdq restart: step ";
  if (line.rfind(tag, 0) != 0)
    throw InputError(path, 1, "not a pdq restart file (the first line must be '" + tag + "N ...')");
  std::istringstream s(line.substr(tag.size()));
  long step = -1;
  if (!(s >> step) || step < 0) throw InputError(path, 1, "the restart step is not a whole number");
  return step;
}

// State.<step>.rst: lines "key value..."; `bonds` gets the bond count (-1: not given).
static void readState(const std::string& text, const std::string& path, RestartState& st,
                      long& bonds) {
  std::istringstream in(text);
  std::string line;
  int n = 0;
  bool dt = false;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string key;
    s >> key;
    std::vector<double> values;
    std::string word;
    while (s >> word) {
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(word, &used);
      } catch (const std::exception&) {
      }
      if (used != word.size()) throw InputError(path, n, "'" + word + "' is not a number");
      values.push_back(v);
    }
    if (key == "dt" && values.size() == 1) {
      st.dt = values[0];
      dt = true;
    } else if (key == "integrator") {
      st.integrator = values;
    } else if (key == "model") {
      st.model = values;
    } else if (key == "checks" && values.size() == 9) {
      st.checks = values;
    } else if (key == "bonds" && values.size() == 1 && values[0] >= 0 &&
               values[0] == static_cast<double>(static_cast<long>(values[0]))) {
      bonds = static_cast<long>(values[0]);
    } else {
      throw InputError(
          path, n,
          "expected 'dt VALUE', 'integrator VALUES', 'model VALUES', 'checks' and 9 values "
          "or 'bonds N'");
    }
  }
  if (!dt) throw InputError(path, 0, "the state file has no 'dt' line");
  st.hasState = true;
}

static std::optional<std::string> fileText(const std::string& path) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the file (unreadable)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

RestartState readRestart(const std::string& path, Problem& pb) {
  RestartTexts t;
  const auto particles = fileText(path);
  if (!particles) throw InputError(path, 0, "cannot open the restart file (missing or unreadable)");
  t.particles = *particles;
  t.step = stepOfHeader(t.particles, path);
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  RestartNames names = restartNames(dir, t.step);
  names.particles = path;
  t.state = fileText(names.state);
  t.fixed = fileText(names.fixed);
  t.bonds = fileText(names.bonds);
  return parseRestart(t, names, pb);
}

RestartState parseRestart(const RestartTexts& t, const RestartNames& names, Problem& pb) {
  const std::string& path = names.particles;
  const long step = stepOfHeader(t.particles, path);
  if (t.step >= 0 && step != t.step)
    throw InputError(path, 1, "not the particles of step " + std::to_string(t.step));
  const Schema schema = pb.model->schema();
  ParticleSet& ps = pb.particles;
  std::unordered_map<Gid, std::size_t> index;
  for (std::size_t k = 0; k < ps.size(); ++k) index.emplace(ps.gid[k], k);
  std::vector<char> seen(ps.size(), 0);
  for (const auto& r : parseNumberTable(t.particles, path, 1 + ps.nAlter)) {
    const Gid id = static_cast<Gid>(r.values[0]);
    auto it = index.find(id);
    if (it == index.end() || static_cast<double>(id) != r.values[0])
      throw InputError(path, r.line, "particle " + std::to_string(id) + " is not in the problem");
    if (seen[it->second]++)
      throw InputError(path, r.line, "duplicate global ID " + std::to_string(id));
    std::copy(r.values.begin() + 1, r.values.end(), ps.alterRow(it->second));
  }
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (!seen[k])
      throw InputError(path, 0, "particle " + std::to_string(ps.gid[k]) + " is missing");
  pb.run.firstStep = step;
  if (pb.run.steps >= 0 && step > pb.run.steps) {
    std::ostringstream os;
    os << "the restart is at step " << step << ", beyond the run's last step " << pb.run.steps;
    throw InputError(path, 1, os.str());
  }
  RestartState bonds;
  const std::string& spath = names.state;
  long bondCount = -1;
  if (t.state) readState(*t.state, spath, bonds, bondCount);
  const std::string& fpath = names.fixed;
  if (t.fixed)
    for (const auto& r : parseNumberTable(*t.fixed, fpath, 1 + ps.nFixed)) {
      auto it = index.find(static_cast<Gid>(r.values[0]));
      if (it == index.end())
        throw InputError(fpath, r.line, "a particle that is not in the problem");
      std::copy(r.values.begin() + 1, r.values.end(), ps.fixedRow(it->second));
    }
  const std::string& bpath = names.bonds;
  if (!t.bonds && !t.bondRows) {
    if (bondCount > 0)
      throw InputError(
          bpath, 0,
          "missing: " + spath + " says the state has " + std::to_string(bondCount) + " bonds");
    return bonds;
  }
  const int nB = schema.nBond(), width = 3 + nB;
  // Each bond's row (owner, partner, dead, attributes) and where it was read: its line in
  // the text, or its row (from 1) in a checkpoint's binary rows (read in place).
  std::vector<double> rows;
  std::vector<int> lines;
  const double* data = nullptr;
  std::size_t nRows = 0;
  if (t.bondRows) {
    if (t.bondRows->size() % width != 0)
      throw InputError(bpath, 0,
                       "damaged: " + std::to_string(t.bondRows->size()) + " numbers, not rows of " +
                           std::to_string(width));
    data = t.bondRows->data();
    nRows = t.bondRows->size() / width;
  } else {
    const std::string first = t.bonds->substr(0, t.bonds->find('\n'));
    const std::string tag = "# pdq bonds: step " + std::to_string(step);
    if (first != tag)
      throw InputError(
          bpath, 1, "not the bonds of step " + std::to_string(step) + " (expected '" + tag + "')");
    for (const auto& r : parseNumberTable(*t.bonds, bpath, width)) {
      rows.insert(rows.end(), r.values.begin(), r.values.end());
      lines.push_back(r.line);
    }
    data = rows.data();
    nRows = lines.size();
  }
  auto lineOf = [&](std::size_t r) { return lines.empty() ? static_cast<int>(r + 1) : lines[r]; };
  // The particle (its index in the problem) of an ID.
  auto particle = [&](double v, int line, const char* what) {
    const Gid g = static_cast<Gid>(v);
    const auto it = static_cast<double>(g) == v ? index.find(g) : index.end();
    if (it == index.end())
      throw InputError(
          bpath, line,
          std::string(what) + " " + numberText(v) + " is not a particle of the problem");
    return it->second;
  };
  // The bonds grouped by owner (a counting sort), each owner's by partner ID then line: a
  // bond listed twice is next to itself, and its partner's own list is searched for the
  // bond back. Of several faults, the one with the smallest owner and partner IDs is told.
  std::vector<std::size_t> ownerOf(nRows), start(ps.size() + 1, 0);
  struct Entry {
    Gid partner;
    int line;
  };
  bonds.owner.reserve(nRows);
  bonds.partner.reserve(nRows);
  bonds.dead.reserve(nRows);
  bonds.attrs.reserve(nRows * static_cast<std::size_t>(nB));
  for (std::size_t r = 0; r < nRows; ++r) {
    const double* v = data + r * width;
    const int line = lineOf(r);
    const std::size_t o = particle(v[0], line, "owner");
    particle(v[1], line, "partner");
    const Gid owner = static_cast<Gid>(v[0]), partner = static_cast<Gid>(v[1]);
    if (owner == partner)
      throw InputError(bpath, line, "particle " + std::to_string(owner) + " is bonded to itself");
    if (v[2] != 0 && v[2] != 1)
      throw InputError(bpath, line, "the dead flag is " + numberText(v[2]) + "; it must be 0 or 1");
    ownerOf[r] = o;
    ++start[o + 1];
    bonds.owner.push_back(owner);
    bonds.partner.push_back(partner);
    bonds.dead.push_back(v[2] != 0 ? 1 : 0);
    bonds.attrs.insert(bonds.attrs.end(), v + 3, v + width);
  }
  for (std::size_t k = 0; k < ps.size(); ++k) start[k + 1] += start[k];
  std::vector<Entry> byOwner(nRows);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t r = 0; r < nRows; ++r)
      byOwner[next[ownerOf[r]]++] = {bonds.partner[r], lineOf(r)};
  }
  auto before = [](const Entry& a, const Entry& b) {
    return a.partner != b.partner ? a.partner < b.partner : a.line < b.line;
  };
  for (std::size_t k = 0; k < ps.size(); ++k)
    std::sort(byOwner.begin() + start[k], byOwner.begin() + start[k + 1], before);
  struct Fault {
    Gid owner = 0, partner = 0;
    int line = 0;
    bool found = false;
    void offer(Gid o, Gid p, int l) {
      if (!found || o < owner || (o == owner && (p < partner || (p == partner && l < line))))
        *this = {o, p, l, true};
    }
  };
  Fault twice;
  for (std::size_t k = 0; k < ps.size(); ++k)
    for (std::size_t e = start[k] + 1; e < start[k + 1]; ++e)
      if (byOwner[e].partner == byOwner[e - 1].partner)
        twice.offer(ps.gid[k], byOwner[e].partner, byOwner[e].line);
  if (twice.found)
    throw InputError(bpath, twice.line,
                     "the bond " + std::to_string(twice.owner) + "-" +
                         std::to_string(twice.partner) + " is listed twice");
  if (bondCount >= 0 && static_cast<long>(bonds.owner.size()) != bondCount)
    throw InputError(bpath, 0,
                     "has " + std::to_string(bonds.owner.size()) + " bonds but " + spath +
                         " says " + std::to_string(bondCount) + " (cut short?)");
  // Every bond is held by both of its particles.
  Fault oneSided;
  for (std::size_t k = 0; k < ps.size(); ++k)
    for (std::size_t e = start[k]; e < start[k + 1]; ++e) {
      const std::size_t p = index.find(byOwner[e].partner)->second;
      if (!std::binary_search(byOwner.begin() + start[p], byOwner.begin() + start[p + 1],
                              Entry{ps.gid[k], 0},
                              [](const Entry& a, const Entry& b) { return a.partner < b.partner; }))
        oneSided.offer(ps.gid[k], byOwner[e].partner, byOwner[e].line);
    }
  if (oneSided.found)
    throw InputError(bpath, oneSided.line,
                     "the bond " + std::to_string(oneSided.owner) + "-" +
                         std::to_string(oneSided.partner) + " has no partner line " +
                         std::to_string(oneSided.partner) + " " + std::to_string(oneSided.owner) +
                         " (one-sided)");
  return bonds;
}

}  // namespace pdq
