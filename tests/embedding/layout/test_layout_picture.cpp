// test_layout_picture.cpp — drawings of canonical layouts: the number of triangles (D plus tiles), tiles of a flat
// torus being exact translates by the reduced periods, hyperbolic tiles staying inside the unit disk, the back faces
// of a sphere culled, and the SVG text carrying one polygon per triangle; a too-small picture size named.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "conformesh/embedding/layout/layout_picture.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/io/mesh_io.h"

using namespace conformesh::embedding;
using namespace conformesh::intrinsic;

namespace {

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
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
}
