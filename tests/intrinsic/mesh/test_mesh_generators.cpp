// test_mesh_generators.cpp — the generators' known answers: exact V/E/F from each construction, χ, genus and boundary
// loops through HalfedgeMesh::fromFaces, consistent orientation, angle bounds argued from the construction, area
// against closed forms with the convergence order measured by a log–log fit, Gauss–Bonnet through curvatureTotals(),
// and perturbLengths() keeping every triangle inequality within its amplitude.
#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <vector>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"

using namespace conformesh::intrinsic;
using conformesh::InputError;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

// Round-off allowance for sums over up to ~10⁵ terms of size O(1): a few hundred ulps of the total.
constexpr double kRoundOff = 1e-12;

struct Topology {
  int components = 0, vertices = 0, edges = 0, faces = 0, boundaryLoops = 0, chi = 0, genus = 0, reoriented = 0;
};

Topology topologyOf(const MeshData& d) {
  BuildReport build;
  const HalfedgeMesh mesh = HalfedgeMesh::fromFaces(d.faces, d.nVertices, d.source, &build, d.cornerEdges);
  mesh.checkInvariants();
  Topology t;
  t.vertices = mesh.nVertices();
  t.edges = mesh.nEdges();
  t.faces = mesh.nFaces();
  t.chi = mesh.eulerCharacteristic();
  t.reoriented = build.reorientedFaces;
  const auto comps = mesh.components();
  t.components = static_cast<int>(comps.size());
  for (const auto& c : comps) {
    t.boundaryLoops += c.boundaryLoops;
    t.genus += c.genus;
  }
  return t;
}

double minCornerAngle(const IntrinsicTriangulation& tri) {
  const auto a = allCornerAngles(tri);
  return *std::min_element(a.begin(), a.end());
}

double maxCornerAngle(const IntrinsicTriangulation& tri) {
  const auto a = allCornerAngles(tri);
  return *std::max_element(a.begin(), a.end());
}

double meanEdgeLength(const IntrinsicTriangulation& tri) {
  double s = 0;
  for (double l : tri.edgeLengths) s += l;
  return s / tri.edgeLengths.size();
}

// Least-squares slope of log y against log x.

// Signed area of face f projected to the xy-plane (planar generators must be counter-clockwise: all positive).
double signedAreaXY(const MeshData& d, int f) {
  const auto& p = d.positions;
  const auto& F = d.faces[f];
  const Eigen::Vector3d u = p[F[1]] - p[F[0]], v = p[F[2]] - p[F[0]];
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

void requireGaussBonnet(const IntrinsicTriangulation& tri, int expectedChi) {
  const CurvatureTotals totals = curvatureTotals(tri);
  REQUIRE(totals.eulerCharacteristic == expectedChi);
  // The residual is a sum of O(V) angle terms each exact to a few ulps of 2π.
  REQUIRE(std::abs(totals.gaussBonnetResidual) < 1e-9);
  REQUIRE(std::abs(totals.interiorDeficit + totals.boundaryTurning - 2 * kPi * expectedChi) < 1e-9);
}

}  // namespace

// =====================================================================================================================
// Icosphere
// =====================================================================================================================

TEST_CASE("icosphere: counts, topology, vertices on the sphere, outward orientation, angle bound", "[icosphere]") {
  for (int level = 0; level <= 5; ++level) {
    const double R = 2.5;
    const MeshData d = makeIcosphere({level, R});
    const long long q = 1LL << (2 * level);  // 4^L
    const Topology t = topologyOf(d);
    CAPTURE(level);
    REQUIRE(t.vertices == 10 * q + 2);
    REQUIRE(t.edges == 30 * q);
    REQUIRE(t.faces == 20 * q);
    REQUIRE(t.chi == 2);
    REQUIRE(t.genus == 0);
    REQUIRE(t.components == 1);
    REQUIRE(t.boundaryLoops == 0);
    REQUIRE(t.reoriented == 0);
    for (const auto& p : d.positions) REQUIRE(std::abs(p.norm() - R) < 1e-15 * R);  // a few ulps of R
    for (const auto& f : d.faces) {
      const Eigen::Vector3d n = (d.positions[f[1]] - d.positions[f[0]]).cross(d.positions[f[2]] - d.positions[f[0]]);
      REQUIRE(n.dot(d.positions[f[0]] + d.positions[f[1]] + d.positions[f[2]]) > 0);
    }
    const IntrinsicTriangulation tri = toTriangulation(d);
    // Level-L triangles are, up to O(h), images of the equilateral subdivision of an icosahedron face under a map to
    // the sphere with anisotropy like that of the central projection, ≤ 1/cos(37.38°) = 1.26 (37.38° = angular
    // circumradius of a face); a linear map of that anisotropy keeps an equilateral triangle's angles above 49°. The
    // bound 45° leaves room for the difference between that map and repeated midpoint projection.
    REQUIRE(minCornerAngle(tri) > 45 * kDeg);
    REQUIRE(maxCornerAngle(tri) < 90 * kDeg);
    requireGaussBonnet(tri, 2);
  }
}

