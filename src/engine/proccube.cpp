#include "engine/proccube.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "engine/error.hpp"

namespace pdq {

namespace {

constexpr int kTagBorder = 11, kTagHalo = 12, kTagMigrate = 13, kTagScratch = 14;

void putGid(std::vector<char>& buf, Gid g) {
  const char* c = reinterpret_cast<const char*>(&g);
  buf.insert(buf.end(), c, c + sizeof g);
}
template <class T>
void put(std::vector<char>& buf, const T* v, std::size_t n) {
  const char* c = reinterpret_cast<const char*>(v);
  buf.insert(buf.end(), c, c + n * sizeof(T));
}
template <class T>
void get(const char*& c, T* v, std::size_t n) {
  std::memcpy(v, c, n * sizeof(T));
  c += n * sizeof(T);
}

}  // namespace

ProcCube::ProcCube(const Decomposition& dec, Comm& comm, Particles& particles, Bonds& bonds,
                   bool binByCurrentPosition)
    : dec_(dec), comm_(comm), p_(particles), bonds_(bonds), byCurrent_(binByCurrentPosition) {
  for (int a = 0; a < 3; ++a) {
    skin_[a] = dec_.active(a) ? dec_.divisions() : 0;
    ext_[a] = dec_.coreCells(a) + 2 * skin_[a];
  }
  // Cells are laid out with the axis of most cells slowest (Z, Y, X on ties): a particle's
  // neighbours then sit closest in memory (a long member's X-neighbours a cross-section of
  // cells away, not a plane of the whole length).
  std::array<int, 3> axes{2, 1, 0};
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return ext_[a] > ext_[b]; });
  int stride = 1;
  for (int k = 2; k >= 0; --k) {
    stride_[axes[k]] = stride;
    stride *= ext_[axes[k]];
  }
  for (int dz = -skin_[2]; dz <= skin_[2]; ++dz)
    for (int dy = -skin_[1]; dy <= skin_[1]; ++dy)
      for (int dx = -skin_[0]; dx <= skin_[0]; ++dx)
        stencil_.push_back(dz * stride_[2] + dy * stride_[1] + dx * stride_[0]);
  memoryStencil_ = stencil_;
  std::sort(memoryStencil_.begin(), memoryStencil_.end());
}

const double* ProcCube::binPosition(std::size_t i) const {
  return byCurrent_ ? p_.alter(i) : p_.fixed(i);
}

std::array<int, 3> ProcCube::globalCellOfPosition(const double* pos) const {
  return {dec_.globalCell(0, pos[0]), dec_.globalCell(1, pos[1]), dec_.globalCell(2, pos[2])};
}

int ProcCube::localCell(const std::array<int, 3>& g) const {
  int l[3];
  for (int a = 0; a < 3; ++a) l[a] = g[a] - dec_.coreLo(a) + skin_[a];
  return l[2] * stride_[2] + l[1] * stride_[1] + l[0] * stride_[0];
}

void ProcCube::distribute(const std::vector<Gid>& gid, const std::vector<double>& fixed,
                          const std::vector<double>& alter) {
  const int nF = p_.schema().nFixed(), nA = p_.schema().nAlter();
  const Domain& dom = dec_.domain();
  p_.clear();
  std::vector<double> f(nF), x(nA);
  for (std::size_t k = 0; k < gid.size(); ++k) {
    std::copy_n(&fixed[k * nF], nF, f.begin());
    std::copy_n(&alter[k * nA], nA, x.begin());
    // Bring periodic coordinates into the box; reference and current positions move
    // together so the displacement is unchanged.
    bool mine = true;
    for (int a = 0; a < dec_.dim(); ++a) {
      double* b = byCurrent_ ? &x[a] : &f[a];
      if (dom.periodic[a]) {
        const double L = dom.length(a);
        while (*b >= dom.hi[a]) f[a] -= L, x[a] -= L;
        while (*b < dom.lo[a]) f[a] += L, x[a] += L;
      }
      const int g = std::clamp(dec_.globalCell(a, *b), 0, dec_.globalCells(a) - 1);
      mine &= dec_.ownerCoord(a, g) == dec_.coord(a);
    }
    if (mine) p_.append(gid[k], f.data(), x.data());
  }
  p_.setOwned(p_.local());
  bonds_.resetEmpty(p_.owned());
  rebuildPos_.clear();
}

