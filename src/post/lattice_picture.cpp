#include "post/lattice_picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <numeric>
#include <sstream>

#include "engine/error.hpp"
#include "post/canvas.hpp"
#include "post/ticks.hpp"

namespace pdq::post {
namespace {

using Vec = std::array<double, 3>;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec normalised(Vec v) {
  const double n = std::sqrt(dot(v, v));
  for (double& c : v) c /= n;
  return v;
}

void check(const LatticeImage& im) {
  const std::size_t n = im.particles();
  auto bad = [](const std::string& what) { throw InputError("picture", 0, what); };
  if (im.position.size() != 3 * n) bad("positions must be x y z triples");
  if (!im.displacement.empty() && im.displacement.size() != 3 * n)
    bad("displacements must be x y z triples, one per particle");
  if (im.bondDamage.size() != im.bonds.size()) bad("each bond needs one damage value");
  if (!im.values.empty() && im.values.size() != n) bad("values must be one per particle");
  for (const auto& b : im.bonds)
    if (b[0] >= n || b[1] >= n) bad("a bond names a particle index beyond the particles");
}

// Drawn (deformed, magnified) positions.
std::vector<double> drawn(const LatticeImage& im, double magnification) {
  std::vector<double> p = im.position;
  if (!im.displacement.empty())
    for (std::size_t k = 0; k < p.size(); ++k) p[k] += magnification * im.displacement[k];
  return p;
}

// Text size from the picture's width (lattices are often much wider than tall).
double fontFor(int width) { return std::clamp(width / 64.0, 11.0, 24.0); }

double legendWidth(double font) { return 7.5 * font; }

int legendsOf(const LatticeImage& im) {
  return (im.bonds.empty() ? 0 : 1) + (im.values.empty() ? 0 : 1);
}

// Vertical colour bar with ticks: `colour(t)` for t in [0, 1], labels at `ticks`.
template <class F>
void colourBar(Canvas& c, double x, double top, double h, const std::string& label, F colour,
               double lo, double hi, const std::vector<double>& ticks, double step) {
  cairo_t* cr = c.cr();
  const double w = 1.2 * c.fontSize(), f = c.fontSize();
  c.setColour({0, 0, 0});
  c.text(x, top - 0.6 * f, label, 0, 1, f);
  cairo_pattern_t* g = cairo_pattern_create_linear(0, top + h, 0, top);
  const int n = 48;  // the ramps are piecewise linear with fewer pieces than this
  for (int k = 0; k <= n; ++k) {
    const Rgb rgb = colour(static_cast<double>(k) / n);
    cairo_pattern_add_color_stop_rgb(g, static_cast<double>(k) / n, rgb.r, rgb.g, rgb.b);
  }
  cairo_rectangle(cr, x, top, w, h);
  cairo_set_source(cr, g);
  cairo_fill(cr);
  cairo_pattern_destroy(g);
  c.setColour({0, 0, 0});
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, x, top, w, h);
  cairo_stroke(cr);
  for (double t : ticks) {
    const double y = top + h - (t - lo) / (hi - lo) * h;
    cairo_move_to(cr, x + w, y);
    cairo_line_to(cr, x + w + 0.4 * f, y);
    cairo_stroke(cr);
    c.text(x + w + 0.6 * f, y, tickLabel(t, step), 0, 0.5, 0.85 * f);
  }
}

}  // namespace

std::array<double, 2> LatticeFrame::pixel(const double* p) const {
  const Vec v{p[0], p[1], p[2]};
  return {x0 + scale * dot(v, right), y0 - scale * dot(v, up)};
}

double LatticeFrame::depth(const double* p) const { return dot(Vec{p[0], p[1], p[2]}, toViewer); }

std::array<double, 3> parseView(const std::string& text, const std::string& file, int line) {
  static const std::vector<std::pair<std::string, Vec>> named{
      {"x", {1, 0, 0}},   {"y", {0, 1, 0}},   {"z", {0, 0, 1}},
      {"-x", {-1, 0, 0}}, {"-y", {0, -1, 0}}, {"-z", {0, 0, -1}}};
  for (const auto& [name, v] : named)
    if (text == name) return v;
  std::string t = text;
  std::replace(t.begin(), t.end(), ',', ' ');
  std::istringstream in(t);
  Vec v{};
  std::string rest;
  if (!(in >> v[0] >> v[1] >> v[2]) || (in >> rest) || dot(v, v) == 0)
    throw InputError(file, line,
                     "'" + text +
                         "' is not a view direction (x, y, z, -x, -y, -z or three "
                         "numbers such as 1,1,1)");
  return v;
}

