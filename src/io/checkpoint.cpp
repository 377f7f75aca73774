#include "io/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <queue>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "engine/atomic_file.hpp"
#include "engine/checksum.hpp"
#include "engine/error.hpp"
#include "engine/particles.hpp"
#include "io/restart.hpp"

namespace fs = std::filesystem;

namespace pdq {

namespace {

constexpr char kMagic[8] = {'P', 'D', 'Q', 'C', 'K', 'P', 'T', '1'};

double seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

template <class T>
void put(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// --- The bonds in a checkpoint ---------------------------------------------------------
// Each rank's owned bonds go to rank 0 as one block of bytes, its particles with bonds in
// ID order, the 8-byte fields first so that they are read in place from the gathered buffer:
//   u64 particles n | n x u64 ID | n x u64 bond count | m x u64 partner ID |
//   m x nAttr f64 attributes | m x u8 dead flag, padded to a multiple of 8 bytes
// A rank's own bonds are read in place instead (`first`: each particle's first bond in the
// arrays; null: one particle's bonds after the other's, as in a gathered block).
struct BondBlock {
  std::size_t n = 0, m = 0;
  const std::uint64_t *id = nullptr, *count = nullptr, *first = nullptr, *partner = nullptr;
  const double* attr = nullptr;
  const std::uint8_t* dead = nullptr;
};

std::size_t blockBytes(std::size_t n, std::size_t m, int nAttr) {
  return 8 * (1 + 2 * n + m + m * nAttr) + (m + 7) / 8 * 8;
}

BondBlock blockView(const char* p, int nAttr) {
  BondBlock v;
  auto u64 = reinterpret_cast<const std::uint64_t*>(p);
  v.n = u64[0];
  v.id = u64 + 1;
  v.count = v.id + v.n;
  for (std::size_t k = 0; k < v.n; ++k) v.m += v.count[k];
  v.partner = v.count + v.n;
  v.attr = reinterpret_cast<const double*>(v.partner + v.m);
  v.dead = reinterpret_cast<const std::uint8_t*>(v.attr + v.m * nAttr);
  return v;
}

std::vector<char> localBondBlock(const Particles& P, const Bonds& B) {
  const int nA = B.nAttr();
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < P.owned(); ++i)
    if (B.end(i) > B.begin(i)) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return P.gid(a) < P.gid(b); });
  std::size_t m = 0;
  for (const std::size_t i : order) m += B.end(i) - B.begin(i);
  std::vector<char> bytes(blockBytes(order.size(), m, nA));
  auto u64 = reinterpret_cast<std::uint64_t*>(bytes.data());
  u64[0] = order.size();
  std::uint64_t *id = u64 + 1, *count = id + order.size(), *partner = count + order.size();
  double* attr = reinterpret_cast<double*>(partner + m);
  auto dead = reinterpret_cast<std::uint8_t*>(attr + m * nA);
  for (const std::size_t i : order) {
    const std::size_t b0 = B.begin(i), nb = B.end(i) - b0;
    *id++ = static_cast<std::uint64_t>(P.gid(i));
    *count++ = nb;
    for (std::size_t b = b0; b < b0 + nb; ++b)
      *partner++ = static_cast<std::uint64_t>(B.partnerGid(b));
    if (nA) std::memcpy(attr, B.attr(b0), nb * nA * sizeof(double));
    attr += nb * nA;
    std::memcpy(dead, B.deadFlags(b0), nb);
    dead += nb;
  }
  return bytes;
}

// The bonds of one rank's particles where the bond table holds them, in ID order; the
// particles' IDs, bond counts and first bonds are this object's.
class LocalBonds {
 public:
  LocalBonds(const Particles& P, const Bonds& B) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < P.owned(); ++i)
      if (B.end(i) > B.begin(i)) order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return P.gid(a) < P.gid(b); });
    for (const std::size_t i : order) {
      id_.push_back(static_cast<std::uint64_t>(P.gid(i)));
      count_.push_back(B.end(i) - B.begin(i));
      first_.push_back(B.begin(i));
      block_.m += count_.back();
    }
    block_.n = order.size();
    block_.id = id_.data();
    block_.count = count_.data();
    block_.first = first_.data();
    if (B.count()) {
      static_assert(sizeof(Gid) == sizeof(std::uint64_t));
      block_.partner = reinterpret_cast<const std::uint64_t*>(B.partnerGids(0));
      block_.attr = B.nAttr() ? B.attr(0) : nullptr;
      block_.dead = B.deadFlags(0);
    }
  }
  const BondBlock& block() const { return block_; }

 private:
  std::vector<std::uint64_t> id_, count_, first_;
  BondBlock block_;
};