void ProcCube::rebuild(long step) {
  const std::size_t n = p_.owned();
  p_.truncate(n);
  gcell_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    gcell_[i] = globalCellOfPosition(binPosition(i));
    for (int a = 0; a < dec_.dim(); ++a)
      gcell_[i][a] = std::clamp(gcell_[i][a], dec_.coreLo(a), dec_.coreHi(a) - 1);
  }
  // Owned particles in (cell, global ID) order: a cell's particles are contiguous and
  // visited in ID order.
  std::vector<std::size_t> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  std::vector<int> key(n);
  for (std::size_t i = 0; i < n; ++i) key[i] = localCell(gcell_[i]);
  std::sort(perm.begin(), perm.end(), [&](std::size_t a, std::size_t b) {
    return key[a] != key[b] ? key[a] < key[b] : p_.gid(a) < p_.gid(b);
  });
  bool identity = true;
  for (std::size_t k = 0; k < n && identity; ++k) identity = perm[k] == k;
  if (!identity) {
    p_.permute(perm);
    bonds_.permute(perm);
    std::vector<std::array<int, 3>> g(n);
    for (std::size_t k = 0; k < n; ++k) g[k] = gcell_[perm[k]];
    gcell_ = std::move(g);
  }
  borderPass();
  buildCellLists();
  remapBonds(step);
  rebuildPos_.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) std::copy_n(p_.alter(i), 3, &rebuildPos_[3 * i]);
}

void ProcCube::borderPass() {
  const int nF = p_.schema().nFixed(), nA = p_.schema().nAlter();
  const Domain& dom = dec_.domain();
  const std::uint64_t m0 = comm_.messages(), b0 = comm_.bytes();
  dirs_.clear();
  std::vector<char> out, in;
  std::vector<double> f(nF), x(nA);
  for (int a = 0; a < dec_.dim(); ++a) {
    for (int dir : {+1, -1}) {
      Direction d{a, dir, dec_.neighbour(a, dir), dec_.neighbour(a, -dir), dec_.wraps(a, dir), {}};
      // The wall: the core's last `skin` cell layers on the side it sends to.
      const int wallLo = dir > 0 ? dec_.coreHi(a) - skin_[a] : dec_.coreLo(a),
                wallHi = wallLo + skin_[a];
      out.clear();
      if (d.dest >= 0) {
        for (std::size_t i = 0; i < p_.local(); ++i) {
          if (gcell_[i][a] < wallLo || gcell_[i][a] >= wallHi) continue;
          d.send.push_back(static_cast<std::uint32_t>(i));
          std::array<int, 3> g = gcell_[i];
          std::copy_n(p_.fixed(i), nF, f.begin());
          std::copy_n(p_.alter(i), nA, x.begin());
          if (d.wrapsOut) {
            g[a] -= dir * dec_.globalCells(a);
            f[a] -= dir * dom.length(a);
            x[a] -= dir * dom.length(a);
          }
          putGid(out, p_.gid(i));
          put(out, g.data(), 3);
          put(out, f.data(), nF);
          put(out, x.data(), nA);
        }
      }
      comm_.sendrecv(out, d.dest, in, d.src, kTagBorder);
      d.recvFirst = p_.local();
      const std::size_t rec = sizeof(Gid) + 3 * sizeof(int) + (nF + nA) * sizeof(double);
      const char* c = in.data();
      for (std::size_t k = 0; k < in.size() / rec; ++k) {
        Gid id;
        std::array<int, 3> g;
        get(c, &id, 1);
        get(c, g.data(), 3);
        get(c, f.data(), nF);
        get(c, x.data(), nA);
        p_.append(id, f.data(), x.data());
        gcell_.push_back(g);
      }
      d.recvCount = p_.local() - d.recvFirst;
      dirs_.push_back(std::move(d));
    }
  }
  stats_.shuffleMessages = comm_.messages() - m0;
  stats_.shuffleBytes = comm_.bytes() - b0;
}