TEST_CASE("icosphere: area converges to 4πR² at order 2 in the edge length", "[icosphere][convergence]") {
  const double R = 1.7, exact = 4 * kPi * R * R;
  std::vector<double> h, err;
  for (int level = 2; level <= 6; ++level) {
    const IntrinsicTriangulation tri = toTriangulation(makeIcosphere({level, R}));
    const double area = totalArea(tri);
    REQUIRE(area < exact);  // inscribed: each flat triangle is shorter than the spherical patch it spans
    h.push_back(meanEdgeLength(tri));
    err.push_back(exact - area);
  }
  const double order = fitLogLogSlope(h, err);
  CAPTURE(order);
  REQUIRE(std::abs(order - 2) < 0.05);
}

TEST_CASE("icosphere: bad parameters are named", "[icosphere][errors]") {
  REQUIRE_THROWS_WITH(makeIcosphere({-1, 1.0}), Catch::Contains("level") && Catch::Contains("found -1"));
  REQUIRE_THROWS_WITH(makeIcosphere({13, 1.0}), Catch::Contains("level") && Catch::Contains("found 13"));
  REQUIRE_THROWS_WITH(makeIcosphere({2, 0.0}), Catch::Contains("radius") && Catch::Contains("found 0"));
  REQUIRE_THROWS_WITH(makeIcosphere({2, std::nan("")}), Catch::Contains("radius") && Catch::Contains("nan"));
}

TEST_CASE("icosphere: a million faces", "[icosphere][size]") {
  // Generation time is measured in bench/, not asserted here.
  const MeshData d = makeIcosphere({8, 1.0});
  REQUIRE(d.faces.size() == 20u * 65536u);
  REQUIRE(d.nVertices == 10 * 65536 + 2);
}

// =====================================================================================================================
// Torus of revolution
// =====================================================================================================================

TEST_CASE("torus: counts, genus 1, orientation, angle bound, Gauss–Bonnet", "[torus]") {
  const double R = 1.0, r = 0.4;
  for (int m : {4, 8, 16, 32}) {
    for (bool alternate : {false, true}) {
      TorusOptions o;
      o.majorRadius = R;
      o.minorRadius = r;
      o.m = m;
      o.n = static_cast<int>(std::lround(m * R / r / 2)) * 2;  // n/m ≈ R/r: comparable spacings; even for alternation
      o.alternateDiagonals = alternate;
      const MeshData d = makeTorus(o);
      const Topology t = topologyOf(d);
      CAPTURE(m, alternate);
      REQUIRE(t.vertices == o.n * m);
      REQUIRE(t.edges == 3 * o.n * m);
      REQUIRE(t.faces == 2 * o.n * m);
      REQUIRE(t.chi == 0);
      REQUIRE(t.genus == 1);
      REQUIRE(t.components == 1);
      REQUIRE(t.boundaryLoops == 0);
      REQUIRE(t.reoriented == 0);
      // Outward: the normal points away from the core circle (R cos u, R sin u, 0).
      for (const auto& f : d.faces) {
        const auto& p = d.positions;
        const Eigen::Vector3d c = (p[f[0]] + p[f[1]] + p[f[2]]) / 3;
        const Eigen::Vector3d core = R * Eigen::Vector3d(c.x(), c.y(), 0).normalized();
        const Eigen::Vector3d n = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
        REQUIRE(n.dot(c - core) > 0);
      }
      const IntrinsicTriangulation tri = toTriangulation(d);
      // Each quad is an isosceles trapezoid with parallel sides 2π(R + r cos v)/n and legs 2πr/m up to O(1/m²); with
      // n/m = R/r their ratio lies in [(R−r)/R, (R+r)/R] = [0.6, 1.4], so half-rectangles have angles ≥ atan(0.6) =
      // 30.96°. The trapezoid's slant changes angles by O(1/m): at m = 4 by less than 5°.
      REQUIRE(minCornerAngle(tri) > std::atan(0.6) - 5 * kDeg);
      requireGaussBonnet(tri, 0);
    }
  }
}

TEST_CASE("torus: area converges to 4π²Rr at order 2", "[torus][convergence]") {
  const double R = 1.3, r = 0.5, exact = 4 * kPi * kPi * R * r;
  std::vector<double> h, err;
  for (int m : {8, 16, 32, 64, 128}) {
    TorusOptions o;
    o.majorRadius = R;
    o.minorRadius = r;
    o.m = m;
    o.n = static_cast<int>(std::lround(m * R / r));
    const IntrinsicTriangulation tri = toTriangulation(makeTorus(o));
    h.push_back(meanEdgeLength(tri));
    err.push_back(std::abs(exact - totalArea(tri)));
  }
  const double order = fitLogLogSlope(h, err);
  CAPTURE(order);
  REQUIRE(std::abs(order - 2) < 0.05);
}

TEST_CASE("torus: bad parameters are named", "[torus][errors]") {
  TorusOptions o;
  o.minorRadius = 1.5;
  REQUIRE_THROWS_WITH(makeTorus(o), Catch::Contains("0 < r < R") && Catch::Contains("r=1.5"));
  o = TorusOptions{};
  o.m = 2;
  REQUIRE_THROWS_WITH(makeTorus(o), Catch::Contains("m=2"));
  o = TorusOptions{};
  o.n = 7;
  o.alternateDiagonals = true;
  REQUIRE_THROWS_WITH(makeTorus(o), Catch::Contains("even") && Catch::Contains("n=7"));
}

// =====================================================================================================================
// Closed genus-g surface
// =====================================================================================================================