LatticeFrame latticeFrame(const LatticeImage& im, const PictureStyle& st) {
  check(im);
  LatticeFrame fr;
  fr.toViewer = normalised(st.view);
  // Screen "up" is world Z, or world Y when looking along Z.
  const Vec worldUp = std::abs(fr.toViewer[2]) > 0.99 ? Vec{0, 1, 0} : Vec{0, 0, 1};
  Vec up = worldUp;
  const double k = dot(worldUp, fr.toViewer);
  for (int a = 0; a < 3; ++a) up[a] -= k * fr.toViewer[a];
  fr.up = normalised(up);
  fr.right = cross(fr.up, fr.toViewer);

  const std::vector<double> p = drawn(im, st.magnification);
  const std::size_t n = im.particles();
  double uLo = 0, uHi = 1, vLo = 0, vHi = 1;
  if (n) {
    uLo = vLo = INFINITY;
    uHi = vHi = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec q{p[3 * i], p[3 * i + 1], p[3 * i + 2]};
      const double u = dot(q, fr.right), v = dot(q, fr.up);
      uLo = std::min(uLo, u), uHi = std::max(uHi, u);
      vLo = std::min(vLo, v), vHi = std::max(vHi, v);
    }
  }
  // Typical spacing: the median reference bond length, else from the area per particle.
  double spacing = 0;
  if (!im.bonds.empty()) {
    std::vector<double> len;
    for (std::size_t b = 0; b < im.bonds.size() && b < 2000; ++b) {
      const double* a = &im.position[3 * im.bonds[b][0]];
      const double* c = &im.position[3 * im.bonds[b][1]];
      len.push_back(std::sqrt((a[0] - c[0]) * (a[0] - c[0]) + (a[1] - c[1]) * (a[1] - c[1]) +
                              (a[2] - c[2]) * (a[2] - c[2])));
    }
    std::nth_element(len.begin(), len.begin() + len.size() / 2, len.end());
    spacing = len[len.size() / 2];
  }
  double uSpan = uHi - uLo, vSpan = vHi - vLo;
  if (!(spacing > 0))
    spacing = n > 1 ? std::sqrt(std::max(uSpan * vSpan, std::max(uSpan, vSpan) * 1e-3) / n) : 1;
  // Room for the dots at the edges.
  uLo -= spacing, uHi += spacing, vLo -= spacing, vHi += spacing;
  uSpan = uHi - uLo, vSpan = vHi - vLo;

  const double font = fontFor(st.width);
  const double margin = 1.5 * font;
  const double top = st.title.empty() ? margin : 3 * font;
  const double legends = legendsOf(im) * legendWidth(font);
  const double areaW = std::max(st.width - 2 * margin - legends, 10.0);
  fr.width = st.width;
  fr.height =
      st.height > 0
          ? st.height
          : static_cast<int>(std::ceil(
                top + margin + std::clamp(areaW * vSpan / uSpan, 0.15 * areaW, 3.0 * areaW)));
  const double areaH = std::max(fr.height - top - margin, 10.0);
  fr.scale = std::min(areaW / uSpan, areaH / vSpan);
  // Centre the lattice in its area.
  fr.x0 = margin + 0.5 * (areaW - fr.scale * uSpan) - fr.scale * uLo;
  fr.y0 = top + 0.5 * (areaH - fr.scale * vSpan) + fr.scale * vHi;
  fr.dotRadius = st.dotRadius > 0 ? st.dotRadius : std::clamp(0.2 * spacing * fr.scale, 0.6, 12.0);
  return fr;
}