void putVarint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out += static_cast<char>(v | 0x80);
    v >>= 7;
  }
  out += static_cast<char>(v);
}

constexpr int kLiteral = 255;  // an attribute code: its 8 bytes follow

// The values of one attribute column seen most often (up to 255, each more than once):
// a bond's value is then one byte, its index, and any other value its 8 bytes behind
// kLiteral. Lattices have few distinct bond lengths and weights; state that varies bond
// by bond (damage) costs one byte more than raw.
class Dictionary {
 public:
  void count(double v) {
    const auto k = bits(v);
    auto it = counts_.find(k);
    if (it != counts_.end())
      ++it->second;
    else if (counts_.size() < kCandidates)
      counts_.emplace(k, 1);
  }
  // Chooses the values (most frequent first, ties by their bits: the same on any machine).
  void choose() {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> c(counts_.begin(), counts_.end());
    std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) {
      return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    for (const auto& [k, n] : c) {
      if (n < 2 || values_.size() == kLiteral) break;
      values_.push_back(k);
    }
    slots_.fill(-1);
    for (std::size_t i = 0; i < values_.size(); ++i) {
      std::size_t s = slot(values_[i]);
      while (slots_[s] >= 0) s = (s + 1) % slots_.size();
      slots_[s] = static_cast<std::int16_t>(i);
    }
  }
  const std::vector<std::uint64_t>& values() const { return values_; }
  int code(std::uint64_t k) const {
    for (std::size_t s = slot(k);; s = (s + 1) % slots_.size()) {
      if (slots_[s] < 0) return kLiteral;
      if (values_[slots_[s]] == k) return slots_[s];
    }
  }
  static std::uint64_t bits(double v) {
    std::uint64_t k;
    std::memcpy(&k, &v, sizeof k);
    return k;
  }

 private:
  static constexpr std::size_t kCandidates = 1 << 16;
  std::size_t slot(std::uint64_t k) const { return (k * 0x9E3779B97F4A7C15ULL) >> 54; }
  std::unordered_map<std::uint64_t, std::uint64_t> counts_;
  std::vector<std::uint64_t> values_;
  std::array<std::int16_t, 1024> slots_{};
};

// The part "bond codes" in its two halves: the IDs and counts, then the attribute codes.
struct EncodedBonds {
  std::string ids, codes;
  bool empty() const { return ids.empty(); }
};

// The part "bond codes": the bonds of every rank's block in ID order (the same bytes on any
// number of ranks), compact (io/checkpoint.hpp gives the layout).
EncodedBonds encodeBonds(const std::vector<BondBlock>& blocks, int nA) {
  struct Next {
    std::uint64_t id;
    std::size_t block;
    bool operator>(const Next& o) const { return id > o.id; }
  };
  // The particles of all blocks merged in ID order: (block, particle, its first bond).
  struct At {
    std::size_t block, k, bond;
  };
  std::vector<At> order;
  std::vector<std::size_t> pos(blocks.size(), 0), bond(blocks.size(), 0);
  std::priority_queue<Next, std::vector<Next>, std::greater<>> heads;
  std::size_t m = 0;
  for (std::size_t r = 0; r < blocks.size(); ++r) {
    if (blocks[r].n) heads.push({blocks[r].id[0], r});
    m += blocks[r].m;
  }
  while (!heads.empty()) {
    const std::size_t r = heads.top().block;
    heads.pop();
    const std::size_t k = pos[r]++;
    order.push_back({r, k, blocks[r].first ? blocks[r].first[k] : bond[r]});
    bond[r] += blocks[r].count[k];
    if (pos[r] < blocks[r].n) heads.push({blocks[r].id[pos[r]], r});
  }
  // Every 7th bond's values choose the dictionaries.
  std::vector<Dictionary> dict(nA);
  std::size_t seen = 0;
  for (const At& a : order) {
    const BondBlock& b = blocks[a.block];
    for (std::size_t j = 0; j < b.count[a.k]; ++j, ++seen)
      if (seen % 7 == 0)
        for (int c = 0; c < nA; ++c) dict[c].count(b.attr[(a.bond + j) * nA + c]);
  }
  std::string out, codes;
  put(out, static_cast<std::uint32_t>(nA));
  for (auto& d : dict) {
    d.choose();
    out += static_cast<char>(d.values().size());
    for (std::uint64_t v : d.values()) put(out, v);
  }
  put(out, static_cast<std::uint64_t>(order.size()));
  put(out, static_cast<std::uint64_t>(m));
  out.reserve(out.size() + 2 * m);
  codes.reserve(m * nA);
  std::uint64_t previous = 0;
  for (const At& a : order) {
    const BondBlock& b = blocks[a.block];
    const std::uint64_t owner = b.id[a.k], n = b.count[a.k];
    putVarint(out, owner - previous);
    putVarint(out, n);
    previous = owner;
    std::uint64_t last = owner;
    for (std::size_t j = a.bond; j < a.bond + n; ++j) {
      const auto d = static_cast<std::int64_t>(b.partner[j] - last);
      if (d >= (std::int64_t{1} << 61) || d <= -(std::int64_t{1} << 61))
        throw Error("checkpoint: the IDs of particles " + std::to_string(owner) + " and " +
                    std::to_string(b.partner[j]) + " are too far apart to be written");
      const auto zigzag = static_cast<std::uint64_t>((d << 1) ^ (d >> 63));
      putVarint(out, zigzag << 1 | (b.dead[j] != 0));
      last = b.partner[j];
      for (int c = 0; c < nA; ++c) {
        const std::uint64_t v = Dictionary::bits(b.attr[j * nA + c]);
        const int code = dict[c].code(v);
        codes += static_cast<char>(code);
        if (code == kLiteral) put(codes, v);
      }
    }
  }
  return {std::move(out), std::move(codes)};
}