TEST_CASE("genus surface: counts, χ = 2 − 2g, right isosceles triangles, exact area, corner curvatures", "[genus]") {
  for (int g = 0; g <= 4; ++g) {
    for (int N : {1, 2, 3, 6}) {
      const double c = 0.75;
      GenusSurfaceOptions o;
      o.genus = g;
      o.resolution = N;
      o.cellSize = c;
      const MeshData d = makeGenusSurface(o);
      CAPTURE(g, N);
      // Counts of the construction documented in mesh_generators.h.
      const long long W = 2 * g + 1, P = 2 * (W + 3) * N + 4LL * g * N;
      const long long V = 2 * ((W * N + 1) * (3 * N + 1) - 1LL * g * (N - 1) * (N - 1)) + (N - 1) * P;
      const long long F = 4 * (3 * W - g) * N * N + 2 * N * P;
      const Topology t = topologyOf(d);
      REQUIRE(t.vertices == V);
      REQUIRE(t.faces == F);
      REQUIRE(t.edges == 3 * F / 2);
      REQUIRE(t.chi == 2 - 2 * g);
      REQUIRE(t.genus == g);
      REQUIRE(t.components == 1);
      REQUIRE(t.boundaryLoops == 0);
      REQUIRE(t.reoriented == 0);

      // No two vertices coincide in R³ (the surface is the boundary of a union of boxes, so this is what an embedding
      // failure of the stitching would show).
      std::vector<std::array<double, 3>> pts;
      for (const auto& p : d.positions) pts.push_back({p.x(), p.y(), p.z()});
      std::sort(pts.begin(), pts.end());
      REQUIRE(std::adjacent_find(pts.begin(), pts.end()) == pts.end());

      const IntrinsicTriangulation tri = toTriangulation(d);
      // Every triangle is half of a grid square of side c/N: angles are exactly 45°, 45°, 90°.
      for (double a : allCornerAngles(tri)) {
        const bool ok = std::abs(a - kPi / 4) < kRoundOff || std::abs(a - kPi / 2) < kRoundOff;
        REQUIRE(ok);
      }
      const double area = c * c * (2 * (3 * W - g) + 2 * (W + 3) + 4 * g);
      REQUIRE(std::abs(totalArea(tri) - area) < kRoundOff * area);
      requireGaussBonnet(tri, 2 - 2 * g);
      // Curvature lives only at the box corners: +π/2 at the 8 outer corners, −π/2 at the 8g hole-wall corners.
      int plus = 0, minus = 0;
      for (double k : vertexCurvatures(tri)) {
        if (std::abs(k - kPi / 2) < 1e-12) {
          ++plus;
        } else if (std::abs(k + kPi / 2) < 1e-12) {
          ++minus;
        } else {
          REQUIRE(std::abs(k) < 1e-12);
        }
      }
      REQUIRE(plus == 8);
      REQUIRE(minus == 8 * g);
    }
  }
}

