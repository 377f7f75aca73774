#include "io/vtu_output.hpp"

#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <unordered_map>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"

namespace pdq {
namespace {

std::string stepTag(long step) {
  std::ostringstream os;
  os << std::setw(6) << std::setfill('0') << step;
  return os.str();
}

vtu::Array idArray(const Particles& P, const std::vector<std::size_t>& rows) {
  vtu::Array a{"id", 1, true, {}, {}};
  for (std::size_t i : rows) a.i64.push_back(P.gid(i));
  return a;
}

vtu::Array displacementArray(const Particles& P, const std::vector<std::size_t>& rows) {
  vtu::Array a{"displacement", 3, false, {}, {}};
  for (std::size_t i : rows)
    for (int d = 0; d < 3; ++d) a.f64.push_back(P.alter(i)[d] - P.fixed(i)[d]);
  return a;
}

// Reads the entries of an earlier run's .pvd (a restarted run continues its series),
// keeping those before `step`; our own files name their step as <stem>_<step>.pvtu.
void loadSeries(const std::string& path, long step, std::vector<vtu::SeriesEntry>& entries,
                std::vector<long>& steps) {
  std::ifstream in(path);
  if (!in) return;
  const std::regex re(R"re(timestep="([^"]*)".*file="([^"]*_([0-9]+)\.pvtu)")re");
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (!std::regex_search(line, m, re)) continue;
    long s = 0;
    const std::string digits = m[3];
    const auto [end, err] = std::from_chars(digits.data(), digits.data() + digits.size(), s);
    if (err != std::errc() || s >= step) continue;
    entries.push_back({std::strtod(m.str(1).c_str(), nullptr), m[2]});
    steps.push_back(s);
  }
}

}  // namespace

vtu::Piece particlePiece(const Context& ctx, const Model& model) {
  const Particles& P = ctx.particles;
  const Schema& S = P.schema();
  const std::size_t n = P.owned();
  std::vector<std::size_t> rows(n);
  vtu::Piece piece;
  piece.points.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    rows[i] = i;
    piece.points.insert(piece.points.end(), P.alter(i), P.alter(i) + 3);
    piece.addCell(vtu::Vertex, {static_cast<std::int64_t>(i)});
  }
  piece.pointData.push_back(idArray(P, rows));
  piece.pointData.push_back(displacementArray(P, rows));
  auto column = [&](const std::string& name, auto get) {
    vtu::Array a{name, 1, false, {}, {}};
    a.f64.resize(n);
    for (std::size_t i = 0; i < n; ++i) a.f64[i] = get(i);
    piece.pointData.push_back(std::move(a));
  };
  for (int k = 3; k < S.nFixed(); ++k)
    column(S.fixed[k], [&](std::size_t i) { return P.fixed(i)[k]; });
  for (int k = 3; k < S.nAlter(); ++k)
    column(S.alter[k], [&](std::size_t i) { return P.alter(i)[k]; });
  const std::vector<std::string> fields = model.fields();
  for (int k = 0; k < static_cast<int>(fields.size()); ++k) {
    vtu::Array a{fields[k], 1, false, std::vector<double>(n, 0.0), {}};
    model.field(ctx, k, std::span<double>(a.f64));
    piece.pointData.push_back(std::move(a));
  }
  // A model with turns in space names its rotation vector's components rx, ry, rz; they
  // are also written as one vector, for ParaView's glyphs and its magnitude.
  auto field = [&](const std::string& name) -> const vtu::Array* {
    for (const vtu::Array& a : piece.pointData)
      if (a.name == name) return &a;
    return nullptr;
  };
  if (const vtu::Array* x = field("rx"), *y = field("ry"), *z = field("rz"); x && y && z) {
    vtu::Array r{"rotation", 3, false, {}, {}};
    r.f64.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      r.f64.insert(r.f64.end(), {x->f64[i], y->f64[i], z->f64[i]});
    piece.pointData.push_back(std::move(r));
  }
  return piece;
}

