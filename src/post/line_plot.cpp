#include "post/line_plot.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>

#include "engine/error.hpp"
#include "post/canvas.hpp"
#include "post/colour.hpp"

namespace pdq::post {
namespace {

double fontFor(const PlotStyle& st) {
  return std::clamp(std::min(st.width, st.height) / 45.0, 11.0, 28.0);
}

}  // namespace

std::array<double, 2> PlotFrame::pixel(double xv, double yv) const {
  return {left + (xv - x.lo) / (x.hi - x.lo) * (right - left),
          bottom - (yv - y.lo) / (y.hi - y.lo) * (bottom - top)};
}

PlotFrame plotFrame(const std::vector<Series>& series, const PlotStyle& st) {
  double xl = INFINITY, xh = -INFINITY, yl = INFINITY, yh = -INFINITY;
  for (const Series& s : series) {
    if (s.x.size() != s.y.size())
      throw InputError("plot", 0,
                       "series '" + s.name + "' has " + std::to_string(s.x.size()) +
                           " x values but " + std::to_string(s.y.size()) + " y values");
    for (std::size_t k = 0; k < s.x.size(); ++k)
      if (std::isfinite(s.x[k]) && std::isfinite(s.y[k])) {
        xl = std::min(xl, s.x[k]), xh = std::max(xh, s.x[k]);
        yl = std::min(yl, s.y[k]), yh = std::max(yh, s.y[k]);
      }
  }
  if (!std::isfinite(xl)) xl = 0, xh = 1, yl = 0, yh = 1;
  PlotFrame f;
  f.width = st.width;
  f.height = st.height;
  f.x = niceTicks(xl, xh, 7);
  f.y = niceTicks(yl, yh, 6);
  const double font = fontFor(st);
  std::size_t chars = 0;
  for (double v : f.y.values) chars = std::max(chars, tickLabel(v, f.y.step).size());
  f.left = font * (st.yLabel.empty() ? 1.0 : 2.6) + 0.62 * font * chars + 0.8 * font;
  f.right = st.width - 1.5 * font;
  f.top = st.title.empty() ? 1.5 * font : 3.2 * font;
  f.bottom = st.height - font * (st.xLabel.empty() ? 2.5 : 4.2);
  return f;
}

void plotLines(const std::vector<Series>& series, const PlotStyle& st, const std::string& path) {
  const PlotFrame f = plotFrame(series, st);
  Canvas c(path, st.width, st.height);
  cairo_t* cr = c.cr();
  const double font = c.fontSize();

  // Grid, axes box, ticks and their numbers.
  cairo_set_line_width(cr, 1);
  for (double v : f.x.values) {
    const double x = std::round(f.pixel(v, 0)[0]) + 0.5;
    c.setColour({0.88, 0.88, 0.88});
    cairo_move_to(cr, x, f.top);
    cairo_line_to(cr, x, f.bottom);
    cairo_stroke(cr);
    c.setColour({0, 0, 0});
    cairo_move_to(cr, x, f.bottom);
    cairo_line_to(cr, x, f.bottom + 0.4 * font);
    cairo_stroke(cr);
    c.text(x, f.bottom + 0.6 * font, tickLabel(v, f.x.step), 0.5, 0, 0.85 * font);
  }
  for (double v : f.y.values) {
    const double y = std::round(f.pixel(0, v)[1]) + 0.5;
    c.setColour({0.88, 0.88, 0.88});
    cairo_move_to(cr, f.left, y);
    cairo_line_to(cr, f.right, y);
    cairo_stroke(cr);
    c.setColour({0, 0, 0});
    cairo_move_to(cr, f.left - 0.4 * font, y);
    cairo_line_to(cr, f.left, y);
    cairo_stroke(cr);
    c.text(f.left - 0.6 * font, y, tickLabel(v, f.y.step), 1, 0.5, 0.85 * font);
  }
  c.setColour({0, 0, 0});
  cairo_rectangle(cr, std::round(f.left) + 0.5, std::round(f.top) + 0.5,
                  std::round(f.right - f.left), std::round(f.bottom - f.top));
  cairo_stroke(cr);
  if (!st.xLabel.empty())
    c.text(0.5 * (f.left + f.right), st.height - 0.6 * font, st.xLabel, 0.5, 1, font);
  if (!st.yLabel.empty())
    c.text(0.6 * font, 0.5 * (f.top + f.bottom), st.yLabel, 0.5, 0, font, M_PI / 2);
  if (!st.title.empty()) c.text(0.5 * st.width, 1.6 * font, st.title, 0.5, 0.5, 1.2 * font);

  // The series, clipped to the plot area.
  cairo_save(cr);
  cairo_rectangle(cr, f.left, f.top, f.right - f.left, f.bottom - f.top);
  cairo_clip(cr);
  cairo_set_line_width(cr, std::max(1.5, 0.16 * font));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (std::size_t k = 0; k < series.size(); ++k) {
    const Series& s = series[k];
    c.setColour(seriesColour(k));
    bool pen = false;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        pen = false;
        continue;
      }
      const auto [x, y] = f.pixel(s.x[i], s.y[i]);
      if (pen) {
        cairo_line_to(cr, x, y);
      } else {
        cairo_move_to(cr, x, y);
        if (s.x.size() == 1) cairo_line_to(cr, x, y);  // a lone point still shows
      }
      pen = true;
    }
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_stroke(cr);
  }
  cairo_restore(cr);

  // Legend in the upper-left corner of the plot area.
  if (st.legend && !series.empty()) {
    double w = 0;
    for (const Series& s : series) w = std::max(w, c.textWidth(s.name, 0.9 * font));
    const double row = 1.4 * font, x = f.left + 0.8 * font, y = f.top + 0.8 * font;
    const double boxW = w + 3.6 * font, boxH = row * series.size() + 0.6 * font;
    c.setColour({1, 1, 1}, 0.9);
    cairo_rectangle(cr, x, y, boxW, boxH);
    cairo_fill_preserve(cr);
    c.setColour({0.6, 0.6, 0.6});
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    for (std::size_t k = 0; k < series.size(); ++k) {
      const double yk = y + 0.3 * font + (k + 0.5) * row;
      c.setColour(seriesColour(k));
      cairo_set_line_width(cr, std::max(2.0, 0.2 * font));
      cairo_move_to(cr, x + 0.5 * font, yk);
      cairo_line_to(cr, x + 2.4 * font, yk);
      cairo_stroke(cr);
      c.setColour({0, 0, 0});
      c.text(x + 2.9 * font, yk, series[k].name, 0, 0.5, 0.9 * font);
    }
  }
  c.save();
}

}  // namespace pdq::post