TEST_CASE("knownAnswers against closed forms; mesh areas against them with bounds derived from the construction",
          "[known]") {
  constexpr double eps = 2.220446049250313e-16;
  // Round-off of a mesh area: Σ of F positive face areas, each from Heron's formula to a few ulps: ≤ 16·F·ε relative.
  auto roundOff = [&](const IntrinsicTriangulation& tri) { return 16.0 * tri.mesh.nFaces() * eps; };
  // Topology from the mesh against the closed form, and the total curvature 2πχ to round-off (V angle sums of a few
  // ulps of 2π each: 8·V·ε·2π).
  auto checkTopology = [&](const MeshData& d, const KnownAnswers& known, int chi, int genus, int loops) {
    CAPTURE(d.source);
    CHECK(known.eulerCharacteristic == chi);
    CHECK(known.genus == genus);
    CHECK(known.boundaryLoops == loops);
    const Topology t = topologyOf(d);
    CHECK(t.chi == chi);
    CHECK(t.genus == genus);
    CHECK(t.boundaryLoops == loops);
    const IntrinsicTriangulation tri = toTriangulation(d);
    const CurvatureTotals totals = curvatureTotals(tri);
    CHECK(std::abs(totals.interiorDeficit + totals.boundaryTurning - 2 * kPi * chi) <=
          8.0 * tri.mesh.nVertices() * eps * 2 * kPi);
  };

  SECTION("icosphere: 4πR², the inscribed polyhedron below it by at most Σ A_f ρ_f²/(R² − ρ_f²)") {
    const double R = 0.8;
    const IcosphereOptions ico{6, R};
    const KnownAnswers known = knownAnswers(ico);
    CHECK(std::abs(known.area - 4 * kPi * R * R) <= 4 * eps * known.area);
    CHECK_FALSE(known.areaIsExact);
    const MeshData d = makeIcosphere(ico);
    checkTopology(d, known, 2, 0, 0);
    // The polyhedron is convex and inscribed, so its area is below the sphere's (Cauchy: surface area is monotone
    // under inclusion of convex bodies). Each face f lies in a plane at distance d_f = √(R² − ρ_f²) from the centre
    // (ρ_f its circumradius); radial projection onto the sphere has area factor R² d_f / |x|³ ≤ R²/d_f², so the
    // spherical triangles it tiles the sphere with satisfy A_s ≤ A_f R²/(R² − ρ_f²). Hence
    //   Σ A_f < 4πR² ≤ Σ A_f R²/(R² − ρ_f²),
    // an O(h²) bracket computed from the mesh itself.
    const IntrinsicTriangulation tri = toTriangulation(d);
    double area = 0, upper = 0;
    for (int f = 0; f < tri.mesh.nFaces(); ++f) {
      const double a = faceArea(tri, f), rho = faceCircumradius(tri, f);
      area += a;
      upper += a * R * R / (R * R - rho * rho);
    }
    const double sphere = 4 * kPi * R * R;
    INFO("deficit " << (sphere - area) / sphere << ", bracket " << (upper - area) / sphere);
    CHECK(area < sphere);
    CHECK(sphere <= upper * (1 + roundOff(tri)));
    CHECK(std::abs(totalArea(tri) - area) <= roundOff(tri) * area);
  }

  SECTION("torus of revolution: 4π²Rr, the mesh area converging at order 2 and extrapolating to it") {
    TorusOptions o;
    o.majorRadius = 1.0;
    o.minorRadius = 0.4;
    const double exact = 4 * kPi * kPi * o.majorRadius * o.minorRadius;
    CHECK(std::abs(knownAnswers(o).area - exact) <= 4 * eps * exact);
    CHECK_FALSE(knownAnswers(o).areaIsExact);
    // Grids refined by 2 at fixed n/m = R/r: the area A(h) = A − c h² + O(h⁴) (the triangulation is symmetric under
    // (u, v) → (−u, −v), so no odd powers). Order fitted over three levels; the Richardson value (4A(h/2) − A(h))/3
    // then has an O(h⁴) error, bounded by the difference of two successive Richardson values (which falls by 16).
    std::vector<double> h, err, areas;
    for (int k : {1, 2, 4, 8}) {
      o.n = 25 * k;
      o.m = 10 * k;
      const MeshData d = makeTorus(o);
      if (k == 4) checkTopology(d, knownAnswers(o), 0, 1, 0);
      areas.push_back(totalArea(toTriangulation(d)));
      h.push_back(1.0 / k);
      err.push_back(exact - areas.back());
    }
    const double order = fitLogLogSlope(h, err);
    const double r1 = (4 * areas[2] - areas[1]) / 3, r2 = (4 * areas[3] - areas[2]) / 3;
    INFO("errors " << err[0] << " … " << err[3] << ", order " << order << ", Richardson " << r1 - exact << ", "
                   << r2 - exact);
    for (double e : err) CHECK(e > 0);
    CHECK(order > 1.95);
    CHECK(order < 2.05);
    // With r = A + d h⁴ + O(h⁶): r1 − A = 16 (r2 − A) to leading order, so |r2 − A| = |r1 − r2|/15; a factor 2 for the
    // O(h⁶) terms.
    CHECK(std::abs(r2 - exact) <= 2 * std::abs(r2 - r1) / 15);
  }

  SECTION("genus-g slab: cellSize²·(2(3W − g) + 2(W + 3) + 4g) exactly") {
    GenusSurfaceOptions o;
    o.genus = 3;
    o.resolution = 2;
    o.cellSize = 1.3;
    const int W = 2 * o.genus + 1;
    const double exact = o.cellSize * o.cellSize * (2 * (3 * W - o.genus) + 2 * (W + 3) + 4 * o.genus);  // 68·1.69
    CHECK(std::abs(knownAnswers(o).area - exact) <= 4 * eps * exact);
    CHECK(knownAnswers(o).areaIsExact);
    const MeshData d = makeGenusSurface(o);
    checkTopology(d, knownAnswers(o), 2 - 2 * o.genus, o.genus, 0);
    const IntrinsicTriangulation tri = toTriangulation(d);
    CHECK(std::abs(totalArea(tri) - exact) <= roundOff(tri) * exact);
  }

  SECTION("disk: πR²; the mesh is the inscribed 6N-gon, 3N R² sin(π/3N), below πR² by at most πR²(π/3N)²/6") {
    const DiskOptions o{40, 2.0};
    const double R = o.radius, N = o.rings;
    CHECK(std::abs(knownAnswers(o).area - kPi * R * R) <= 4 * eps * kPi * R * R);
    CHECK_FALSE(knownAnswers(o).areaIsExact);
    const MeshData d = makeDisk(o);
    checkTopology(d, knownAnswers(o), 1, 0, 1);
    const IntrinsicTriangulation tri = toTriangulation(d);
    const double polygon = 3 * N * R * R * std::sin(kPi / (3 * N));
    CHECK(std::abs(totalArea(tri) - polygon) <= roundOff(tri) * polygon);
    // sin x ≥ x − x³/6: 0 < πR² − polygon ≤ πR² x²/6, x = π/3N.
    const double x = kPi / (3 * N);
    CHECK(polygon < kPi * R * R);
    CHECK(kPi * R * R - polygon <= kPi * R * R * x * x / 6);
  }

  SECTION("annulus: π(r2² − r1²); the mesh is the outer n-gon minus the inner one, (n/2) sin(2π/n)(r2² − r1²)") {
    AnnulusOptions o;
    o.rings = 30;
    const double r1 = o.innerRadius, r2 = o.outerRadius;
    const double exact = kPi * (r2 * r2 - r1 * r1);
    CHECK(std::abs(knownAnswers(o).area - exact) <= 4 * eps * exact);
    CHECK_FALSE(knownAnswers(o).areaIsExact);
    // n = max(3, round(2πN / ln(r2/r1))), written here.
    const int n = std::max(3, static_cast<int>(std::lround(2 * kPi * o.rings / std::log(r2 / r1))));
    CHECK(annulusRingVertexCount(o) == n);
    const MeshData d = makeAnnulus(o);
    checkTopology(d, knownAnswers(o), 0, 0, 2);
    const IntrinsicTriangulation tri = toTriangulation(d);
    const double polygons = 0.5 * n * std::sin(2 * kPi / n) * (r2 * r2 - r1 * r1);
    CHECK(std::abs(totalArea(tri) - polygons) <= roundOff(tri) * polygons);
    // (n/2) sin θ = π sin θ/θ with θ = 2π/n: 0 < exact − polygons ≤ exact θ²/6.
    const double theta = 2 * kPi / n;
    CHECK(polygons < exact);
    CHECK(exact - polygons <= exact * theta * theta / 6);
  }

  SECTION("flat torus: |Im(ω̄1 ω2)| exactly, with every angle sum 2π") {
    FlatTorusOptions o;
    o.omega1 = {1.5, 0.2};
    o.omega2 = {-0.4, 1.1};
    const double exact = 1.5 * 1.1 - 0.2 * (-0.4);  // 1.73
    CHECK(std::abs(knownAnswers(o).area - exact) <= 4 * eps * exact);
    CHECK(knownAnswers(o).areaIsExact);
    const MeshData d = makeFlatTorus(o);
    checkTopology(d, knownAnswers(o), 0, 1, 0);
    const IntrinsicTriangulation tri = toTriangulation(d);
    CHECK(std::abs(totalArea(tri) - exact) <= roundOff(tri) * exact);
  }
}

