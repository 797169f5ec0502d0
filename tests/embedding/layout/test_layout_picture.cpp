// test_layout_picture.cpp — drawings of canonical layouts: the number of triangles (D plus tiles), tiles of a flat
// torus being exact translates by the reduced periods, hyperbolic tiles staying inside the unit disk, the back faces
// of a sphere culled, and the SVG parsed back: one polygon per triangle at the documented image of its corners, the
// lines, the Poincaré disk's unit circle enclosing every corner; a too-small picture size named.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "conformesh/embedding/layout/layout_picture.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/io/mesh_io.h"

#include "support/svg_reader.h"

using namespace conformesh::embedding;
using namespace conformesh::intrinsic;

namespace {

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// The SVG's geometry against the drawing, by the picture's documented map (layout_picture.h: `pixels` wide and high,
// y up, the bounding box of the triangles, lines and unit circle fitted with a 3 % margin): every triangle one filled
// polygon — the tiles (layer 1) first, then D, each layer in its own <g> — with its corners at
// (P/2 + s(x − cx), P/2 − s(y − cy)), s = 0.94 P / span, to the 0.005 px of the two printed decimals; every line one
// unfilled polyline or polygon; the unit circle, when drawn, a <circle> of radius s about the image of 0. Returns the
// parsed picture.
conformesh::testing::SvgPicture checkSvg(const LayoutDrawing& d, const std::string& svg, int pixels) {
  const conformesh::testing::SvgPicture pic = conformesh::testing::readSvg(svg);
  CHECK(pic.viewBox == std::array<double, 4>{0, 0, double(pixels), double(pixels)});
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  auto grow = [&](const Eigen::Vector2d& p) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  };
  for (const auto& t : d.triangles)
    for (const auto& p : t.corners) grow(p);
  for (const auto& l : d.lines)
    for (const auto& p : l.points) grow(p);
  if (d.unitCircle) grow({-1, -1}), grow({1, 1});
  const double scale = 0.94 * pixels / std::max(x1 - x0, y1 - y0), cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  auto image = [&](const Eigen::Vector2d& p) {
    return std::array<double, 2>{pixels / 2.0 + scale * (p.x() - cx), pixels / 2.0 - scale * (p.y() - cy)};
  };
  std::vector<const DrawnTriangle*> order;
  for (int layer : {1, 0})
    for (const auto& t : d.triangles)
      if (t.layer == layer) order.push_back(&t);
  std::vector<const conformesh::testing::SvgShape*> filled, unfilled;
  for (const auto& sh : pic.shapes) (sh.fill == "none" ? unfilled : filled).push_back(&sh);
  REQUIRE(filled.size() == d.triangles.size());
  int misplaced = 0, outside = 0;
  double worst = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    REQUIRE(filled[i]->points.size() == 3);
    for (int k = 0; k < 3; ++k) {
      const auto want = image(order[i]->corners[k]), got = filled[i]->points[k];
      const double e = std::max(std::abs(got[0] - want[0]), std::abs(got[1] - want[1]));
      worst = std::max(worst, e);
      misplaced += e <= 0.005 + 1e-9 * pixels ? 0 : 1;
      outside += (got[0] >= 0 && got[0] <= pixels && got[1] >= 0 && got[1] <= pixels) ? 0 : 1;
    }
    // One <g> per layer: D's triangles in one group, the tiles' in another.
    if (i > 0) CHECK((filled[i]->groupStroke == filled[i - 1]->groupStroke) == (order[i]->layer == order[i - 1]->layer));
  }
  INFO("largest corner offset " << worst << " px");
  CHECK(misplaced == 0);
  CHECK(outside == 0);
  std::size_t lines = 0;
  for (const auto& l : d.lines) lines += l.points.size() >= 2 ? 1 : 0;
  CHECK(unfilled.size() == lines);
  REQUIRE(pic.circles.size() == (d.unitCircle ? 1u : 0u));
  if (d.unitCircle) {
    const auto centre = image({0, 0});
    CHECK(std::abs(pic.circles[0].cx - centre[0]) < 1e-6 * pixels);
    CHECK(std::abs(pic.circles[0].cy - centre[1]) < 1e-6 * pixels);
    CHECK(pic.circles[0].r == Approx(scale).epsilon(1e-6));
  }
  return pic;
}

}  // namespace

