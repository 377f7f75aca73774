#include "post/snapshot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

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

std::string damageName(const PictureRequest& r, const std::vector<std::string>& bondNames) {
  if (r.bondDamage == "none") return "";
  if (!r.bondDamage.empty()) return r.bondDamage;
  // A model's own damage measure if it has one, else the engine's broken-bond flag.
  return std::find(bondNames.begin(), bondNames.end(), "damage") != bondNames.end() ? "damage"
                                                                                    : "broken";
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

  // Fixed-size records: a particle is its ID then 6 + nq doubles (X, x, quantities); a
  // bond is its two IDs, the far end's position as this rank sees it, its attributes.
  // The first bond attribute is the engine's broken flag; bonds whose dead partner has
  // left the procCube are not drawn.
  const std::size_t pRec = 8 * (7 + nq), bRec = 8 * (6 + nB);
  auto written = [&](std::size_t i, std::size_t b) {
    return B.partnerGid(b) > P.gid(i) && B.partner(b) >= 0;
  };
  std::uint64_t nb = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) nb += written(i, b);
  Writer w;
  w.bytes.reserve(16 + n * pRec + nb * bRec);
  w.put<std::uint64_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    w.put(P.gid(i));
    w.put(P.fixed(i), 3);
    w.put(P.alter(i), 3);
    w.put(P.fixed(i) + 3, S.nFixed() - 3);
    w.put(P.alter(i) + 3, S.nAlter() - 3);
    for (const auto& f : fieldValues) w.put(f[i]);
  }
  w.put(nb);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      if (!written(i, b)) continue;
      w.put(P.gid(i));
      w.put(B.partnerGid(b));
      w.put(P.alter(B.partner(b)), 3);
      w.put(B.alive(b) ? 0.0 : 1.0);
      w.put(B.attr(b), nB);
    }
  const auto blocks = comm.gather(w.bytes);

  Snapshot s;
  s.step = step;
  s.time = static_cast<double>(step) * ctx.dt();
  if (!comm.root()) return s;
  s.names = names;
  s.bondNames = {"broken"};
  s.bondNames.insert(s.bondNames.end(), S.bond.begin(), S.bond.end());
  // The records are read in place, ordered through pointers.
  std::vector<const char*> prt, bnd;
  for (const auto& block : blocks) {
    const char* at = block.data();
    auto count = [&] {
      std::uint64_t c;
      std::memcpy(&c, at, 8);
      at += 8;
      return c;
    };
    for (std::uint64_t k = count(); k > 0; --k, at += pRec) prt.push_back(at);
    for (std::uint64_t k = count(); k > 0; --k, at += bRec) bnd.push_back(at);
  }
  auto word = [](const char* rec, int k, auto v) {
    std::memcpy(&v, rec + 8 * k, 8);
    return v;
  };
  auto gid = [&](const char* rec, int k) { return word(rec, k, Gid{}); };
  std::sort(prt.begin(), prt.end(),
            [&](const char* a, const char* b) { return gid(a, 0) < gid(b, 0); });
  const std::size_t N = prt.size();
  s.id.resize(N);
  s.reference.resize(3 * N);
  s.current.resize(3 * N);
  s.values.assign(nq, std::vector<double>(N));
  for (std::size_t i = 0; i < N; ++i) {
    s.id[i] = gid(prt[i], 0);
    for (int d = 0; d < 3; ++d) {
      s.reference[3 * i + d] = word(prt[i], 1 + d, 0.0);
      s.current[3 * i + d] = word(prt[i], 4 + d, 0.0);
    }
    for (int k = 0; k < nq; ++k) s.values[k][i] = word(prt[i], 7 + k, 0.0);
  }
  std::sort(bnd.begin(), bnd.end(), [&](const char* a, const char* b) {
    return std::pair(gid(a, 0), gid(a, 1)) < std::pair(gid(b, 0), gid(b, 1));
  });
  auto index = [&](Gid g) {
    return static_cast<std::size_t>(std::lower_bound(s.id.begin(), s.id.end(), g) - s.id.begin());
  };
  s.bonds.reserve(bnd.size());
  s.bondAttrs.reserve(bnd.size() * (nB + 1));
  for (const char* rec : bnd) {
    const std::size_t a = index(gid(rec, 0)), b = index(gid(rec, 1));
    bool image = false;  // the far end is a periodic image, not where the particle is
    for (int d = 0; d < 3; ++d) image |= word(rec, 2 + d, 0.0) != s.current[3 * b + d];
    if (image) continue;
    s.bonds.push_back({a, b});
    for (int k = 0; k <= nB; ++k) s.bondAttrs.push_back(word(rec, 5 + k, 0.0));
  }
  return s;
}

void sortParticles(Snapshot& s) {
  const std::size_t n = s.particles();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return s.id[a] < s.id[b]; });
  auto permute = [&](auto& v, std::size_t width) {
    auto old = v;
    for (std::size_t i = 0; i < n; ++i) std::copy_n(&old[width * order[i]], width, &v[width * i]);
  };
  permute(s.id, 1);
  permute(s.reference, 3);
  permute(s.current, 3);
  for (auto& v : s.values) permute(v, 1);
}