TEST_CASE("genus surface: 10⁶ faces at g = 2, N = 100", "[genus][size]") {
  GenusSurfaceOptions o;
  o.genus = 2;
  o.resolution = 100;
  const MeshData d = makeGenusSurface(o);
  REQUIRE(d.faces.size() == 1000000u);  // 100 N² for g = 2
}

TEST_CASE("genus surface: bad parameters are named", "[genus][errors]") {
  GenusSurfaceOptions o;
  o.resolution = 0;
  REQUIRE_THROWS_WITH(makeGenusSurface(o), Catch::Contains("resolution") && Catch::Contains("found 0"));
  o = GenusSurfaceOptions{};
  o.genus = -1;
  REQUIRE_THROWS_WITH(makeGenusSurface(o), Catch::Contains("genus") && Catch::Contains("found -1"));
  o = GenusSurfaceOptions{};
  o.cellSize = std::nan("");
  REQUIRE_THROWS_WITH(makeGenusSurface(o), Catch::Contains("cell size"));
}

// =====================================================================================================================
// Disk and annulus
// =====================================================================================================================

TEST_CASE("disk: counts, one boundary loop, counter-clockwise, angle bound, flat interior", "[disk]") {
  for (int N : {1, 2, 4, 8, 16, 32}) {
    const double R = 1.0;
    const MeshData d = makeDisk({N, R});
    CAPTURE(N);
    const Topology t = topologyOf(d);
    REQUIRE(t.vertices == 3 * N * (N + 1) + 1);
    REQUIRE(t.faces == 6 * N * N);
    REQUIRE(t.edges == 9 * N * N + 3 * N);
    REQUIRE(t.chi == 1);
    REQUIRE(t.genus == 0);
    REQUIRE(t.boundaryLoops == 1);
    REQUIRE(t.components == 1);
    REQUIRE(t.reoriented == 0);
    for (int f = 0; f < static_cast<int>(d.faces.size()); ++f) REQUIRE(signedAreaXY(d, f) > 0);
    const HalfedgeMesh mesh = HalfedgeMesh::fromFaces(d.faces, d.nVertices);
    REQUIRE(mesh.boundaryLoops().at(0).size() == static_cast<std::size_t>(6 * N));

    const IntrinsicTriangulation tri = toTriangulation(d);
    // The rings are the hexagonal lattice's hexagons mapped onto circles keeping their angular spacing; that map's
    // anisotropy is bounded by the hexagon's circumradius/inradius = 2/√3, so angles stay away from 0 and 180° at
    // every N (equilateral at N = 1; the worst triangles sit at the sector boundaries and tend to 44.1°–90°).
    REQUIRE(minCornerAngle(tri) > 40 * kDeg);
    REQUIRE(maxCornerAngle(tri) < 95 * kDeg);
    // Counter-clockwise faces tiling the inscribed regular 6N-gon: the area is exactly the polygon's.
    const double polygon = 3 * N * R * R * std::sin(kPi / (3 * N));
    REQUIRE(std::abs(totalArea(tri) - polygon) < kRoundOff);
    requireGaussBonnet(tri, 1);
    const auto K = vertexCurvatures(tri);
    const HalfedgeMesh& m = tri.mesh;
    double boundaryTurning = 0;
    for (int v = 0; v < m.nVertices(); ++v) {
      if (m.isBoundaryVertex(v)) {
        boundaryTurning += K[v];
      } else {
        REQUIRE(std::abs(K[v]) < 1e-12);  // planar: every interior angle sum is 2π
      }
    }
    REQUIRE(std::abs(boundaryTurning - 2 * kPi) < 1e-10);
  }
}

