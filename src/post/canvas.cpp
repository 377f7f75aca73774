#include "post/canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <filesystem>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"

namespace pdq::post {
namespace {

enum Kind { Png, Svg, Pdf };

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Canvas::Canvas(std::string path, int width, int height, double fontSize)
    : path_(std::move(path)), width_(width), height_(height) {
  std::string ext = std::filesystem::path(path_).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") {
    kind_ = Png;
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  } else if (ext == ".svg") {
    kind_ = Svg;
    surface_ = cairo_svg_surface_create_for_stream(append, &bytes_, width, height);
  } else if (ext == ".pdf") {
    kind_ = Pdf;
    surface_ = cairo_pdf_surface_create_for_stream(append, &bytes_, width, height);
  } else {
    throw InputError(path_, 0, "unknown picture format '" + ext + "' (use .png, .svg or .pdf)");
  }
  cr_ = cairo_create(surface_);
  if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS)
    throw Error("cannot draw " + path_ + ": " + cairo_status_to_string(cairo_status(cr_)));
  font_ = fontSize > 0 ? fontSize : std::clamp(std::min(width, height) / 45.0, 11.0, 28.0);
  cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr_, 1, 1, 1);  // white background, also in PNG
  cairo_paint(cr_);
}

Canvas::~Canvas() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

void Canvas::setColour(Rgb c, double alpha) { cairo_set_source_rgba(cr_, c.r, c.g, c.b, alpha); }

double Canvas::textWidth(const std::string& s, double size) {
  cairo_set_font_size(cr_, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr_, s.c_str(), &e);
  return e.x_advance;
}

void Canvas::text(double x, double y, const std::string& s, double ax, double ay, double size,
                  double angle) {
  cairo_save(cr_);
  cairo_set_font_size(cr_, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr_, s.c_str(), &e);
  cairo_font_extents_t f;
  cairo_font_extents(cr_, &f);
  cairo_translate(cr_, x, y);
  cairo_rotate(cr_, -angle);
  // Vertical anchoring by the font's ascent, so labels of one row line up.
  cairo_move_to(cr_, -ax * e.x_advance, -ay * f.ascent + f.ascent);
  cairo_show_text(cr_, s.c_str());
  cairo_restore(cr_);
}

void Canvas::save() {
  if (kind_ == Png) {
    cairo_surface_flush(surface_);
    cairo_surface_write_to_png_stream(surface_, append, &bytes_);
  } else {
    cairo_surface_finish(surface_);
  }
  const cairo_status_t st = cairo_surface_status(surface_);
  if (st != CAIRO_STATUS_SUCCESS)
    throw Error("cannot draw " + path_ + ": " + cairo_status_to_string(st));
  writeFileAtomically(path_, bytes_);
}

}  // namespace pdq::post