void addBonds(Snapshot& s, const std::vector<Gid>& owner, const std::vector<Gid>& partner,
              const std::vector<double>& attrs, const std::string& source) {
  const std::size_t nB = s.bondNames.size();
  auto index = [&](Gid g) {
    const auto it = std::lower_bound(s.id.begin(), s.id.end(), g);
    if (it == s.id.end() || *it != g)
      throw InputError(
          source, 0,
          "a bond names particle " + std::to_string(g) + ", which is not among the particles");
    return static_cast<std::size_t>(it - s.id.begin());
  };
  std::vector<std::size_t> listed;  // bonds listed from their smaller ID's end
  for (std::size_t k = 0; k < owner.size(); ++k) {
    index(owner[k]);  // both ends must be particles
    index(partner[k]);
    if (owner[k] < partner[k]) listed.push_back(k);
  }
  // A bond listed only from its larger ID's end is kept from there.
  std::vector<std::pair<Gid, Gid>> have;
  for (std::size_t k : listed) have.emplace_back(owner[k], partner[k]);
  std::sort(have.begin(), have.end());
  for (std::size_t k = 0; k < owner.size(); ++k)
    if (owner[k] > partner[k] &&
        !std::binary_search(have.begin(), have.end(), std::pair(partner[k], owner[k])))
      listed.push_back(k);
  auto ends = [&](std::size_t k) { return std::minmax(owner[k], partner[k]); };
  std::sort(listed.begin(), listed.end(),
            [&](std::size_t a, std::size_t b) { return ends(a) < ends(b); });
  for (std::size_t k : listed) {
    const auto [a, b] = ends(k);
    s.bonds.push_back({index(a), index(b)});
    s.bondAttrs.insert(s.bondAttrs.end(), attrs.begin() + k * nB, attrs.begin() + (k + 1) * nB);
  }
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
    throw InputError(r.bondDamageSource, r.bondDamageLine,
                     "no bond attribute '" + d + "' to draw as damage" + suggestion(d, bondNames));
}

Slab parseSlab(const std::string& text, const std::string& file, int line) {
  auto bad = [&](const std::string& why) {
    throw InputError(file, line,
                     "slab '" + text + "': " + why +
                         " (give an axis and a range of its reference coordinate, such as "
                         "z=0.05:0.11)");
  };
  const auto eq = text.find('='), colon = text.find(':');
  if (eq == std::string::npos || colon == std::string::npos || colon < eq) bad("no axis=lo:hi");
  const std::string axis = text.substr(0, eq);
  Slab slab;
  if (axis == "x" || axis == "X")
    slab.axis = 0;
  else if (axis == "y" || axis == "Y")
    slab.axis = 1;
  else if (axis == "z" || axis == "Z")
    slab.axis = 2;
  else
    bad("the axis must be x, y or z");
  auto number = [&](const std::string& t) {
    std::size_t used = 0;
    double v = NAN;
    try {
      v = std::stod(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (t.empty() || used != t.size() || !std::isfinite(v)) bad("'" + t + "' is not a number");
    return v;
  };
  slab.lo = number(text.substr(eq + 1, colon - eq - 1));
  slab.hi = number(text.substr(colon + 1));
  if (!(slab.lo < slab.hi)) bad("the range is empty (lo must be below hi)");
  return slab;
}

void emptySlab(const PictureRequest& r, double lo, double hi) {
  const char name = static_cast<char>('x' + r.slab.axis);
  throw InputError(r.slabSource, r.slabLine,
                   fmt::format("the slab {}={}:{} holds no particle (the particles' reference {} "
                               "runs from {:.6g} to {:.6g})",
                               name, r.slab.lo, r.slab.hi, name, lo, hi));
}

LatticeImage latticeImage(const Snapshot& s, const PictureRequest& r) {
  checkRequest(r, s.names, s.bondNames);
  LatticeImage im;
  // The particles drawn (those in the slab) and their places in the image.
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> kept, place(s.particles(), none);
  for (std::size_t i = 0; i < s.particles(); ++i)
    if (r.slab.contains(&s.reference[3 * i])) {
      place[i] = kept.size();
      kept.push_back(i);
    }
  if (kept.empty() && r.slab.axis >= 0) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < s.particles(); ++i) {
      lo = std::min(lo, s.reference[3 * i + r.slab.axis]);
      hi = std::max(hi, s.reference[3 * i + r.slab.axis]);
    }
    emptySlab(r, lo, hi);
  }
  const std::size_t n = kept.size();
  for (std::size_t i : kept)
    for (int a = 0; a < 3; ++a) {
      im.position.push_back(s.reference[3 * i + a]);
      im.displacement.push_back(s.current[3 * i + a] - s.reference[3 * i + a]);
    }
  if (r.colourBy == "displacement") {
    im.values.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      im.values[i] = std::hypot(im.displacement[3 * i], im.displacement[3 * i + 1],
                                im.displacement[3 * i + 2]);
  } else if (!r.colourBy.empty()) {
    const auto k = std::find(s.names.begin(), s.names.end(), r.colourBy) - s.names.begin();
    for (std::size_t i : kept) im.values.push_back(s.values[k][i]);
  }
  im.valueName = r.colourBy;
  const std::string d = damageName(r, s.bondNames);
  if (!d.empty()) {
    const std::size_t nb = s.bondNames.size();
    const auto k = std::find(s.bondNames.begin(), s.bondNames.end(), d) - s.bondNames.begin();
    for (std::size_t b = 0; b < s.bonds.size(); ++b) {
      const std::size_t i = place[s.bonds[b][0]], j = place[s.bonds[b][1]];
      if (i == none || j == none) continue;
      im.bonds.push_back({i, j});
      im.bondDamage.push_back(s.bondAttrs[b * nb + k]);
    }
  }
  return im;
}

void renderSnapshot(const Snapshot& s, const PictureRequest& r, const std::string& path) {
  renderLattice(latticeImage(s, r), r.style, path);
}

}  // namespace pdq::post