TEST_CASE("disk: area converges to πR² at order 2", "[disk][convergence]") {
  std::vector<double> h, err;
  for (int N : {4, 8, 16, 32, 64}) {
    const IntrinsicTriangulation tri = toTriangulation(makeDisk({N, 1.0}));
    h.push_back(meanEdgeLength(tri));
    err.push_back(kPi - totalArea(tri));
  }
  const double order = fitLogLogSlope(h, err);
  CAPTURE(order);
  REQUIRE(std::abs(order - 2) < 0.05);
}

TEST_CASE("annulus: counts, two boundary loops, angle bound, exact and converging area", "[annulus]") {
  for (double r1 : {0.5, 0.1}) {
    const double r2 = 1.0;
    std::vector<double> h, err;
    for (int N : {2, 4, 8, 16, 32}) {
      AnnulusOptions o;
      o.innerRadius = r1;
      o.outerRadius = r2;
      o.rings = N;
      const int n = annulusRingVertexCount(o);
      CAPTURE(r1, N, n);
      REQUIRE(n == std::max(3, static_cast<int>(std::lround(2 * kPi * N / std::log(r2 / r1)))));
      const MeshData d = makeAnnulus(o);
      const Topology t = topologyOf(d);
      REQUIRE(t.vertices == n * (N + 1));
      REQUIRE(t.faces == 2 * n * N);
      REQUIRE(t.edges == 3 * n * N + n);
      REQUIRE(t.chi == 0);
      REQUIRE(t.boundaryLoops == 2);
      REQUIRE(t.genus == 0);
      REQUIRE(t.components == 1);
      REQUIRE(t.reoriented == 0);
      for (int f = 0; f < static_cast<int>(d.faces.size()); ++f) REQUIRE(signedAreaXY(d, f) > 0);
      const IntrinsicTriangulation tri = toTriangulation(d);
      // Cells are exp-images of squares of side s = ln(r2/r1)/N; exp is conformal, so a cell is a square up to a
      // relative O(s) and its halves have angles 45°, 45°, 90° up to O(s). At s ≤ 0.1 the deviation is < 5°.
      if (std::log(r2 / r1) / N <= 0.1) {
        REQUIRE(minCornerAngle(tri) > 40 * kDeg);
        REQUIRE(maxCornerAngle(tri) < 95 * kDeg);
      }
      const double polygons = 0.5 * n * std::sin(2 * kPi / n) * (r2 * r2 - r1 * r1);
      REQUIRE(std::abs(totalArea(tri) - polygons) < kRoundOff);
      requireGaussBonnet(tri, 0);
      h.push_back(meanEdgeLength(tri));
      err.push_back(kPi * (r2 * r2 - r1 * r1) - totalArea(tri));
    }
    const double order = fitLogLogSlope(h, err);
    CAPTURE(r1, order);
    REQUIRE(std::abs(order - 2) < 0.1);
  }
}

TEST_CASE("disk and annulus: bad parameters are named", "[disk][annulus][errors]") {
  REQUIRE_THROWS_WITH(makeDisk({0, 1.0}), Catch::Contains("rings") && Catch::Contains("found 0"));
  REQUIRE_THROWS_WITH(makeDisk({4, -1.0}), Catch::Contains("radius") && Catch::Contains("-1"));
  AnnulusOptions o;
  o.innerRadius = 1.0;
  o.outerRadius = 0.5;
  REQUIRE_THROWS_WITH(makeAnnulus(o), Catch::Contains("0 < r1 < r2") && Catch::Contains("r1=1"));
}

// =====================================================================================================================
// Flat torus
// =====================================================================================================================

TEST_CASE("flat torus: counts, genus 1 at every n (Δ-complex for n < 3), zero curvature, lattice area, Delaunay",
          "[flat-torus]") {
  const std::complex<double> hexagonal = std::polar(1.0, kPi / 3);
  const std::vector<std::pair<std::complex<double>, std::complex<double>>> lattices = {
      {{1, 0}, {0, 1}}, {{1, 0}, hexagonal}, {{2, 0.5}, {0.3, 0.9}}, {{1, 0}, {2.7, 0.4}}, {{0, 1}, {1, 0}}};
  for (const auto& [w1, w2] : lattices) {
    for (int n : {1, 2, 3, 8, 20}) {
      FlatTorusOptions o;
      o.omega1 = w1;
      o.omega2 = w2;
      o.n = n;
      const MeshData d = makeFlatTorus(o);
      CAPTURE(w1.real(), w1.imag(), w2.real(), w2.imag(), n);
      REQUIRE(d.positions.empty());
      REQUIRE(d.edges.size() == static_cast<std::size_t>(3 * n * n));
      REQUIRE(d.cornerEdges.empty() == (n >= 3));
      const Topology t = topologyOf(d);
      REQUIRE(t.vertices == n * n);
      REQUIRE(t.edges == 3 * n * n);
      REQUIRE(t.faces == 2 * n * n);
      REQUIRE(t.chi == 0);
      REQUIRE(t.genus == 1);
      REQUIRE(t.boundaryLoops == 0);
      REQUIRE(t.components == 1);

      const IntrinsicTriangulation tri = toTriangulation(d);
      for (double k : vertexCurvatures(tri)) REQUIRE(std::abs(k) < 1e-12);
      const double area = std::abs(std::imag(std::conj(w1) * w2));
      REQUIRE(std::abs(totalArea(tri) - area) < kRoundOff * area);
      requireGaussBonnet(tri, 0);
      for (int e = 0; e < tri.mesh.nEdges(); ++e) REQUIRE(delaunayMargin(tri, e) > -1e-12);
    }
  }
}

