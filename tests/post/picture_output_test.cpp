// Pictures during a run: the gathered snapshot is the whole lattice at any number of
// ranks, and the damage picture shows every broken bond in black and no intact one.
#include "post/picture_output.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "engine/error.hpp"
#include "png_pixels.hpp"
#include "spring_lattice.hpp"

namespace pdq {
namespace {

// Records the snapshot of the last step, as the picture output sees it.
class Capture final : public Output {
 public:
  explicit Capture(post::Snapshot& s) : Output(0), s_(s) {}
  bool atEnd() const override { return true; }
  void write(OutputContext& out) override {
    s_ = post::gatherSnapshot(out.ctx, out.model, out.comm, out.step);
  }

 private:
  post::Snapshot& s_;
};

TEST(PictureOutput, GathersAndDrawsDamage) {
  Comm comm;
  const std::string dir = "pictures_np" + std::to_string(comm.size());
  if (comm.root()) std::filesystem::remove_all(dir);
  comm.barrier();
  const int nx = 12, ny = 7;
  auto sim = test::springLattice(comm, nx, ny, 20, dir);
  post::PictureOptions opt;
  opt.every = 10;
  opt.request.bondDamage = "broken";
  opt.request.style.width = 900;
  sim->addOutput(std::make_unique<post::PictureOutput>(opt));
  post::Snapshot snap;
  sim->addOutput(std::make_unique<Capture>(snap));
  sim->run();
  const auto x = test::gatherAlter(*sim, 0);
  const auto bonds = test::gatherBonds(*sim);
  if (!comm.root()) {
    EXPECT_EQ(snap.particles(), 0u);
    return;
  }
  for (long step : {0, 10, 20})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + post::PictureOutput::fileName(opt, step)));

  // The snapshot: every particle in ID order, every bond once with its attribute.
  ASSERT_EQ(snap.particles(), static_cast<std::size_t>(nx * ny));
  for (std::size_t i = 0; i < snap.particles(); ++i) {
    EXPECT_EQ(snap.id[i], static_cast<Gid>(i));
    EXPECT_EQ(snap.current[3 * i], x.at(snap.id[i]));
  }
  ASSERT_EQ(snap.bonds.size(), bonds.size());
  EXPECT_EQ(snap.names, (std::vector<std::string>{"vx", "vy", "vz", "damage"}));
  for (std::size_t b = 0; b < snap.bonds.size(); ++b)
    EXPECT_EQ(snap.bondAttrs[b * snap.bondNames.size()],
              bonds.at({snap.id[snap.bonds[b][0]], snap.id[snap.bonds[b][1]]}));

  // The same snapshot rebuilt as `pdq post` would from files: particles in another
  // order, every bond listed from both ends.
  post::Snapshot files;
  files.names = snap.names;
  files.bondNames = snap.bondNames;
  files.values.resize(snap.names.size());
  for (std::size_t r = snap.particles(); r-- > 0;) {
    files.id.push_back(snap.id[r]);
    files.reference.insert(files.reference.end(), &snap.reference[3 * r],
                           &snap.reference[3 * r + 3]);
    files.current.insert(files.current.end(), &snap.current[3 * r], &snap.current[3 * r + 3]);
    for (std::size_t k = 0; k < snap.names.size(); ++k)
      files.values[k].push_back(snap.values[k][r]);
  }
  post::sortParticles(files);
  std::vector<Gid> owner, partner;
  std::vector<double> attrs;
  for (std::size_t b = snap.bonds.size(); b-- > 0;)
    for (int side = 0; side < 2; ++side) {
      owner.push_back(snap.id[snap.bonds[b][side]]);
      partner.push_back(snap.id[snap.bonds[b][1 - side]]);
      const std::size_t nb = snap.bondNames.size();
      attrs.insert(attrs.end(), snap.bondAttrs.begin() + b * nb,
                   snap.bondAttrs.begin() + (b + 1) * nb);
    }
  post::addBonds(files, owner, partner, attrs, "restart");
  EXPECT_EQ(files.id, snap.id);
  EXPECT_EQ(files.current, snap.current);
  EXPECT_EQ(files.values, snap.values);
  EXPECT_EQ(files.bonds, snap.bonds);
  EXPECT_EQ(files.bondAttrs, snap.bondAttrs);
  owner.push_back(nx * ny);  // not a particle
  partner.push_back(0);
  attrs.push_back(0);
  EXPECT_THROW(post::addBonds(files, owner, partner, attrs, "restart"), InputError);