void ProcCube::buildCellLists() {
  const int nCells = ext_[0] * ext_[1] * ext_[2];
  const std::size_t n = p_.local();
  cell_.resize(n);
  cellStart_.assign(nCells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      const int l = gcell_[i][a] - dec_.coreLo(a) + skin_[a];
      if (l < 0 || l >= ext_[a]) {
        std::ostringstream os;
        os << "particle " << p_.gid(i) << " arrived outside the procCube of rank " << comm_.rank();
        throw RunError(os.str());
      }
    }
    cell_[i] = localCell(gcell_[i]);
    cellStart_[cell_[i] + 1]++;
  }
  for (int c = 0; c < nCells; ++c) cellStart_[c + 1] += cellStart_[c];
  cellList_.resize(n);
  std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) cellList_[fill[cell_[i]]++] = static_cast<std::uint32_t>(i);
  // Ghosts arrive in message order; put each skin cell in global-ID order.
  for (int c = 0; c < nCells; ++c)
    std::sort(cellList_.begin() + cellStart_[c], cellList_.begin() + cellStart_[c + 1],
              [&](std::uint32_t a, std::uint32_t b) { return p_.gid(a) < p_.gid(b); });
}

void ProcCube::remapBonds(long step) {
  if (bonds_.empty()) return;
  // Open-addressing table gid -> first local index, with a chain through copies of the
  // same particle (periodic images seen twice by one procCube).
  const std::size_t n = p_.local();
  std::size_t size = 16;
  while (size < 2 * n) size *= 2;
  std::vector<std::int64_t> keys(size, -1);
  std::vector<std::int32_t> first(size, -1), next(n, -1);
  auto slot = [&](Gid g) {
    std::size_t h = static_cast<std::size_t>(g) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29)) & (size - 1);
    while (keys[h] != -1 && keys[h] != g) h = (h + 1) & (size - 1);
    return h;
  };
  for (std::size_t i = n; i-- > 0;) {
    const std::size_t h = slot(p_.gid(i));
    keys[h] = p_.gid(i);
    next[i] = first[h];
    first[h] = static_cast<std::int32_t>(i);
  }
  auto& partner = bonds_.renumberPartners();
  for (std::size_t i = 0; i < p_.owned(); ++i) {
    const double* xi = p_.alter(i);
    for (std::size_t b = bonds_.begin(i); b < bonds_.end(i); ++b) {
      const std::size_t h = slot(bonds_.partnerGid(b));
      std::int32_t j = keys[h] == bonds_.partnerGid(b) ? first[h] : -1;
      if (j < 0 && !bonds_.alive(b)) {
        partner[b] = -1;
        continue;
      }
      if (j < 0) {
        std::ostringstream os;
        os << "step " << step << ": bond partner " << bonds_.partnerGid(b) << " of particle "
           << p_.gid(i) << " is not within the procCube (the bond is longer than a cell; "
           << "raise the minimum cell size)";
        throw RunError(os.str());
      }
      if (next[j] >= 0) {  // several copies: take the nearest
        double best = INFINITY;
        for (std::int32_t k = j; k >= 0; k = next[k]) {
          const double* xk = p_.alter(k);
          const double d = (xk[0] - xi[0]) * (xk[0] - xi[0]) + (xk[1] - xi[1]) * (xk[1] - xi[1]) +
                           (xk[2] - xi[2]) * (xk[2] - xi[2]);
          if (d < best && k != static_cast<std::int32_t>(i)) best = d, j = k;
        }
      }
      partner[b] = j;
    }
  }
}