TEST_CASE("flat torus: lattice reduction keeps the lattice; the given basis can be kept", "[flat-torus]") {
  const std::complex<double> w1{2, 0.5}, w2{0.3, 0.9};
  const auto [r1, r2] = reduceLatticeBasis(w1, w2);
  REQUIRE(std::abs(r1) <= std::abs(r2));
  REQUIRE(std::abs(r2) <= std::abs(r2 + r1) * (1 + 1e-15));
  REQUIRE(std::abs(r2) <= std::abs(r2 - r1) * (1 + 1e-15));
  // Same lattice: the reduced vectors have integer coordinates in the given basis, and the covolume is unchanged.
  const double det = std::imag(std::conj(w1) * w2);
  for (const auto& z : {r1, r2}) {
    const double a = std::imag(std::conj(z) * w2) / det, b = std::imag(std::conj(w1) * z) / det;  // z = a·w1 + b·w2
    REQUIRE(std::abs(a - std::round(a)) < 1e-12);
    REQUIRE(std::abs(b - std::round(b)) < 1e-12);
  }
  REQUIRE(std::abs(std::abs(std::imag(std::conj(r1) * r2)) - std::abs(det)) < 1e-14);

  FlatTorusOptions o;
  o.omega1 = w1;
  o.omega2 = w2;
  o.n = 4;
  o.reduceBasis = false;
  const MeshData d = makeFlatTorus(o);
  const double longest = std::max_element(d.edges.begin(), d.edges.end(), [](const auto& x, const auto& y) {
                           return x.length < y.length;
                         })->length;
  REQUIRE(std::abs(longest - std::abs(w1) / 4) < 1e-15);  // the given, unreduced period is an edge
  const IntrinsicTriangulation tri = toTriangulation(d);
  for (double k : vertexCurvatures(tri)) REQUIRE(std::abs(k) < 1e-12);
  REQUIRE(std::abs(totalArea(tri) - std::abs(det)) < kRoundOff);
  int nonDelaunay = 0;
  for (int e = 0; e < tri.mesh.nEdges(); ++e) nonDelaunay += delaunayMargin(tri, e) < 0;
  REQUIRE(nonDelaunay > 0);  // which is why the reduction is the default
}

TEST_CASE("flat torus: dependent periods are rejected", "[flat-torus][errors]") {
  FlatTorusOptions o;
  o.omega1 = {1, 1};
  o.omega2 = {-2, -2};
  REQUIRE_THROWS_WITH(makeFlatTorus(o), Catch::Contains("linearly dependent"));
  o = FlatTorusOptions{};
  o.n = 0;
  REQUIRE_THROWS_WITH(makeFlatTorus(o), Catch::Contains("found 0"));
}

// =====================================================================================================================
// Random metric perturbation
// =====================================================================================================================

namespace {

double relativeSlack(double a, double b, double c) {
  return std::min({b + c - a, a + c - b, a + b - c}) / (a + b + c);
}

// Checks the perturbation contract on `d` (already perturbed) against the lengths `before` of the same edges.
void requirePerturbationContract(const MeshData& d, const std::vector<double>& before, double amplitude,
                                 const PerturbReport& report, int chi) {
  REQUIRE(d.edges.size() == before.size());
  double maxChange = 0;
  for (std::size_t e = 0; e < before.size(); ++e) {
    const double change = std::abs(d.edges[e].length / before[e] - 1);
    REQUIRE(change <= amplitude * (1 + 1e-15));
    maxChange = std::max(maxChange, change);
  }
  REQUIRE(report.maxRelativeChange == Approx(maxChange).epsilon(1e-14));
  const IntrinsicTriangulation tri = toTriangulation(d);
  REQUIRE(tri.edgeLengths.size() == before.size());
  // The metric is valid as read back by toTriangulation (which validates it); the margin itself is checked face by face
  // against the unperturbed slack in the next test case.
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    const double a = tri.length(3 * f), b = tri.length(3 * f + 1), c = tri.length(3 * f + 2);
    REQUIRE(relativeSlack(a, b, c) > 0);
  }
  requireGaussBonnet(tri, chi);
}

std::vector<double> lengthsOf(const MeshData& d) {
  std::vector<double> l;
  for (const auto& e : d.edges) l.push_back(e.length);
  return l;
}

}  // namespace