vtu::Piece bondPiece(const Context& ctx) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  const std::size_t n = P.owned();
  // Points: the owned particles, then each ghost that ends a written bond, once.
  std::vector<std::size_t> rows(n);
  for (std::size_t i = 0; i < n; ++i) rows[i] = i;
  std::unordered_map<std::size_t, std::int64_t> ghostPoint;
  vtu::Piece piece;
  // Cell data: the engine's broken flag, then the model's bond attributes.
  std::vector<vtu::Array> attrs(B.nAttr() + 1);
  attrs[0] = {"broken", 1, false, {}, {}};
  for (int k = 0; k < B.nAttr(); ++k) attrs[k + 1] = {P.schema().bond[k], 1, false, {}, {}};
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      if (B.partnerGid(b) < P.gid(i)) continue;  // the other end writes it
      if (B.partner(b) < 0) continue;            // broken, and the partner has gone
      const std::size_t j = static_cast<std::size_t>(B.partner(b));
      std::int64_t pj = static_cast<std::int64_t>(j);
      if (j >= n) {
        auto [it, fresh] = ghostPoint.try_emplace(j, static_cast<std::int64_t>(rows.size()));
        if (fresh) rows.push_back(j);
        pj = it->second;
      }
      piece.addCell(vtu::Line, {static_cast<std::int64_t>(i), pj});
      attrs[0].f64.push_back(B.alive(b) ? 0.0 : 1.0);
      for (int k = 0; k < B.nAttr(); ++k) attrs[k + 1].f64.push_back(B.attr(b)[k]);
    }
  piece.points.reserve(3 * rows.size());
  for (std::size_t i : rows) piece.points.insert(piece.points.end(), P.alter(i), P.alter(i) + 3);
  piece.pointData.push_back(idArray(P, rows));
  piece.pointData.push_back(displacementArray(P, rows));
  piece.cellData = std::move(attrs);
  return piece;
}

VtuOptions vtuOptions(const Params& t) {
  VtuOptions o;
  o.every = t.integer("every", o.every);
  if (o.every < 0) {
    const auto v = t.raw("every");
    throw InputError(v->file, v->line, "every must be 0 or more steps");
  }
  o.atEnd = t.flag("at_end", o.atEnd);
  o.bonds = t.flag("bonds", o.bonds);
  o.name = t.text("name", o.name);
  return o;
}

VtuOutput::VtuOutput(VtuOptions options) : Output(options.every), opt_(std::move(options)) {
  particles_.name = opt_.name;
  bonds_.name = opt_.name + "_bonds";
}

void VtuOutput::write(OutputContext& out) {
  writeStep(out, particles_, particlePiece(out.ctx, out.model));
  if (opt_.bonds) writeStep(out, bonds_, bondPiece(out.ctx));
}

void VtuOutput::writeStep(OutputContext& out, Series& series, const vtu::Piece& piece) {
  const std::string dir = out.outDir + "/" + opt_.name;
  const std::string stem = series.name + "_" + stepTag(out.step);
  createFolder(dir);
  const std::string pieceFile = stem + "_" + std::to_string(out.comm.rank()) + ".vtu";
  {
    AtomicFile f(dir + "/" + pieceFile);
    vtu::writePiece(f.stream(), piece);
    f.commit();
  }
  // The step's header and the series name only complete pieces.
  out.comm.barrier();
  if (!out.comm.root()) return;
  std::vector<std::string> files;
  for (int r = 0; r < out.comm.size(); ++r)
    files.push_back(stem + "_" + std::to_string(r) + ".vtu");
  writeFileAtomically(dir + "/" + stem + ".pvtu", vtu::encodeParallel(piece, files));

  const std::string pvd = out.outDir + "/" + series.name + ".pvd";
  if (!series.loaded) {
    loadSeries(pvd, out.step, series.entries, series.steps);
    series.loaded = true;
  }
  const vtu::SeriesEntry entry{static_cast<double>(out.step) * out.ctx.dt(),
                               opt_.name + "/" + stem + ".pvtu"};
  if (!series.steps.empty() && series.steps.back() == out.step) {
    series.entries.back() = entry;
  } else {
    series.entries.push_back(entry);
    series.steps.push_back(out.step);
  }
  writeFileAtomically(pvd, vtu::encodeSeries(series.entries));
}

}  // namespace pdq