void ProcCube::halo(bool allColumns) {
  const std::size_t nA = p_.schema().nAlter(),
                    nH = allColumns ? nA : static_cast<std::size_t>(p_.schema().nHalo());
  const std::uint64_t m0 = comm_.messages(), b0 = comm_.bytes();
  std::uint64_t wall = 0;
  const Domain& dom = dec_.domain();
  auto& table = p_.alterTable();
  for (const Direction& d : dirs_) {
    const std::size_t nSend = d.dest >= 0 ? d.send.size() * nH : 0, nRecv = d.recvCount * nH;
    double* s = buffer(sendBuf_, nSend);
    if (d.dest >= 0)
      for (std::uint32_t i : d.send) {
        std::copy_n(&table[std::size_t(i) * nA], nH, s);
        if (d.wrapsOut) s[d.axis] -= d.dir * dom.length(d.axis);
        s += nH;
      }
    if (d.dest >= 0) wall += d.send.size();
    // Whole rows are received in place; some columns of each row through a buffer.
    double* ghosts = table.data() + d.recvFirst * nA;
    double* r = nH == nA ? ghosts : buffer(recvBuf_, nRecv);
    comm_.sendrecvKnown(sendBuf_.data(), nSend, d.dest, r, nRecv, d.src, kTagHalo);
    if (nH != nA)
      for (std::size_t k = 0; k < d.recvCount; ++k) std::copy_n(r + k * nH, nH, ghosts + k * nA);
  }
  stats_.haloMessages = comm_.messages() - m0;
  stats_.haloBytes = comm_.bytes() - b0;
  stats_.haloWallParticles = wall;
}

void ProcCube::refreshGhosts(std::span<double> values, int width) {
  ++refreshes_;
  const std::size_t w = static_cast<std::size_t>(width);
  if (values.size() < p_.local() * w)
    throw std::logic_error("refreshGhosts: the array is shorter than local particles x width");
  for (const Direction& d : dirs_) {
    const std::size_t nSend = d.dest >= 0 ? d.send.size() * w : 0;
    double* s = buffer(sendBuf_, nSend);
    if (d.dest >= 0)
      for (std::uint32_t i : d.send) s = std::copy_n(values.data() + i * w, w, s);
    comm_.sendrecvKnown(sendBuf_.data(), nSend, d.dest, values.data() + d.recvFirst * w,
                        d.recvCount * w, d.src, kTagScratch);
  }
}

double ProcCube::maxDisplacementSinceRebuild(std::size_t* which) const {
  double m = 0;
  for (std::size_t i = 0; i < p_.owned(); ++i) {
    const double* x = p_.alter(i);
    const double* x0 = &rebuildPos_[3 * i];
    const double d = (x[0] - x0[0]) * (x[0] - x0[0]) + (x[1] - x0[1]) * (x[1] - x0[1]) +
                     (x[2] - x0[2]) * (x[2] - x0[2]);
    if (d > m && which) *which = i;
    m = std::max(m, d);
  }
  return std::sqrt(m);
}

void ProcCube::shuffle(long step) {
  const std::uint64_t m0 = comm_.messages(), b0 = comm_.bytes();
  migrate(step);
  const std::uint64_t m1 = comm_.messages(), b1 = comm_.bytes();
  rebuild(step);
  stats_.shuffleMessages += m1 - m0;
  stats_.shuffleBytes += b1 - b0;
}

