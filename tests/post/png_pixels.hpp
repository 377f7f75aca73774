#pragma once
// Reads pixels of a PNG written by the renderer, for the picture tests.
#include <cairo.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "post/colour.hpp"

namespace pdq::test {

class Png {
 public:
  explicit Png(const std::string& path) : s_(cairo_image_surface_create_from_png(path.c_str())) {
    if (cairo_surface_status(s_) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("cannot read " + path);
  }
  ~Png() { cairo_surface_destroy(s_); }
  int width() const { return cairo_image_surface_get_width(s_); }
  int height() const { return cairo_image_surface_get_height(s_); }
  // The colour at pixel (x, y), rounded to the pixel grid; channels in [0, 1].
  post::Rgb at(double x, double y) const {
    const int px = static_cast<int>(std::floor(x)), py = static_cast<int>(std::floor(y));
    const unsigned char* d =
        cairo_image_surface_get_data(s_) + py * cairo_image_surface_get_stride(s_);
    std::uint32_t v;
    std::memcpy(&v, d + 4 * px, 4);  // ARGB32 in native order; opaque pictures
    return {((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0};
  }

 private:
  cairo_surface_t* s_;
};

inline double distance(post::Rgb a, post::Rgb b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

}  // namespace pdq::test