TEST_CASE("perturbLengths: every triangle inequality kept with its margin, changes within the amplitude", "[perturb]") {
  for (double amplitude : {0.05, 0.3, 0.95}) {
    CAPTURE(amplitude);
    // Meshes with positions: the unperturbed lengths are what perturbing by 0 gives.
    std::vector<std::pair<MeshData, int>> meshes;
    meshes.push_back({makeIcosphere({3, 1.0}), 2});
    meshes.push_back({makeTorus({}), 0});
    GenusSurfaceOptions go;
    go.genus = 2;
    go.resolution = 3;
    meshes.push_back({makeGenusSurface(go), -2});
    meshes.push_back({makeDisk({6, 1.0}), 1});
    meshes.push_back({makeFlatTorus({}), 0});  // edges given, no positions
    FlatTorusOptions one;
    one.n = 1;
    meshes.push_back({makeFlatTorus(one), 0});  // one vertex, three self-loops
    for (auto& [d, chi] : meshes) {
      CAPTURE(d.source);
      MeshData zero = d;
      perturbLengths(zero, 0.0, 1);
      const std::vector<double> before = lengthsOf(zero);
      MeshData p = d;
      const PerturbReport report = perturbLengths(p, amplitude, 12345);
      REQUIRE(report.edges == static_cast<int>(before.size()));
      requirePerturbationContract(p, before, amplitude, report, chi);
      // The perturbation really happens: on ≥ 3 edges some change exceeds a third of the amplitude.
      if (before.size() >= 3) REQUIRE(report.maxRelativeChange > amplitude / 3);
      // Same seed, same metric; another seed, another metric.
      MeshData again = d, other = d;
      perturbLengths(again, amplitude, 12345);
      perturbLengths(other, amplitude, 54321);
      REQUIRE(lengthsOf(again) == lengthsOf(p));
      REQUIRE(lengthsOf(other) != lengthsOf(p));
    }
  }
}

TEST_CASE("perturbLengths: the margin is enforced face by face and large amplitudes are shrunk", "[perturb]") {
  // Right isosceles triangles have relative slack (2 − √2)/(2 + √2) = 0.17; at amplitude 0.95 the draw breaks many.
  GenusSurfaceOptions go;
  go.genus = 1;
  go.resolution = 4;
  MeshData d = makeGenusSurface(go);
  MeshData zero = d;
  perturbLengths(zero, 0.0, 0);
  const PerturbReport report = perturbLengths(d, 0.95, 7);
  REQUIRE(report.shrunkEdges > 0);
  REQUIRE(report.passes >= 2);
  // Face sides → edge records by endpoint pair (this mesh is simplicial).
  std::map<std::pair<int, int>, int> id;
  for (std::size_t e = 0; e < d.edges.size(); ++e)
    id[{std::min(d.edges[e].v0, d.edges[e].v1), std::max(d.edges[e].v0, d.edges[e].v1)}] = static_cast<int>(e);
  for (const auto& f : d.faces) {
    double after[3], before[3];
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      const int e = id.at({std::min(a, b), std::max(a, b)});
      after[k] = d.edges[e].length;
      before[k] = zero.edges[e].length;
    }
    const double required = std::min(kPerturbMinRelativeSlack, relativeSlack(before[0], before[1], before[2]) / 2);
    REQUIRE(relativeSlack(after[0], after[1], after[2]) >= required);
  }
}

TEST_CASE("perturbLengths: a flat torus becomes a genuine cone metric", "[perturb]") {
  MeshData d = makeFlatTorus({});
  perturbLengths(d, 0.1, 3);
  const IntrinsicTriangulation tri = toTriangulation(d);
  double maxK = 0;
  for (double k : vertexCurvatures(tri)) maxK = std::max(maxK, std::abs(k));
  REQUIRE(maxK > 1e-3);        // angle defects appear at the vertices ...
  requireGaussBonnet(tri, 0);  // ... and still sum to 2πχ = 0
}

TEST_CASE("perturbLengths: bad input is named", "[perturb][errors]") {
  MeshData d = makeIcosphere({1, 1.0});
  REQUIRE_THROWS_WITH(perturbLengths(d, 1.0, 0), Catch::Contains("amplitude") && Catch::Contains("[0, 1)"));
  REQUIRE_THROWS_WITH(perturbLengths(d, -0.1, 0), Catch::Contains("amplitude"));
  MeshData noGeometry = d;
  noGeometry.positions.clear();
  REQUIRE_THROWS_WITH(perturbLengths(noGeometry, 0.1, 0), Catch::Contains("nothing to take lengths from"));
  MeshData bad = makeFlatTorus({});
  bad.edges[0].length = 10;  // ten times the other sides of its two faces
  REQUIRE_THROWS_WITH(perturbLengths(bad, 0.1, 0),
                      Catch::Contains("face") && Catch::Contains("triangle inequality") && Catch::Contains("10"));
  MeshData nan = makeFlatTorus({});
  nan.edges[5].length = std::nan("");
  REQUIRE_THROWS_WITH(perturbLengths(nan, 0.1, 0), Catch::Contains("edge 5"));
  FlatTorusOptions three;
  three.n = 3;
  MeshData missing = makeFlatTorus(three);  // simplicial, so sides are matched to records by endpoints
  const EdgeRecord dropped = missing.edges.back();
  missing.edges.pop_back();
  REQUIRE_THROWS_WITH(perturbLengths(missing, 0.1, 0),
                      Catch::Contains("side") && Catch::Contains("no edge record") &&
                          (Catch::Contains(std::to_string(dropped.v0) + "-" + std::to_string(dropped.v1)) ||
                           Catch::Contains(std::to_string(dropped.v1) + "-" + std::to_string(dropped.v0))));
}