  // The last picture: broken bonds black at their midpoints; intact bonds between
  // particles with no broken bond not drawn (white between the dots).
  post::PictureRequest req = opt.request;
  req.style.title = "t";  // the same layout as the output's titled picture
  const post::LatticeImage im = post::latticeImage(snap, req);
  const post::LatticeFrame f = post::latticeFrame(im, req.style);
  test::Png png(dir + "/" + post::PictureOutput::fileName(opt, 20));
  ASSERT_EQ(png.height(), f.height);
  std::vector<bool> cracked(snap.particles(), false);
  for (std::size_t b = 0; b < im.bonds.size(); ++b)
    if (im.bondDamage[b] != 0) cracked[im.bonds[b][0]] = cracked[im.bonds[b][1]] = true;
  int black = 0, white = 0;
  for (std::size_t b = 0; b < im.bonds.size(); ++b) {
    double p[3];
    for (int a = 0; a < 3; ++a)
      p[a] = 0.5 * (snap.current[3 * im.bonds[b][0] + a] + snap.current[3 * im.bonds[b][1] + a]);
    const auto px = f.pixel(p);
    const post::Rgb c = png.at(px[0], px[1]);
    if (im.bondDamage[b] != 0) {
      EXPECT_LT(test::distance(c, {0, 0, 0}), 0.02) << "broken bond " << b;
      ++black;
    } else if (!cracked[im.bonds[b][0]] && !cracked[im.bonds[b][1]]) {
      EXPECT_LT(test::distance(c, {1, 1, 1}), 0.02) << "intact bond " << b;
      ++white;
    }
  }
  EXPECT_GT(black, 0);
  EXPECT_GT(white, 0);
}

TEST(PictureOutput, UnknownNamesAreErrors) {
  post::Snapshot s;
  s.names = {"vx", "damage"};
  s.bondNames = {"broken"};
  post::PictureRequest r;
  r.colourBy = "damgae";
  try {
    post::checkRequest(r, s.names, s.bondNames);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'damage'"), std::string::npos) << e.what();
  }
  r.colourBy = "displacement";
  r.bondDamage = "damage";
  EXPECT_THROW(post::checkRequest(r, s.names, s.bondNames), InputError);
  r.bondDamage = "";  // automatic: this model has no "damage" bond attribute, so no bonds
  EXPECT_NO_THROW(post::checkRequest(r, s.names, s.bondNames));
  post::PictureOptions gif;
  gif.format = "gif";
  EXPECT_THROW(post::PictureOutput{gif}, InputError);
}

TEST(PictureOutput, OptionsFromAScenarioTable) {
  Params t("[output.picture]");
  t.set("every", "500", "beam.toml", 12);
  t.set("view", "1,-1,0.5", "beam.toml", 13);
  t.set("colour_by", "damgae", "beam.toml", 14);
  t.set("magnification", "50", "beam.toml", 15);
  t.set("format", "svg", "beam.toml", 16);
  const post::PictureOptions o = post::pictureOptions(t);
  EXPECT_EQ(o.every, 500);
  EXPECT_EQ(o.format, "svg");
  EXPECT_EQ(o.request.style.magnification, 50);
  EXPECT_EQ(o.request.style.view, (std::array<double, 3>{1, -1, 0.5}));
  try {
    post::checkRequest(o.request, {"damage"}, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "beam.toml");
    EXPECT_EQ(e.line(), 14);
  }
  t.set("view", "sideways", "beam.toml", 13);
  try {
    post::pictureOptions(t);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 13);
  }
  t.set("view", "z", "beam.toml", 13);
  t.set("format", "gif", "beam.toml", 16);
  EXPECT_THROW(post::pictureOptions(t), InputError);
}

// A 3 × 3 × 3 lattice at unit spacing with bonds along X; three of them damaged, one in
// each Z layer: (0,1,1)-(1,1,1) broken, (1,1,0)-(2,1,0) broken, (0,0,2)-(1,0,2) half.
post::Snapshot cube() {
  post::Snapshot s;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) {
        s.id.push_back(static_cast<Gid>(s.id.size()));
        s.reference.insert(s.reference.end(), {double(x), double(y), double(z)});
      }
  s.current = s.reference;
  s.bondNames = {"broken", "damage"};
  auto at = [](int x, int y, int z) { return static_cast<std::size_t>(x + 3 * y + 9 * z); };
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 2; ++x) {
        s.bonds.push_back({at(x, y, z), at(x + 1, y, z)});
        double d = 0;
        if (x == 0 && y == 1 && z == 1) d = 1;
        if (x == 1 && y == 1 && z == 0) d = 1;
        if (x == 0 && y == 0 && z == 2) d = 0.5;
        s.bondAttrs.insert(s.bondAttrs.end(), {d == 1 ? 1.0 : 0.0, d});
      }
  return s;
}

