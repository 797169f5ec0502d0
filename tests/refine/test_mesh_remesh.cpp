// Tests for mesh_remesh.h: remeshing a triangle mesh with pull-back through the input faces. Exact cases: a flat
// torus (its own uniformization up to scale: no flip, constant λ) where every output length is e^λ times its
// uniformized length; a planar disk, where the developed image paths are planar segments, so every output length is
// the Euclidean distance of its ends' mapped positions. Then a real genus-2 mesh (CGAL's eight.off) end to end, the
// curvature-measure check's exact limit, and bad input naming what is wrong.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <limits>
#include <random>

#include "conformesh/intrinsic/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh_generators.h"
#include "conformesh/intrinsic/mesh_io.h"
#include "conformesh/refine/mesh_remesh.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using namespace conformesh::refine;

namespace {

MeshRemeshResult run(const MeshInput& in, double eps, int extraBisections = 0) {
  MeshRemeshOptions o;
  o.epsilon = eps;
  o.extraBisections = extraBisections;
  return remeshMesh(in.triangulation, in.positions, o);
}

// A planar disk whose interior vertices are moved off the regular rings, so that its uniformization to the unit disk
// has a non-constant conformal factor and flips edges.
MeshData jitteredDisk() {
  DiskOptions d;
  d.rings = 5;
  MeshData m = makeDisk(d);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (auto& p : m.positions)
    if (p.norm() < 0.99) p += Eigen::Vector3d(jitter(rng), jitter(rng), 0);
  m.source = "jittered disk";
  return m;
}

double relativeLengthMismatch(const MeshRemeshResult& r) {
  const HalfedgeMesh& m = r.mesh.mesh;
  double worst = 0;
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e);
    const double chord = (r.positions[m.tail(h)] - r.positions[m.tip(h)]).norm();
    worst = std::max(worst, std::abs(r.mesh.edgeLengths[e] - chord) / chord);
  }
  return worst;
}

}  // namespace

TEST_CASE("mesh remesh: flat torus, no flip and constant lambda: lengths scale by e^lambda exactly") {
  FlatTorusOptions ft;
  ft.omega2 = std::polar(1.0, M_PI / 3);  // equilateral: every vertex flat, every edge Delaunay
  ft.n = 6;
  const MeshInput in = meshInputFromData(makeFlatTorus(ft));
  const MeshRemeshResult r = run(in, 0.05);
  REQUIRE(r.uniformization.flips == 0);
  const double lambda = r.lambda[0];
  for (double l : r.lambda) REQUIRE(l == Approx(lambda).epsilon(1e-12));
  CHECK(r.quality.vertices > 3 * in.triangulation.mesh.nVertices());  // refinement happened
  // Every length is e^λ times its uniformized length, so the shape figures agree and the sizes scale.
  CHECK(r.quality.minAngleDeg == Approx(r.uniformQuality.minAngleDeg).epsilon(1e-10));
  CHECK(r.quality.meanMinAngleDeg == Approx(r.uniformQuality.meanMinAngleDeg).epsilon(1e-10));
  CHECK(r.quality.maxCircumradius == Approx(std::exp(lambda) * r.uniformQuality.maxCircumradius).epsilon(1e-12));
  CHECK(r.quality.meanCircumradius == Approx(std::exp(lambda) * r.uniformQuality.meanCircumradius).epsilon(1e-12));
  // The flat torus T0* has area 1; T1 tiles the input, whose area is 2·36·(√3/4).
  CHECK(totalArea(r.mesh) == Approx(totalArea(in.triangulation)).epsilon(1e-12));
  CHECK(r.maxBendExcess < 1e-12);  // the image paths are straight
  CHECK(std::abs(r.quality.gaussBonnetResidual) < 1e-9);
  CHECK(r.invertedTriangles == 0);
}

TEST_CASE("mesh remesh: planar disk, flips and varying lambda: lengths are Euclidean distances of the mapped points") {
  const MeshInput in = meshInputFromData(jitteredDisk());
  const MeshRemeshResult r = run(in, 0.05);
  REQUIRE(r.uniformization.flips > 0);
  REQUIRE(r.inputEdgeCrossings > 0);  // paths cross input edges: the exact crossings are exercised
  // The input is a plane, so the development of every image path is the plane itself and its ends are the mapped
  // positions (interpolated in their input faces).
  CHECK(relativeLengthMismatch(r) < 1e-12);
  CHECK(totalArea(r.mesh) == Approx(totalArea(in.triangulation)).epsilon(1e-13));
  for (const auto& p : r.positions) CHECK(p.z() == 0);
  CHECK(r.invertedTriangles == 0);
  CHECK(std::abs(r.quality.gaussBonnetResidual) < 1e-9);  // χ = 1: boundary turning + deficits = 2π
  // Paths bend where the piecewise-projective map's derivative jumps: a few per cent at most on this input.
  CHECK(r.maxBendExcess < 0.05);
}

