#pragma once
// A drawing surface chosen by the file's extension (.png, .svg, .pdf), written
// atomically when saved. The pictures draw on it with Cairo; Cairo stays private to
// libpdq, so this header only names its context type.
#include <string>

#include "post/colour.hpp"

struct _cairo;
struct _cairo_surface;

namespace pdq::post {

class Canvas {
 public:
  // Throws InputError for an extension other than .png, .svg or .pdf. `fontSize` 0:
  // from the picture's size.
  Canvas(std::string path, int width, int height, double fontSize = 0);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  _cairo* cr() { return cr_; }
  int width() const { return width_; }
  int height() const { return height_; }
  double fontSize() const { return font_; }

  void setColour(Rgb c, double alpha = 1);
  // Text anchored at (x, y): ax, ay are the fractions of its width and height left of
  // and above the anchor (0.5, 0.5 = centred); `angle` in radians, counter-clockwise.
  void text(double x, double y, const std::string& s, double ax, double ay, double size,
            double angle = 0);
  double textWidth(const std::string& s, double size);
  void save();  // finishes the surface and writes the file

 private:
  std::string path_, bytes_;
  int width_, height_;
  double font_;
  int kind_;
  _cairo_surface* surface_ = nullptr;
  _cairo* cr_ = nullptr;
};

}  // namespace pdq::post