TEST(PictureOutput, SlabsAndPlanesOfA3dLattice) {
  const post::Snapshot s = cube();
  post::PictureRequest r;
  r.style.width = 600;
  r.style.dotRadius = 4;
  auto colourAt = [&](const std::string& path, std::array<double, 3> p) {
    const post::LatticeFrame f = post::latticeFrame(post::latticeImage(s, r), r.style);
    post::renderSnapshot(s, r, path);
    const test::Png png(path);
    const auto px = f.pixel(p.data());
    return png.at(px[0], px[1]);
  };
  // Side elevation (XY) of the whole lattice: the broken bonds of layers z = 0 and 1.
  EXPECT_LT(test::distance(colourAt("side.png", {0.5, 1, 1}), {0, 0, 0}), 0.02);
  EXPECT_LT(test::distance(colourAt("side.png", {1.5, 1, 0}), {0, 0, 0}), 0.02);
  // The slab of the middle layer: its broken bond black, the bottom layer's not drawn.
  r.slab = post::parseSlab("z=0.5:1.5", "view.toml", 3);
  EXPECT_LT(test::distance(colourAt("slab.png", {0.5, 1, 1}), {0, 0, 0}), 0.02);
  EXPECT_LT(test::distance(colourAt("slab.png", {1.5, 1, 0}), {1, 1, 1}), 0.02);
  EXPECT_EQ(post::latticeImage(s, r).particles(), 9u);
  EXPECT_EQ(post::latticeImage(s, r).bonds.size(), 6u);
  // Plan from below (XZ, viewer at -Y): X to the right, Z up; the slab y = 0 shows the
  // half-damaged bond of the top layer in the ramp's colour at (x, z) = (0.5, 2).
  r.style.view = post::parseView("-y");
  r.slab = post::parseSlab("y=-0.5:0.5", "view.toml", 3);
  const post::LatticeFrame f = post::latticeFrame(post::latticeImage(s, r), r.style);
  EXPECT_NEAR(f.right[0], 1, 1e-12);
  EXPECT_NEAR(f.up[2], 1, 1e-12);
  EXPECT_LT(test::distance(colourAt("below.png", {0.5, 0, 2}), post::damageColour(0.5)), 0.02);
  EXPECT_LT(test::distance(colourAt("below.png", {1.5, 0, 0}), {1, 1, 1}), 0.02);
}

TEST(PictureOutput, BadSlabsAreErrors) {
  for (const char* text : {"z=0.11:0.05", "z=0.1:0.1", "w=0:1", "z0:1", "z=a:1", "z=0.1", ""}) {
    try {
      post::parseSlab(text, "beam.toml", 7);
      FAIL() << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "beam.toml");
      EXPECT_EQ(e.line(), 7);
    }
  }
  // A slab beside the lattice holds no particle: the error names the lattice's range.
  Params t("[output.picture]");
  t.set("slab", "z=5:6", "beam.toml", 9);
  const post::PictureOptions o = post::pictureOptions(t);
  try {
    post::latticeImage(cube(), o.request);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "beam.toml");
    EXPECT_EQ(e.line(), 9);
    EXPECT_NE(std::string(e.what()).find("holds no particle"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("from 0 to 2"), std::string::npos) << e.what();
  }
}

TEST(PictureOutput, AddBondsKeepsOneCopyPerPair) {
  post::Snapshot s;
  s.id = {10, 11, 12};
  s.reference = s.current = std::vector<double>(9, 0.0);
  s.bondNames = {"damage"};
  // 12-11 only from the larger end; 10-11 from both ends (values differ: the smaller
  // ID's copy wins); 10-12 from the smaller end only.
  post::addBonds(s, {12, 11, 10, 10}, {11, 10, 11, 12}, {0.3, 0.9, 0.1, 0.5}, "restart");
  EXPECT_EQ(s.bonds, (std::vector<std::array<std::size_t, 2>>{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_EQ(s.bondAttrs, (std::vector<double>{0.1, 0.5, 0.3}));
}

}  // namespace
}  // namespace pdq
