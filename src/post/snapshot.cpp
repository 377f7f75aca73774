#include "post/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <unordered_map>

#include "engine/error.hpp"
#include "engine/model.hpp"

namespace pdq::post {
namespace {

class Writer {
 public:
  template <class T>
  void put(const T* v, std::size_t n) {
    const auto* p = reinterpret_cast<const char*>(v);
    bytes.insert(bytes.end(), p, p + n * sizeof(T));
  }
  template <class T>
  void put(T v) {
    put(&v, 1);
  }
  std::vector<char> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& b) : b_(b) {}
  template <class T>
  void get(T* v, std::size_t n) {
    std::memcpy(v, &b_[at_], n * sizeof(T));
    at_ += n * sizeof(T);
  }
  template <class T>
  T get() {
    T v;
    get(&v, 1);
    return v;
  }

 private:
  const std::vector<char>& b_;
  std::size_t at_ = 0;
};

std::string damageName(const PictureRequest& r, const std::vector<std::string>& bondNames) {
  if (r.bondDamage == "none") return "";
  if (!r.bondDamage.empty()) return r.bondDamage;
  return std::find(bondNames.begin(), bondNames.end(), "damage") != bondNames.end() ? "damage" : "";
}

}  // namespace

std::vector<std::string> quantityNames(const Schema& s, const Model& model) {
  std::vector<std::string> names(s.fixed.begin() + 3, s.fixed.end());
  names.insert(names.end(), s.alter.begin() + 3, s.alter.end());
  for (const std::string& f : model.fields()) names.push_back(f);
  return names;
}