void ProcCube::migrate(long step) {
  const Schema& s = p_.schema();
  const int nF = s.nFixed(), nA = s.nAlter(), nI = s.nInteg(), nB = bonds_.nAttr();
  const Domain& dom = dec_.domain();
  const std::size_t n0 = p_.owned();
  p_.truncate(n0);
  // Wrap periodic positions and check how far each particle went since the last rebuild.
  for (std::size_t i = 0; i < n0; ++i) {
    double* x = p_.alter(i);
    double* f = p_.fixed(i);
    for (int a = 0; a < dec_.dim(); ++a) {
      if (i < rebuildPos_.size() / 3 && std::fabs(x[a] - rebuildPos_[3 * i + a]) > dec_.reach(a)) {
        std::ostringstream os;
        os << "step " << step << ": particle " << p_.gid(i) << " moved "
           << std::fabs(x[a] - rebuildPos_[3 * i + a]) << " along "
           << "XYZ"[a] << " since the last shuffle, further than the skin (one cell, "
           << dec_.reach(a) << "); the time step is too large or the system is unstable";
        throw RunError(os.str());
      }
      if (!std::isfinite(x[a])) {
        std::ostringstream os;
        os << "step " << step << ": particle " << p_.gid(i) << " has a non-finite position";
        throw RunError(os.str());
      }
      if (dom.periodic[a]) {
        const double L = dom.length(a);
        if (x[a] >= dom.hi[a])
          x[a] -= L, f[a] -= L;
        else if (x[a] < dom.lo[a])
          x[a] += L, f[a] += L;
      } else if (x[a] < dom.lo[a] || x[a] >= dom.hi[a]) {
        std::ostringstream os;
        os << "step " << step << ": particle " << p_.gid(i) << " left the domain along "
           << "XYZ"[a] << " (position " << x[a] << ", domain [" << dom.lo[a] << ", " << dom.hi[a]
           << ")); enlarge the margin";
        throw RunError(os.str());
      }
    }
  }
  std::vector<char> outP, outN, in;
  for (int a = 0; a < dec_.dim(); ++a) {
    const int me = dec_.coord(a), nP = dec_.procs(a);
    std::vector<std::size_t> keep;
    outP.clear();
    outN.clear();
    for (std::size_t i = 0; i < p_.owned(); ++i) {
      const int g = std::clamp(dec_.globalCell(a, p_.alter(i)[a]), 0, dec_.globalCells(a) - 1);
      int d = dec_.ownerCoord(a, g) - me;
      if (dom.periodic[a]) {
        if (d > nP / 2) d -= nP;
        if (d < -(nP / 2)) d += nP;
      }
      if (d == 0) {
        keep.push_back(i);
        continue;
      }
      if (d > 1 || d < -1) {
        std::ostringstream os;
        os << "step " << step << ": particle " << p_.gid(i) << " skipped a whole core along "
           << "XYZ"[a];
        throw RunError(os.str());
      }
      std::vector<char>& out = d > 0 ? outP : outN;
      const std::size_t nb = bonds_.end(i) - bonds_.begin(i);
      putGid(out, p_.gid(i));
      put(out, p_.fixed(i), nF);
      put(out, p_.alter(i), nA);
      put(out, p_.integ(i), nI);
      const std::uint64_t nb64 = nb;
      put(out, &nb64, 1);
      for (std::size_t b = bonds_.begin(i); b < bonds_.end(i); ++b)
        putGid(out, bonds_.partnerGid(b));
      if (nb && nB) put(out, bonds_.attr(bonds_.begin(i)), nb * nB);
      if (nb) put(out, bonds_.deadFlags(bonds_.begin(i)), nb);
    }
    if (keep.size() != p_.owned()) {
      p_.permute(keep);
      p_.truncate(keep.size());
      p_.setOwned(keep.size());
      bonds_.permute(keep);
    }
    for (int dir : {+1, -1}) {
      comm_.sendrecv(dir > 0 ? outP : outN, dec_.neighbour(a, dir), in, dec_.neighbour(a, -dir),
                     kTagMigrate);
      const char* c = in.data();
      const char* e = in.data() + in.size();
      std::vector<double> f(nF), x(nA), ig(nI);
      std::vector<Gid> pg;
      std::vector<double> ba;
      std::vector<std::uint8_t> dead;
      while (c < e) {
        Gid id;
        std::uint64_t nb;
        get(c, &id, 1);
        get(c, f.data(), nF);
        get(c, x.data(), nA);
        get(c, ig.data(), nI);
        get(c, &nb, 1);
        pg.resize(nb);
        ba.resize(nb * nB);
        get(c, pg.data(), nb);
        get(c, ba.data(), nb * nB);
        dead.resize(nb);
        get(c, dead.data(), nb);
        const std::size_t k = p_.append(id, f.data(), x.data());
        std::copy_n(ig.data(), nI, p_.integ(k));
        p_.setOwned(p_.local());
        bonds_.appendParticle(pg.data(), ba.data(), dead.data(), nb);
      }
    }
  }
  rebuildPos_.clear();
}

std::uint64_t ProcCube::haloRecordBytes() const {
  return static_cast<std::uint64_t>(p_.schema().nHalo()) * sizeof(double);
}

double* ProcCube::buffer(std::vector<double>& b, std::size_t n) {
  // Grown only: resizing down and up again would zero what is overwritten anyway.
  if (b.size() < n) b.resize(n);
  return b.data();
}

}  // namespace pdq