// Every rank's bonds, encoded on rank 0 (empty elsewhere, and when there are none).
EncodedBonds gatherBonds(OutputContext& out) {
  const int nA = out.ctx.bonds.nAttr();
  if (out.comm.size() == 1) {  // read where they are, not copied first
    const LocalBonds local(out.ctx.particles, out.ctx.bonds);
    return local.block().m ? encodeBonds({local.block()}, nA) : EncodedBonds{};
  }
  std::vector<char> local = localBondBlock(out.ctx.particles, out.ctx.bonds);
  std::vector<std::size_t> starts{0, local.size()};
  const std::vector<char> all = out.comm.gather(local, starts);
  local = {};
  if (!out.comm.root()) return {};
  std::vector<BondBlock> blocks;
  std::size_t m = 0;
  for (std::size_t r = 0; r + 1 < starts.size(); ++r) {
    blocks.push_back(blockView(all.data() + starts[r], nA));
    m += blocks.back().m;
  }
  return m ? encodeBonds(blocks, nA) : EncodedBonds{};
}

// The part "bond codes" back as rows (owner, partner, dead, attributes), for parseRestart.
std::vector<double> decodeBonds(std::string_view part, int& nA, const std::string& path) {
  auto damaged = [&](const std::string& what) {
    return InputError(path, 0, "damaged: its bond codes " + what);
  };
  std::size_t at = 0;
  auto need = [&](std::size_t n) {
    if (n > part.size() - at) throw damaged("end early");
  };
  auto fixed = [&](auto v) {
    need(sizeof v);
    std::memcpy(&v, part.data() + at, sizeof v);
    at += sizeof v;
    return v;
  };
  auto varint = [&] {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      need(1);
      const auto byte = static_cast<unsigned char>(part[at++]);
      if (shift == 63 && byte > 1) throw damaged("hold a number of more than 64 bits");
      v |= std::uint64_t{byte & 0x7FU} << shift;
      if (!(byte & 0x80)) return v;
    }
  };
  const auto columns = fixed(std::uint32_t{});
  if (columns > 64) throw damaged("say each bond has " + std::to_string(columns) + " attributes");
  nA = static_cast<int>(columns);
  std::vector<std::vector<double>> dict(nA);
  for (auto& d : dict) {
    const auto size = static_cast<unsigned char>(fixed(char{}));
    for (unsigned k = 0; k < size; ++k) d.push_back(fixed(double{}));
  }
  const auto particles = fixed(std::uint64_t{}), bonds = fixed(std::uint64_t{});
  // Each particle and each bond takes a byte at least: a bound before allocating.
  if (particles > part.size() - at || bonds > (part.size() - at) / (1 + nA))
    throw damaged("end early");
  const std::size_t width = 3 + nA;
  std::vector<double> rows(bonds * width);
  std::size_t row = 0;
  std::uint64_t owner = 0;
  for (std::uint64_t k = 0; k < particles; ++k) {
    owner += varint();
    const std::uint64_t n = varint();
    if (n > bonds - row) throw damaged("hold more bonds than they say");
    std::uint64_t partner = owner;
    for (std::uint64_t j = 0; j < n; ++j, ++row) {
      const std::uint64_t code = varint();
      const std::uint64_t zigzag = code >> 1;
      partner += (zigzag >> 1) ^ (~(zigzag & 1) + 1);
      double* r = &rows[row * width];
      r[0] = static_cast<double>(static_cast<Gid>(owner));
      r[1] = static_cast<double>(static_cast<Gid>(partner));
      r[2] = static_cast<double>(code & 1);
    }
  }
  if (row != bonds) throw damaged("hold fewer bonds than they say");
  for (std::size_t r = 0; r < bonds; ++r)
    for (int c = 0; c < nA; ++c) {
      const auto code = static_cast<unsigned char>(fixed(char{}));
      if (code == kLiteral)
        rows[r * width + 3 + c] = fixed(double{});
      else if (code < dict[c].size())
        rows[r * width + 3 + c] = dict[c][code];
      else
        throw damaged("name value " + std::to_string(code) + " of a dictionary of " +
                      std::to_string(dict[c].size()));
    }
  if (at != part.size())
    throw damaged("are followed by " + std::to_string(part.size() - at) + " bytes");
  return rows;
}