Snapshot gatherSnapshot(const Context& ctx, const Model& model, const Comm& comm, long step) {
  const Particles& P = ctx.particles;
  const Bonds& B = ctx.bonds;
  const Schema& S = P.schema();
  const std::size_t n = P.owned();
  const std::vector<std::string> names = quantityNames(S, model);
  const int nq = static_cast<int>(names.size()), nB = B.nAttr();

  // The model's fields of the owned particles, field by field.
  const std::vector<std::string> fields = model.fields();
  std::vector<std::vector<double>> fieldValues(fields.size(), std::vector<double>(n));
  for (std::size_t k = 0; k < fields.size(); ++k)
    model.field(ctx, static_cast<int>(k), std::span<double>(fieldValues[k]));

  Writer w;
  w.put<std::uint64_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    w.put(P.gid(i));
    w.put(P.fixed(i), 3);
    w.put(P.alter(i), 3);
    w.put(P.fixed(i) + 3, S.nFixed() - 3);
    w.put(P.alter(i) + 3, S.nAlter() - 3);
    for (const auto& f : fieldValues) w.put(f[i]);
  }
  std::uint64_t nb = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) nb += B.partnerGid(b) > P.gid(i);
  w.put(nb);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      if (B.partnerGid(b) < P.gid(i)) continue;
      w.put(P.gid(i));
      w.put(B.partnerGid(b));
      w.put(P.alter(B.partner(b)), 3);  // where this rank sees the far end
      w.put(B.attr(b), nB);
    }
  const auto blocks = comm.gather(w.bytes);

  Snapshot s;
  s.step = step;
  s.time = static_cast<double>(step) * ctx.dt();
  if (!comm.root()) return s;
  s.names = names;
  s.bondNames = S.bond;
  struct Row {
    Gid id;
    std::vector<double> v;  // X(3) x(3) quantities
  };
  std::vector<Row> rows;
  struct BondRow {
    Gid a, b;
    double far[3];
    std::vector<double> attrs;
  };
  std::vector<BondRow> bonds;
  for (const auto& block : blocks) {
    Reader r(block);
    const auto np = r.get<std::uint64_t>();
    for (std::uint64_t k = 0; k < np; ++k) {
      Row row{r.get<Gid>(), std::vector<double>(6 + nq)};
      r.get(row.v.data(), row.v.size());
      rows.push_back(std::move(row));
    }
    const auto nbk = r.get<std::uint64_t>();
    for (std::uint64_t k = 0; k < nbk; ++k) {
      BondRow br{r.get<Gid>(), r.get<Gid>(), {}, std::vector<double>(nB)};
      r.get(br.far, 3);
      r.get(br.attrs.data(), nB);
      bonds.push_back(std::move(br));
    }
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.id < b.id; });
  const std::size_t N = rows.size();
  s.values.assign(nq, std::vector<double>(N));
  std::unordered_map<Gid, std::size_t> index;
  for (std::size_t i = 0; i < N; ++i) {
    s.id.push_back(rows[i].id);
    s.reference.insert(s.reference.end(), rows[i].v.begin(), rows[i].v.begin() + 3);
    s.current.insert(s.current.end(), rows[i].v.begin() + 3, rows[i].v.begin() + 6);
    for (int k = 0; k < nq; ++k) s.values[k][i] = rows[i].v[6 + k];
    index[rows[i].id] = i;
  }
  std::sort(bonds.begin(), bonds.end(), [](const BondRow& x, const BondRow& y) {
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  for (const BondRow& br : bonds) {
    const std::size_t a = index.at(br.a), b = index.at(br.b);
    if (!std::equal(br.far, br.far + 3, &s.current[3 * b])) continue;  // a periodic image
    s.bonds.push_back({a, b});
    s.bondAttrs.insert(s.bondAttrs.end(), br.attrs.begin(), br.attrs.end());
  }
  return s;
}

void checkRequest(const PictureRequest& r, const std::vector<std::string>& names,
                  const std::vector<std::string>& bondNames) {
  if (!r.colourBy.empty() && r.colourBy != "displacement" &&
      std::find(names.begin(), names.end(), r.colourBy) == names.end()) {
    std::vector<std::string> all = names;
    all.push_back("displacement");
    throw InputError(
        r.source, r.colourByLine,
        "cannot colour by '" + r.colourBy + "': no such quantity" + suggestion(r.colourBy, all));
  }
  const std::string d = damageName(r, bondNames);
  if (!d.empty() && std::find(bondNames.begin(), bondNames.end(), d) == bondNames.end())
    throw InputError(r.source, r.bondDamageLine,
                     "no bond attribute '" + d + "' to draw as damage" + suggestion(d, bondNames));
}

LatticeImage latticeImage(const Snapshot& s, const PictureRequest& r) {
  checkRequest(r, s.names, s.bondNames);
  LatticeImage im;
  const std::size_t n = s.particles();
  im.position = s.reference;
  im.displacement.resize(3 * n);
  for (std::size_t k = 0; k < 3 * n; ++k) im.displacement[k] = s.current[k] - s.reference[k];
  if (r.colourBy == "displacement") {
    im.values.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      im.values[i] = std::hypot(im.displacement[3 * i], im.displacement[3 * i + 1],
                                im.displacement[3 * i + 2]);
  } else if (!r.colourBy.empty()) {
    const auto k = std::find(s.names.begin(), s.names.end(), r.colourBy) - s.names.begin();
    im.values = s.values[k];
  }
  im.valueName = r.colourBy;
  const std::string d = damageName(r, s.bondNames);
  if (!d.empty()) {
    const std::size_t nb = s.bondNames.size();
    const auto k = std::find(s.bondNames.begin(), s.bondNames.end(), d) - s.bondNames.begin();
    im.bonds = s.bonds;
    for (std::size_t b = 0; b < s.bonds.size(); ++b)
      im.bondDamage.push_back(s.bondAttrs[b * nb + k]);
  }
  return im;
}

void renderSnapshot(const Snapshot& s, const PictureRequest& r, const std::string& path) {
  renderLattice(latticeImage(s, r), r.style, path);
}

}  // namespace pdq::post
