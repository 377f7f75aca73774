#include "io/checkpoint.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "engine/atomic_file.hpp"
#include "engine/checksum.hpp"
#include "engine/error.hpp"
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

// A checkpoint read back: its header and the texts of its parts.
struct Contents {
  long step = -1;
  double time = 0, dt = 0, setupDt = 0;
  std::uint64_t hash = 0;
  RestartTexts texts;
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
    } else if (name == "particles")
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
  // The restart files too: a signal writes them where the scenario asks for none.
  removeRestartFiles(out.outDir, resumed ? out.step : -1);
}

void CheckpointOutput::write(OutputContext& out) {
  if (out.step == lastWritten_) return;
  lastWritten_ = out.step;
  last_ = seconds();
  const RestartTexts t = restartTexts(out, true);
  if (!out.comm.root()) return;
  // Written part by part as the CRC-32 runs over them, so that the bonds (most of the
  // bytes) are neither formatted as text nor copied into one buffer first.
  AtomicFile f(checkpointPath(out.outDir, out.step));
  std::uint32_t crc = 0;
  auto emit = [&](std::string_view b) {
    crc = crc32(b.data(), b.size(), crc);
    f.stream().write(b.data(), static_cast<std::streamsize>(b.size()));
  };
  auto emitPart = [&](const std::string& name, std::string_view content) {
    std::string head;
    put(head, static_cast<std::uint32_t>(name.size()));
    head += name;
    put(head, static_cast<std::uint64_t>(content.size()));
    emit(head);
    emit(content);
  };
  std::string head(kMagic, sizeof kMagic);
  put(head, static_cast<std::uint64_t>(out.step));
  put(head, out.ctx.time());
  put(head, out.ctx.dt());
  put(head, out.setupDt);
  put(head, hash_);
  put(head, static_cast<std::uint32_t>(2 + (t.fixed ? 1 : 0) + (t.bondRows ? 1 : 0)));
  emit(head);
  emitPart("state", *t.state);
  if (t.fixed) emitPart("fixed", *t.fixed);
  if (t.bondRows)
    emitPart("bond rows", std::string_view(reinterpret_cast<const char*>(t.bondRows->data()),
                                           t.bondRows->size() * sizeof(double)));
  emitPart("particles", t.particles);
  f.stream().write(reinterpret_cast<const char*>(&crc), sizeof crc);
  f.commit(true);
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