TEST_CASE("a flat torus is drawn with its 3×3 block of translated tiles") {
  FlatTorusOptions o;
  o.omega2 = {0.3, 1.1};
  o.n = 4;
  const IntrinsicTriangulation tri = toTriangulation(makeFlatTorus(o));
  const TorusLayout t = layoutTorus(tri);
  const LayoutDrawing d = drawTorus(tri, t);
  const int nf = tri.mesh.nFaces();
  REQUIRE(static_cast<int>(d.triangles.size()) == 9 * nf);
  // Tile k (k ≥ 1) is D translated by a lattice vector: every corner moves by the same amount.
  for (int k = 1; k < 9; ++k) {
    const Eigen::Vector2d shift = d.triangles[k * nf].corners[0] - d.triangles[0].corners[0];
    for (int f = 0; f < nf; ++f)
      for (int c = 0; c < 3; ++c)
        CHECK((d.triangles[k * nf + f].corners[c] - d.triangles[f].corners[c] - shift).norm() < 1e-12);
    const Complex s(shift.x(), shift.y());
    // The shift is m ω₁' + n ω₂' with integers |m|, |n| ≤ 1.
    const double n = std::imag(s / t.reducedOmega1) / std::imag(t.reducedOmega2 / t.reducedOmega1);
    const double m = std::real((s - n * t.reducedOmega2) / t.reducedOmega1);
    CHECK(std::abs(n - std::round(n)) < 1e-12);
    CHECK(std::abs(m - std::round(m)) < 1e-12);
  }
  const std::string svg = toSvg(d, 400);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(countOf(svg, "<polygon points=") == d.triangles.size());
  checkSvg(d, svg, 400);
  CHECK_THROWS_WITH(toSvg(d, 4), Catch::Contains("picture size 4 px"));
  // Tiles beyond maxTriangles are left out; D stays.
  PictureOptions few;
  few.maxTriangles = nf;
  CHECK(static_cast<int>(drawTorus(tri, t, few).triangles.size()) == nf);
}

TEST_CASE("a hyperbolic surface is drawn inside the Poincare disk with its deck tiles") {
  const IntrinsicTriangulation input = toTriangulation(readMesh(std::string(CONFORMESH_TEST_DATA_DIR) + "/eight.off"));
  const Uniformization u = uniformize(input);
  const HyperbolicLayout h = layoutHyperbolic(u.uniform);
  const LayoutDrawing d = drawHyperbolic(u.uniform, h);
  CHECK(d.unitCircle);
  CHECK(d.triangles.size() == std::size_t(1 + 4 * 2) * u.uniform.mesh.nFaces());
  double maxRadius = 0;
  for (const auto& t : d.triangles)
    for (const auto& p : t.corners) maxRadius = std::max(maxRadius, p.norm());
  CHECK(maxRadius < 1);
  // In the SVG: the unit circle drawn about the centre of the picture, every corner inside it.
  const conformesh::testing::SvgPicture pic = checkSvg(d, toSvg(d, 900), 900);
  REQUIRE(pic.circles.size() == 1);
  const conformesh::testing::SvgCircle c = pic.circles[0];
  CHECK(c.cx == Approx(450).epsilon(1e-9));
  CHECK(c.cy == Approx(450).epsilon(1e-9));
  CHECK(c.r == Approx(0.47 * 900).epsilon(1e-9));  // the bounding box is the circle's, [−1, 1]²
  double farthest = 0;
  for (const auto& sh : pic.shapes)
    for (const auto& p : sh.points) farthest = std::max(farthest, std::hypot(p[0] - c.cx, p[1] - c.cy));
  CHECK(farthest < c.r + 0.01);  // printed to 0.01 px
  // Four generator loops, each drawn in its own colour.
  std::vector<int> colours;
  for (const auto& l : d.lines)
    if (l.colour > 0) colours.push_back(l.colour);
  CHECK(*std::max_element(colours.begin(), colours.end()) == 4);
}

TEST_CASE("a sphere layout is drawn from the front") {
  const IntrinsicTriangulation tri = toTriangulation(makeIcosphere({2, 1.0}));
  const Uniformization u = uniformize(tri);
  const SphereLayout s = layoutSphere(u);
  const LayoutDrawing d = drawSphere(u.uniform, s);
  // Roughly half of the 320 faces face the viewer.
  CHECK(d.triangles.size() > 120);
  CHECK(d.triangles.size() < 200);
  for (const auto& t : d.triangles) CHECK((t.shade > 0 && t.shade <= 1));
  checkSvg(d, toSvg(d, 500), 500);
}