// A checkpoint read back: its header and the texts of its parts.
struct Contents {
  long step = -1;
  double time = 0, dt = 0, setupDt = 0;
  std::uint64_t hash = 0;
  RestartTexts texts;
  int bondAttrs = -1;  // the attributes per bond its bond codes hold
};

// Reads `bytes` from `at`, or says the file is cut short.
class Reader {
 public:
  Reader(const std::string& bytes, std::size_t end, const std::string& path)
      : b_(bytes), end_(end), path_(path) {}
  template <class T>
  T get() {
    T v;
    need(sizeof v);
    std::memcpy(&v, b_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  std::string text(std::uint64_t n) {
    need(n);
    std::string s = b_.substr(at_, n);
    at_ += n;
    return s;
  }
  std::size_t at() const { return at_; }

 private:
  void need(std::uint64_t n) const {
    if (n > end_ - at_)
      throw InputError(path_, 0,
                       "cut short: " + std::to_string(b_.size()) +
                           " bytes, its contents need more (a kill while it was written?)");
  }
  const std::string& b_;
  std::size_t end_, at_ = 0;
  const std::string& path_;
};

Contents readCheckpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the checkpoint (unreadable)");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(path, 0,
                     bytes.size() < sizeof kMagic ? "cut short: " + std::to_string(bytes.size()) +
                                                        " bytes (a kill while it was written?)"
                                                  : "not a pdq checkpoint");
  if (bytes.size() < sizeof kMagic + sizeof(std::uint32_t))
    throw InputError(path, 0, "cut short: no checksum");
  const std::size_t body = bytes.size() - sizeof(std::uint32_t);
  Reader r(bytes, body, path);
  r.text(sizeof kMagic);
  Contents c;
  c.step = static_cast<long>(r.get<std::uint64_t>());
  c.time = r.get<double>();
  c.dt = r.get<double>();
  c.setupDt = r.get<double>();
  c.hash = r.get<std::uint64_t>();
  const auto parts = r.get<std::uint32_t>();
  if (parts > 4)
    throw InputError(path, 0, "damaged: it says it has " + std::to_string(parts) + " parts");
  c.texts.step = c.step;
  for (std::uint32_t k = 0; k < parts; ++k) {
    const std::string name = r.text(r.get<std::uint32_t>());
    std::string text = r.text(r.get<std::uint64_t>());
    if (name == "state")
      c.texts.state = std::move(text);
    else if (name == "fixed")
      c.texts.fixed = std::move(text);
    else if (name == "bonds")  // the bonds as text: checkpoints of earlier versions
      c.texts.bonds = std::move(text);
    else if (name == "bond rows") {
      if (text.size() % sizeof(double) != 0)
        throw InputError(path, 0,
                         "damaged: its bond rows are " + std::to_string(text.size()) +
                             " bytes, not a whole number of numbers");
      auto& rows = c.texts.bondRows.emplace(text.size() / sizeof(double));
      std::memcpy(rows.data(), text.data(), text.size());
    } else if (name == "bond codes")
      c.texts.bondRows = decodeBonds(text, c.bondAttrs, path);
    else if (name == "particles")
      c.texts.particles = std::move(text);
    else
      throw InputError(path, 0, "damaged: a part named '" + name + "'");
  }
  if (r.at() != body)
    throw InputError(path, 0,
                     "damaged: " + std::to_string(body - r.at()) + " bytes after its last part");
  std::uint32_t stored;
  std::memcpy(&stored, bytes.data() + body, sizeof stored);
  const std::uint32_t crc = crc32(bytes.data(), body);
  if (crc != stored) {
    char msg[128];
    std::snprintf(msg, sizeof msg, "damaged: its CRC-32 is %08x, the file says %08x", crc, stored);
    throw InputError(path, 0, msg);
  }
  return c;
}

