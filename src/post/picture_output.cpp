#include "post/picture_output.hpp"

#include <fmt/format.h>

#include "engine/error.hpp"
#include "engine/model.hpp"

namespace pdq::post {

PictureOutput::PictureOutput(PictureOptions options)
    : Output(options.every), opt_(std::move(options)) {
  if (opt_.format != "png" && opt_.format != "svg" && opt_.format != "pdf")
    throw InputError("picture", 0,
                     "unknown picture format '" + opt_.format + "' (use png, svg or pdf)");
}

std::string PictureOutput::fileName(const PictureOptions& o, long step) {
  return fmt::format("{}_{:06d}.{}", o.name, step, o.format);
}

void PictureOutput::write(OutputContext& out) {
  if (!checked_) {  // every rank alike, before any collective call
    const Schema& schema = out.ctx.particles.schema();
    checkRequest(opt_.request, quantityNames(schema, out.model), schema.bond);
    checked_ = true;
  }
  const Snapshot s = gatherSnapshot(out.ctx, out.model, out.comm, out.step);
  if (!out.comm.root()) return;
  PictureRequest r = opt_.request;
  if (r.style.title.empty()) r.style.title = fmt::format("step {}, t = {:.4g}", s.step, s.time);
  renderSnapshot(s, r, out.outDir + "/" + fileName(opt_, out.step));
}

}  // namespace pdq::post