TEST_CASE("mesh remesh: image paths are single geodesics per uniformized face (extra halvings change nothing)") {
  // Halving a piece moves the input-edge crossings to sub-pieces whose ends are other points of the same geodesic;
  // the sums of straight pieces agree only if every crossing is exact (and the developed lengths anyway).
  const MeshInput in = meshInputFromData(jitteredDisk());
  const MeshRemeshResult a = run(in, 0.08), b = run(in, 0.08, 3);
  REQUIRE(a.mesh.mesh.nEdges() == b.mesh.mesh.nEdges());
  REQUIRE(a.inputEdgeCrossings > 0);
  CHECK(b.pathPieces > 4 * a.pathPieces);
  double worstPath = 0, worstLength = 0;
  for (int e = 0; e < a.mesh.mesh.nEdges(); ++e) {
    worstPath = std::max(worstPath, std::abs(a.pathLength[e] - b.pathLength[e]) / a.pathLength[e]);
    worstLength = std::max(worstLength, std::abs(a.mesh.edgeLengths[e] - b.mesh.edgeLengths[e]) / a.pathLength[e]);
  }
  CHECK(worstPath < 1e-12);
  CHECK(worstLength < 1e-12);
}

TEST_CASE("mesh remesh: CGAL's genus-2 eight.off end to end") {
  const MeshInput in = meshInputFromData(readMesh(std::string(CONFORMESH_TEST_DATA_DIR) + "/eight.off"));
  REQUIRE(in.triangulation.mesh.eulerCharacteristic() == -2);
  const MeshRemeshResult r = run(in, 0.03);
  CHECK(r.uniformization.target == UniformizationTarget::Hyperbolic);
  CHECK(r.quality.vertices > in.triangulation.mesh.nVertices());
  // T1* satisfies the refinement's bound in the uniformized metric; T1 is measured in the input's metric.
  CHECK(r.uniformQuality.minAngleDeg >= 20.7);
  CHECK(std::abs(r.quality.gaussBonnetResidual) < 1e-9);
  CHECK(r.invertedTriangles == 0);
  CHECK(r.orientationChecked > 0);
  // Output vertices lie on the input: their interpolated positions are within the input's bounding box.
  Eigen::Vector3d lo = in.positions[0], hi = in.positions[0];
  for (const auto& p : in.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (const auto& p : r.positions) CHECK(((p - lo).minCoeff() >= -1e-12 && (hi - p).minCoeff() >= -1e-12));
  // The output's angle deficits and the input's both total 2πχ = −4π.
  const double chi = -2;
  CHECK(curvatureTotals(r.mesh).interiorDeficit == Approx(2 * M_PI * chi).epsilon(1e-12));

  SECTION("curvature measure: balls covering the whole surface compare 2πχ with 2πχ") {
    CurvatureMeasureOptions o;
    o.radiusFraction = 1e3;
    const CurvatureMeasureResult c = meshCurvatureMeasure(r, in.triangulation, o);
    CHECK(c.smoothTotalCurvature == Approx(2 * M_PI * chi).epsilon(1e-12));
    CHECK(c.maxAbsoluteError < 1e-9);
    CHECK(c.fractionWithinBand == 1.0);
  }
  SECTION("T1 is an intrinsic retriangulation of the input: deficits, flat new vertices, area") {
    // Every output triangle is the flat triangle of its developed vertices, and the three developments agree, so the
    // output is the input's cone metric retriangulated: input vertices keep their deficits, inserted ones are flat,
    // and the measure check at the paper's radius is exact up to round-off.
    const std::vector<double> k1 = vertexCurvatures(r.mesh), k0 = vertexCurvatures(in.triangulation);
    double worst = 0;
    for (int v = 0; v < r.mesh.mesh.nVertices(); ++v)
      worst = std::max(worst, std::abs(k1[v] - (v < r.inputVertices ? k0[v] : 0.0)));
    CHECK(worst < 1e-12);
    CHECK(totalArea(r.mesh) == Approx(totalArea(in.triangulation)).epsilon(1e-13));
    const CurvatureMeasureResult c = meshCurvatureMeasure(r, in.triangulation);
    CHECK(c.maxAbsoluteError < 1e-12);
  }
}

TEST_CASE("mesh remesh: bad input is named") {
  SECTION("an edge in three faces") {
    MeshData d;
    d.source = "fin.off";
    d.nVertices = 5;
    d.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    d.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    CHECK_THROWS_AS(meshInputFromData(d), InputError);
    CHECK_THROWS_WITH(meshInputFromData(d), Catch::Contains("fin.off") && Catch::Contains("edge"));
  }
  SECTION("a NaN coordinate") {
    MeshData d = makeDisk({});
    d.source = "nan.ply";
    d.positions[7].y() = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(meshInputFromData(d), InputError);
    CHECK_THROWS_WITH(meshInputFromData(d), Catch::Contains("nan.ply") && Catch::Contains("7"));
  }
  SECTION("a spherical metric-only mesh") {
    MeshData d = fromTriangulation(toTriangulation(makeDisk({})));
    d.background = Background::Spherical;
    d.source = "sphere.ply";
    CHECK_THROWS_WITH(meshInputFromData(d), Catch::Contains("sphere.ply") && Catch::Contains("Euclidean"));
  }
  SECTION("eps") {
    const MeshInput in = meshInputFromData(makeDisk({}));
    MeshRemeshOptions o;
    o.epsilon = -1;
    CHECK_THROWS_WITH(remeshMesh(in.triangulation, in.positions, o), Catch::Contains("--eps"));
    o.epsilon = 0.1;
    o.inputSubdivisions = 9;
    CHECK_THROWS_WITH(remeshMesh(in.triangulation, in.positions, o), Catch::Contains("subdivisions"));
  }
}