void renderLattice(const LatticeImage& im, const PictureStyle& st, const std::string& path) {
  const LatticeFrame fr = latticeFrame(im, st);
  Canvas c(path, fr.width, fr.height, fontFor(fr.width));
  cairo_t* cr = c.cr();
  const double font = c.fontSize();
  const std::vector<double> p = drawn(im, st.magnification);
  const std::size_t n = im.particles();

  // Colour range of the values.
  double lo = st.valueMin, hi = st.valueMax;
  if (!im.values.empty() && (std::isnan(lo) || std::isnan(hi))) {
    double mn = INFINITY, mx = -INFINITY;
    for (double v : im.values)
      if (std::isfinite(v)) mn = std::min(mn, v), mx = std::max(mx, v);
    if (std::isnan(lo)) lo = std::isfinite(mn) ? mn : 0;
    if (std::isnan(hi)) hi = std::isfinite(mx) ? mx : 1;
  }
  Ticks vt = niceTicks(lo, hi, 5);
  if (!im.values.empty() && !(hi > lo)) lo = vt.lo, hi = vt.hi;
  if (!im.values.empty()) {  // keep only the ticks inside the bar
    std::erase_if(vt.values,
                  [&](double t) { return t < lo - 1e-9 * (hi - lo) || t > hi + 1e-9 * (hi - lo); });
  }

  // Particles, far ones first; dots of one colour (256 levels) at one depth share
  // paths, much faster than a fill per dot.
  auto level = [&](std::size_t i) {
    if (im.values.empty()) return -1;
    const double t = (im.values[i] - lo) / (hi - lo);
    return std::isfinite(t) ? static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * 255)) : 0;
  };
  std::vector<std::pair<double, int>> key(n);
  for (std::size_t i = 0; i < n; ++i) key[i] = {fr.depth(&p[3 * i]), level(i)};
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  for (std::size_t k = 0; k < n;) {
    const int lv = key[order[k]].second;
    c.setColour(lv < 0 ? Rgb{0.55, 0.55, 0.55} : valueColour(lv / 255.0));
    // Paths of a few hundred dots: Cairo fills very long paths more slowly.
    for (int inPath = 0; k < n && key[order[k]].second == lv && inPath < 256; ++k, ++inPath) {
      const auto [x, y] = fr.pixel(&p[3 * order[k]]);
      cairo_new_sub_path(cr);
      cairo_arc(cr, x, y, fr.dotRadius, 0, 2 * M_PI);
    }
    cairo_fill(cr);
  }

  // Damaged bonds over them, the most damaged last so cracks stay black.
  std::vector<std::size_t> shown;
  for (std::size_t b = 0; b < im.bonds.size(); ++b)
    if (im.bondDamage[b] > st.damageThreshold) shown.push_back(b);
  std::stable_sort(shown.begin(), shown.end(), [&](std::size_t a, std::size_t b) {
    return im.bondDamage[a] < im.bondDamage[b];
  });
  cairo_set_line_width(cr, std::max(1.0, 0.8 * fr.dotRadius));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (std::size_t b : shown) {
    const auto [x0, y0] = fr.pixel(&p[3 * im.bonds[b][0]]);
    const auto [x1, y1] = fr.pixel(&p[3 * im.bonds[b][1]]);
    c.setColour(damageColour(im.bondDamage[b]));
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
  }

  if (!st.title.empty()) {
    c.setColour({0, 0, 0});
    c.text(0.5 * fr.width, 1.5 * font, st.title, 0.5, 0.5, 1.2 * font);
  }
  // Legends on the right: the damage ramp, then the colour bar.
  const double margin = 1.5 * font;
  double x = fr.width - legendsOf(im) * legendWidth(font) - 0.5 * margin + font;
  const double top = (st.title.empty() ? margin : 3 * font) + 1.5 * font;
  const double h = std::max(std::min(fr.height - top - margin, 14.0 * font), 2.0 * font);
  if (!im.bonds.empty()) {
    colourBar(c, x, top, h, "damage", damageColour, 0, 1, {0, 0.2, 0.4, 0.6, 0.8, 1}, 0.1);
    x += legendWidth(font);
  }
  if (!im.values.empty()) {
    colourBar(
        c, x, top, h, im.valueName, [](double t) { return valueColour(t); }, lo, hi, vt.values,
        vt.step);
  }
  c.save();
}

}  // namespace pdq::post