// The names of a checkpoint's parts in messages: "DIR/checkpoint.<step>.ckpt[Bonds.<step>.rst]".
RestartNames partNames(const std::string& path, long step) {
  RestartNames n = restartNames("", step);
  for (std::string* s : {&n.particles, &n.state, &n.fixed, &n.bonds})
    *s = path + "[" + s->substr(1) + "]";
  return n;
}

}  // namespace

std::string checkpointPath(const std::string& dir, long step) {
  char name[48];
  std::snprintf(name, sizeof name, "/checkpoint.%012ld.ckpt", step);
  return dir + name;
}

std::vector<long> checkpointSteps(const std::string& dir) {
  std::vector<long> steps;
  // checkpoint.<twelve digits>.ckpt, matched by hand (<regex> is slow to compile).
  constexpr std::string_view head = "checkpoint.", tail = ".ckpt";
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    if (f.size() != head.size() + 12 + tail.size() || !f.starts_with(head) || !f.ends_with(tail))
      continue;
    const std::string digits = f.substr(head.size(), 12);
    if (std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      steps.push_back(std::stol(digits));
  }
  std::sort(steps.begin(), steps.end());
  return steps;
}

std::uint64_t scenarioHash(const std::string& input, const ParticleSet& initial) {
  std::vector<fs::path> files;
  if (fs::is_directory(input)) {
    for (const auto& e : fs::directory_iterator(input))
      if (e.is_regular_file() && e.path().extension() == ".dat") files.push_back(e.path());
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(input);
  }
  std::uint64_t h = hash64("");
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    h = hash64(f.filename().string(), h);
    h = hash64(ss.str(), h);
  }
  auto bytes = [](const auto& v) {
    return std::string_view(reinterpret_cast<const char*>(v.data()), v.size() * sizeof v[0]);
  };
  h = hash64(bytes(initial.gid), h);
  h = hash64(bytes(initial.fixed), h);
  return hash64(bytes(initial.alter), h);
}

CheckpointOutput::CheckpointOutput(const OutputSettings& s, std::uint64_t scenarioHash)
    : Output(s.checkpointEvery),
      minutes_(s.checkpointMinutes),
      kept_(s.checkpointsKept),
      hash_(scenarioHash),
      last_(seconds()) {}

bool CheckpointOutput::requested() { return seconds() - last_ >= 60 * minutes_; }

void CheckpointOutput::begin(OutputContext& out, bool resumed) {
  last_ = seconds();
  if (!out.comm.root()) return;
  removeStepFiles(out.outDir, "checkpoint.", ".ckpt", resumed ? out.step : -1);
  // The restart files too: an earlier run in the folder may have written some where this one writes
  // none.
  removeRestartFiles(out.outDir, resumed ? out.step : -1);
}

