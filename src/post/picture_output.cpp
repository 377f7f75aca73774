#include "post/picture_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "engine/model.hpp"

namespace pdq::post {

PictureOptions pictureOptions(const Params& t) {
  PictureOptions o;
  auto where = [&](const std::string& key) {
    const auto v = t.raw(key);
    return std::pair(v ? v->file : t.owner(), v ? v->line : 0);
  };
  o.every = t.integer("every", o.every);
  if (o.every < 0) {
    const auto [file, line] = where("every");
    throw InputError(file, line, "every must be 0 or more steps");
  }
  o.atEnd = t.flag("at_end", o.atEnd);
  o.name = t.text("name", o.name);
  o.format = t.choice("format", o.format, {"png", "svg", "pdf"});
  PictureRequest& r = o.request;
  r.colourBy = t.text("colour_by", r.colourBy);
  r.bondDamage = t.text("bond_damage", r.bondDamage);
  std::tie(r.source, r.colourByLine) = where("colour_by");
  std::tie(r.bondDamageSource, r.bondDamageLine) = where("bond_damage");
  PictureStyle& st = r.style;
  st.magnification = t.number("magnification", st.magnification, 0, 1e12);
  if (t.has("view")) {
    const auto [file, line] = where("view");
    st.view = parseView(t.text("view"), file, line);
  }
  st.width = static_cast<int>(t.number("width", st.width, 50, 20000));
  st.height = static_cast<int>(t.number("height", st.height, 0, 20000));
  st.dotRadius = t.number("dot_radius", st.dotRadius, 0, 1000);
  st.damageThreshold = t.number("damage_threshold", st.damageThreshold, 0, 1);
  st.valueMin = t.number("value_min", st.valueMin);
  st.valueMax = t.number("value_max", st.valueMax);
  st.title = t.text("title", st.title);
  if (t.has("slab")) {
    const auto [file, line] = where("slab");
    r.slab = parseSlab(t.text("slab"), file, line);
    r.slabSource = file;
    r.slabLine = line;
  }
  return o;
}

PictureOutput::PictureOutput(PictureOptions options)
    : Output(options.every), opt_(std::move(options)) {
  if (opt_.format != "png" && opt_.format != "svg" && opt_.format != "pdf")
    throw InputError("picture", 0,
                     "unknown picture format '" + opt_.format + "' (use png, svg or pdf)");
}

std::string PictureOutput::fileName(const PictureOptions& o, long step) {
  return fmt::format("{}_{:06d}.{}", o.name, step, o.format);
}

void PictureOutput::begin(OutputContext& out, bool resumed) {
  // Every rank alike, before the first step: errors stop the run before anything is drawn.
  const Schema& schema = out.ctx.particles.schema();
  std::vector<std::string> bondNames{"broken"};  // the engine's flag, then the model's
  bondNames.insert(bondNames.end(), schema.bond.begin(), schema.bond.end());
  checkRequest(opt_.request, quantityNames(schema, out.model), bondNames);
  if (const Slab& slab = opt_.request.slab; slab.axis >= 0) {
    const Particles& P = out.ctx.particles;
    double inside = 0, lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < P.owned(); ++i) {
      inside = std::max(inside, slab.contains(P.fixed(i)) ? 1.0 : 0.0);
      lo = std::min(lo, P.fixed(i)[slab.axis]);
      hi = std::max(hi, P.fixed(i)[slab.axis]);
    }
    if (out.ctx.max(inside) == 0) emptySlab(opt_.request, out.ctx.min(lo), out.ctx.max(hi));
  }
  if (out.comm.root())
    removeStepFiles(out.outDir, opt_.name + "_", "." + opt_.format, resumed ? out.step : -1);
}

void PictureOutput::write(OutputContext& out) {
  const Snapshot s = gatherSnapshot(out.ctx, out.model, out.comm, out.step);
  if (!out.comm.root()) return;
  PictureRequest r = opt_.request;
  if (r.style.title.empty()) r.style.title = fmt::format("step {}, t = {:.4g}", s.step, s.time);
  renderSnapshot(s, r, out.outDir + "/" + fileName(opt_, out.step));
}

}  // namespace pdq::post