void CheckpointOutput::write(OutputContext& out) {
  if (out.step == lastWritten_) return;
  lastWritten_ = out.step;
  last_ = seconds();
  EncodedBonds bonds = gatherBonds(out);
  // Each part is written as its pieces arrive, its length (and the header's count of parts)
  // filled in afterwards, and the CRC-32 read back from the file: rank 0 holds no whole part
  // but the bond codes.
  std::unique_ptr<AtomicFile> f;
  std::ofstream* o = nullptr;
  std::streampos countAt, lengthAt, partAt;
  std::uint32_t parts = 0;
  std::vector<std::pair<std::streampos, std::uint64_t>> lengths;
  auto bytes = [&](std::string_view b) {
    o->write(b.data(), static_cast<std::streamsize>(b.size()));
  };
  auto endPart = [&] {
    if (parts) lengths.emplace_back(lengthAt, static_cast<std::uint64_t>(o->tellp() - partAt));
  };
  auto beginPart = [&](const std::string& name) {
    endPart();
    ++parts;
    std::string head;
    put(head, static_cast<std::uint32_t>(name.size()));
    head += name;
    bytes(head);
    lengthAt = o->tellp();
    bytes(std::string(sizeof(std::uint64_t), '\0'));
    partAt = o->tellp();
  };
  if (out.comm.root()) {
    f = std::make_unique<AtomicFile>(checkpointPath(out.outDir, out.step));
    o = &f->stream();
    std::string head(kMagic, sizeof kMagic);
    put(head, static_cast<std::uint64_t>(out.step));
    put(head, out.ctx.time());
    put(head, out.ctx.dt());
    put(head, out.setupDt);
    put(head, hash_);
    bytes(head);
    countAt = o->tellp();
    bytes(std::string(sizeof(std::uint32_t), '\0'));
  }
  static const char* const names[] = {"state", "fixed", "bonds", "particles"};
  int current = -1;
  restartParts(out, false, [&](RestartPart part, const std::string& text) {
    if (static_cast<int>(part) != current) {
      current = static_cast<int>(part);
      if (part == RestartPart::PARTICLES && !bonds.empty()) {
        beginPart("bond codes");
        bytes(bonds.ids);
        bytes(bonds.codes);
        bonds = {};
      }
      beginPart(names[current]);
    }
    bytes(text);
  });
  if (!out.comm.root()) return;
  endPart();
  for (const auto& [at, length] : lengths) {
    o->seekp(at);
    o->write(reinterpret_cast<const char*>(&length), sizeof length);
  }
  o->seekp(countAt);
  o->write(reinterpret_cast<const char*>(&parts), sizeof parts);
  o->seekp(0, std::ios::end);
  o->flush();
  if (!*o) throw Error("cannot write " + f->path() + ": " + std::strerror(errno));
  std::uint32_t crc = 0;
  {
    std::ifstream in(f->temporaryPath(), std::ios::binary);
    std::vector<char> chunk(1 << 20);
    while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
      crc = crc32(chunk.data(), static_cast<std::size_t>(in.gcount()), crc);
  }
  o->write(reinterpret_cast<const char*>(&crc), sizeof crc);
  f->commit(true);
  // The newest `kept` stay; this one is the newest (begin removed any later).
  const auto steps = checkpointSteps(out.outDir);
  for (std::size_t k = 0; k + kept_ < steps.size(); ++k)
    fs::remove(checkpointPath(out.outDir, steps[k]));
}

Resumed resumeFromCheckpoint(const std::string& dir, std::uint64_t scenarioHash, bool force,
                             Problem& pb) {
  Resumed out;
  const auto steps = checkpointSteps(dir);
  if (steps.empty())
    throw InputError(dir, 0, "no checkpoint (checkpoint.<step>.ckpt) to resume from");
  const ParticleSet before = pb.particles;
  for (auto s = steps.rbegin(); s != steps.rend(); ++s) {
    const std::string path = checkpointPath(dir, *s);
    // Damaged or cut short: skipped, for an older one may still be whole.
    auto skip = [&](const InputError& e) {
      pb.particles = before;
      out.warnings.push_back(std::string(e.what()) + "; skipped");
    };
    Contents c;
    try {
      c = readCheckpoint(path);
      if (c.step != *s)
        throw InputError(path, 0, "damaged: it holds step " + std::to_string(c.step));
    } catch (const InputError& e) {
      skip(e);
      continue;
    }
    if (c.bondAttrs >= 0 && c.bondAttrs != pb.model->schema().nBond()) {
      skip(InputError(path, 0,
                      "its bonds have " + std::to_string(c.bondAttrs) +
                          " attributes, the model's " +
                          std::to_string(pb.model->schema().nBond())));
      continue;
    }
    if (c.hash != scenarioHash && !force)
      throw InputError(path, 0,
                       "written by a run of another scenario (its input has changed since); "
                       "start afresh, or continue anyway with --force");
    try {
      out.state = parseRestart(c.texts, partNames(path, c.step), pb);
    } catch (const InputError& e) {
      skip(e);
      continue;
    }
    out.state.setupDt = c.setupDt;
    out.state.adoptDt = force;
    out.path = path;
    return out;
  }
  std::string why;
  for (const auto& w : out.warnings) why += "\n  " + w;
  throw InputError(dir, 0, "no valid checkpoint to resume from:" + why);
}

}  // namespace pdq
