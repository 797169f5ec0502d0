// test_uniformization.cpp — T0 → T0* on real meshes of CGAL's data set (genus 0, 1, 2, 3, a disk, an annulus, domains
// with three and four boundary loops): interior angle sums 2π in the background geometry from the lengths as written to
// and read back from PLY, Gauss–Bonnet with the area term, boundary loops concyclic, λ consistent with the Penner
// relation; the flat torus of a torus of revolution against its exact modulus i·r/√(R² − r²), with the order of a
// log–log fit; an ellipsoid's chart discretization against its conformal latitude and conformal factor (order 2); a
// planar annulus (already a circle domain) reproduced exactly; inadmissible inputs reported.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Sparse>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_registry.h"

#include "support/flat_torus_modulus.h"
#include "support/gauss_bonnet_bound.h"
#include "support/scratch_dir.h"
#include "support/test_meshes.h"

using namespace conformesh::intrinsic;
using conformesh::testing::flatTorusModulus;

namespace {

std::string dataFile(const std::string& name) {
  return std::string(CONFORMESH_TEST_DATA_DIR) + "/" + name;
}

// Writes T0* with λ to PLY and reads it back: the checks below use only what a user of the file would see.
IntrinsicTriangulation roundTrip(const Uniformization& u, const std::string& name) {
  MeshData data = fromTriangulation(u.uniform);
  data.vertexProperties["lambda"] = u.lambda;
  // In the test process's own scratch folder (removed at exit), not the shared data folder.
  const std::string path = (conformesh::testing::scratchDir() / ("uniformized-" + name + ".ply")).string();
  writeMesh(data, path);
  const MeshData back = readMesh(path);
  std::remove(path.c_str());
  REQUIRE(back.background == u.uniform.background);
  REQUIRE(back.vertexProperties.count("lambda") == 1);
  return toTriangulation(back);
}

double maxInteriorAngleError(const IntrinsicTriangulation& tri) {
  const std::vector<double> sums = angleSums(tri);
  double worst = 0;
  for (int v = 0; v < tri.mesh.nVertices(); ++v)
    if (!tri.mesh.isBoundaryVertex(v)) worst = std::max(worst, std::abs(sums[v] - 2 * M_PI));
  return worst;
}

// Relative radius deviation of each boundary loop of a flat triangulation laid out in the plane: circle through three
// spread vertices, then max | |p − c| − R | / R over the loop.
std::vector<std::pair<double, double>> loopCircles(const IntrinsicTriangulation& tri) {
  const std::vector<Eigen::Vector2d> p = layoutFlat(tri);
  std::vector<std::pair<double, double>> out;  // (radius, relative deviation)
  for (const auto& loop : tri.mesh.boundaryLoops()) {
    const int n = static_cast<int>(loop.size());
    const Eigen::Vector2d A = p[tri.mesh.tail(loop[0])], B = p[tri.mesh.tail(loop[n / 3])],
                          C = p[tri.mesh.tail(loop[2 * n / 3])];
    const double d = 2 * (A.x() * (B.y() - C.y()) + B.x() * (C.y() - A.y()) + C.x() * (A.y() - B.y()));
    const Eigen::Vector2d c(
        (A.squaredNorm() * (B.y() - C.y()) + B.squaredNorm() * (C.y() - A.y()) + C.squaredNorm() * (A.y() - B.y())) / d,
        (A.squaredNorm() * (C.x() - B.x()) + B.squaredNorm() * (A.x() - C.x()) + C.squaredNorm() * (B.x() - A.x())) /
            d);
    const double R = (A - c).norm();
    double dev = 0;
    for (int h : loop) dev = std::max(dev, std::abs((p[tri.mesh.tail(h)] - c).norm() - R) / R);
    out.emplace_back(R, dev);
  }
  return out;
}

// Checks the Penner relation c*_ij = e^{−(λ_i+λ_j)/2} c_ij (λ = −w) on every edge whose endpoints are unchanged and
// which lies in no face touched by a flip (such an edge was never flipped).
void checkLambda(const IntrinsicTriangulation& input, const Uniformization& u) {
  std::vector<char> touched(input.mesh.nFaces(), 0);
  for (const PtolemyFlip& f : u.correspondence.flips()) touched[f.faceA] = touched[f.faceB] = 1;
  int checked = 0;
  double worst = 0;
  for (int e = 0; e < input.mesh.nEdges(); ++e) {
    const int h = u.uniform.mesh.edgeHalfedge(e), h0 = input.mesh.edgeHalfedge(e);
    if (touched[HalfedgeMesh::face(h)] ||
        (u.uniform.mesh.twin(h) != kInvalid && touched[HalfedgeMesh::face(u.uniform.mesh.twin(h))]))
      continue;
    const int a = u.uniform.mesh.tail(h), b = u.uniform.mesh.tip(h);
    REQUIRE(((a == input.mesh.tail(h0) && b == input.mesh.tip(h0)) ||
             (b == input.mesh.tail(h0) && a == input.mesh.tip(h0))));
    const double predicted =
        std::exp(-0.5 * (u.lambda[a] + u.lambda[b])) * pennerFromLength(input.background, input.edgeLengths[e]);
    worst = std::max(worst, std::abs(pennerFromLength(u.uniform.background, u.uniform.edgeLengths[e]) / predicted - 1));
    ++checked;
  }
  CHECK(checked > 0);
  // The genus-0 chords come from positions on the sphere (layout, stereographic map, Möbius centring): 1e-9 relative.
  CHECK(worst < 1e-9);
}

struct Expect {
  const char* file;
  UniformizationTarget target;
  Background background;
  int genus, loops;
};

}  // namespace

TEST_CASE("real meshes of each topology are uniformized to angle sums 2π, Gauss–Bonnet and circles") {
  const Expect cases[] = {
      {"blobby.off", UniformizationTarget::Sphere, Background::Spherical, 0, 0},
      {"handle.off", UniformizationTarget::Sphere, Background::Spherical, 0, 0},
      // The cow's tail has conformal factors ~10⁻¹⁵: its lengths come from the Penner form (pennerLengths).
      {"cow.off", UniformizationTarget::Sphere, Background::Spherical, 0, 0},
      {"knot1.off", UniformizationTarget::FlatTorus, Background::Euclidean, 1, 0},
      {"double-torus-example.off", UniformizationTarget::Hyperbolic, Background::Hyperbolic, 2, 0},
      {"3torus.off", UniformizationTarget::Hyperbolic, Background::Hyperbolic, 3, 0},
      {"elephant.off", UniformizationTarget::Hyperbolic, Background::Hyperbolic, 3, 0},
      {"patch-01.off", UniformizationTarget::CircleDomain, Background::Euclidean, 0, 1},
      {"mech-holes-shark.off", UniformizationTarget::CircleDomain, Background::Euclidean, 0, 4},
      {"head.off", UniformizationTarget::CircleDomain, Background::Euclidean, 0, 3},
  };
  for (const Expect& c : cases) {
    SECTION(c.file) {
      const IntrinsicTriangulation input = toTriangulation(readMesh(dataFile(c.file)));
      const Uniformization u = uniformize(input);
      CHECK(u.report.target == c.target);
      CHECK(u.report.genus == c.genus);
      CHECK(u.report.boundaryLoops == c.loops);
      CHECK(u.uniform.background == c.background);
      const IntrinsicTriangulation out = roundTrip(u, c.file);
      INFO(c.file << ": Newton steps " << u.report.newtonSteps << ", flips " << u.report.flips);
      CHECK(maxInteriorAngleError(out) < 1e-10);
      const CurvatureTotals totals = curvatureTotals(out);
      CHECK(std::abs(totals.gaussBonnetResidual) < 1e-9);
      CHECK(countNonDelaunayEdges(out) == 0);
      const double chi = 2.0 - 2 * c.genus - c.loops;
      if (c.target == UniformizationTarget::Sphere) CHECK(totalArea(out) == Approx(4 * M_PI).epsilon(1e-10));
      if (c.target == UniformizationTarget::FlatTorus) CHECK(totalArea(out) == Approx(1.0).epsilon(1e-12));
      if (c.target == UniformizationTarget::Hyperbolic) CHECK(totalArea(out) == Approx(-2 * M_PI * chi).epsilon(1e-9));
      if (c.target == UniformizationTarget::CircleDomain) {
        const auto circles = loopCircles(out);
        REQUIRE(static_cast<int>(circles.size()) == c.loops);
        double outer = 0;
        for (const auto& [R, dev] : circles) {
          CHECK(dev < 1e-8);
          outer = std::max(outer, R);
        }
        CHECK(outer == Approx(1.0).epsilon(1e-8));  // the longest loop is the unit circle
      }
      checkLambda(input, u);
    }
  }
}

TEST_CASE("a planar annulus bounded by concentric circles is its own circle domain") {
  // Every interior angle sum of the generated annulus is already 2π and its boundary polygons are inscribed in
  // circles, so the solution is the input up to scale: λ is constant and no flip is needed.
  const MeshData data = makeAnnulus({0.5, 1.0, 6});
  const IntrinsicTriangulation input = toTriangulation(data);
  const Uniformization u = uniformize(input);
  CHECK(u.report.target == UniformizationTarget::CircleDomain);
  double lo = 1e300, hi = -1e300;
  for (double l : u.lambda) {
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  CHECK(hi - lo < 1e-10);
  CHECK(std::exp(-lo) == Approx(1.0).epsilon(1e-10));  // outer radius 1 already: lengths scale by e^{w} = e^{−λ}
}

TEST_CASE("a torus of revolution converges to the flat torus of modulus i r/sqrt(R^2 - r^2)") {
  const double R = 1.0, r = 0.4;
  const double a = r / std::sqrt(R * R - r * r);
  const double expected = std::max(a, 1 / a);  // Im of the reduced modulus (the period ratio ≥ 1)
  std::vector<double> logH, logErr;
  for (int k : {1, 2, 4}) {
    TorusOptions options;
    options.majorRadius = R;
    options.minorRadius = r;
    options.n = 25 * k;
    options.m = 10 * k;
    const IntrinsicTriangulation input = toTriangulation(makeTorus(options));
    const Uniformization u = uniformize(input);
    const std::complex<double> tau = flatTorusModulus(u.uniform);
    const double err = std::abs(tau - std::complex<double>(0, expected));
    logH.push_back(std::log(2 * M_PI * R / options.n));
    logErr.push_back(std::log(err));
  }
  const double mx = (logH[0] + logH[1] + logH[2]) / 3, my = (logErr[0] + logErr[1] + logErr[2]) / 3;
  double sxy = 0, sxx = 0;
  for (int i = 0; i < 3; ++i) {
    sxy += (logH[i] - mx) * (logErr[i] - my);
    sxx += (logH[i] - mx) * (logH[i] - mx);
  }
  const double order = sxy / sxx;
  INFO("modulus errors " << std::exp(logErr[0]) << " " << std::exp(logErr[1]) << " " << std::exp(logErr[2])
                         << ", order " << order);
  CHECK(order > 1.8);
  // Regression bound, calibrated on an earlier run (2.7e-3 at 100 × 40, b32757c), not derived; the order above is
  // the mathematical claim.
  CHECK(std::exp(logErr[2]) < 5e-3);
}

TEST_CASE("an ellipsoid of revolution converges to its conformal latitude at order 2, map and conformal factor") {
  // Oblate spheroid x² + y² + z²/c² = 1 (a = 1, c = 0.6), the `ellipsoid` family's chart discretization at
  // resolutions 6, 12, 24, 48 (362 to 23 042 vertices). The exact conformal map to the sphere keeps the longitude and
  // sends the geodetic latitude φ to the conformal latitude χ, asinh(tan χ) = asinh(tan φ) − e atanh(e sin φ),
  // e² = 1 − c² (Karney; GeographicLib's AuxLatitude); its conformal factor, from the parallels' radii ρ = e^λ cos χ,
  // is λ = log(ρ / cos χ). It is balanced (it commutes with the rotations about z and with z → −z), so it agrees with
  // the Möbius-centred discrete map up to a rotation: the map is compared by the rotation-invariant angles between
  // pairs of image points, λ (rotation-invariant) directly.
  // Why not z-scaled icospheres (the earlier version of this test, order 0.4): measured at levels 2–5 the angle error
  // stalls (2.0e-3, 5.0e-4, 2.5e-4, 2.9e-4) and λ's error GROWS (1.1e-3, 1.6e-3, 3.1e-3, 4.7e-3; rotated before
  // scaling: 2.9e-3 to 1.3e-2), with the centring on; without it both are O(0.1). Those meshes are centrally
  // symmetric, so any symmetric centring weights give the same balanced map: the weights are not the cause; the
  // discrete conformal structure of the squashed icosphere does not converge to the ellipsoid's (docs/ricci_flow.md
  // §6).
  const double c = 0.6, e = std::sqrt(1 - c * c);
  const auto metric = makeMetric("ellipsoid", {{"a", 1.0}, {"f", 1 - c}});
  std::vector<double> hs, angleErrors, lambdaErrors;
  for (int resolution : {6, 12, 24, 48}) {
    DiscretizationOptions d;
    d.resolution = resolution;
    const MeshData data = discretizeMetric(*metric, d);
    const IntrinsicTriangulation input = toTriangulation(data);
    const Uniformization u = uniformize(input);
    REQUIRE(u.report.target == UniformizationTarget::Sphere);
    const int n = static_cast<int>(data.positions.size());
    std::vector<Eigen::Vector3d> exact(n);
    double lambdaErr = 0;
    for (int v = 0; v < n; ++v) {
      const Eigen::Vector3d& p = data.positions[v];
      const double rho = std::hypot(p.x(), p.y()), lon = std::atan2(p.y(), p.x());
      const double phi = std::atan2(p.z(), c * c * rho);  // the normal of x² + y² + z²/c² = 1
      const double chi = std::atan(std::sinh(std::asinh(std::tan(phi)) - e * std::atanh(e * std::sin(phi))));
      exact[v] = Eigen::Vector3d(std::cos(chi) * std::cos(lon), std::cos(chi) * std::sin(lon), std::sin(chi));
      if (rho > 1e-9) lambdaErr = std::max(lambdaErr, std::abs(u.lambda[v] - std::log(rho / std::cos(chi))));
    }  // (λ's closed form is 0/0 at the two poles, which are skipped)
    double angleErr = 0;
    const int stride = std::max(1, n / 300);
    for (int i = 0; i < n; i += stride)
      for (int j = i + stride; j < n; j += stride) {
        const double got = std::acos(std::clamp(u.positions[i].dot(u.positions[j]), -1.0, 1.0));
        const double want = std::acos(std::clamp(exact[i].dot(exact[j]), -1.0, 1.0));
        angleErr = std::max(angleErr, std::abs(got - want));
      }
    double h = 0;
    for (double l : input.edgeLengths) h += l;
    hs.push_back(h / input.edgeLengths.size());
    angleErrors.push_back(angleErr);
    lambdaErrors.push_back(lambdaErr);
  }
  const double angleOrder = fitLogLogSlope(hs, angleErrors), lambdaOrder = fitLogLogSlope(hs, lambdaErrors);
  INFO("angle errors " << angleErrors[0] << " " << angleErrors[1] << " " << angleErrors[2] << " " << angleErrors[3]
                       << ", order " << angleOrder << "; lambda errors " << lambdaErrors[0] << " " << lambdaErrors[1]
                       << " " << lambdaErrors[2] << " " << lambdaErrors[3] << ", order " << lambdaOrder);
  // Measured 3.0e-3 … 4.8e-5 (order 1.99) and 2.2e-3 … 3.4e-5 (order 2.00). The chords of a smooth surface differ from
  // its geodesic distances by O(h²) relative, the error the vertex-scaling map inherits on a mesh whose triangles are
  // smooth conformal images of a regular pattern (docs/layout.md §5); 1.8 rejects order 1 (a defect of the map or of λ
  // that shrinks only with h) with room for the coarsest level's pre-asymptotic slope over four levels.
  CHECK(angleOrder > 1.8);
  CHECK(lambdaOrder > 1.8);
}

TEST_CASE("genus 0: link vertices released early when clearly reflex give the sphere of releases at solutions") {
  // The box's grid makes the star repair of its puncture take rounds: faces next to the star degenerate during the
  // first solve, and vertices it adds turn out reflex. λ after Möbius centring is unique (up to rotations, which do not
  // change it), so judging reflex vertices early must not change it beyond the flow tolerance.
  GenusSurfaceOptions box;
  box.genus = 0;
  box.resolution = 27;  // 10 k vertices
  const IntrinsicTriangulation input = toTriangulation(makeGenusSurface(box));
  auto run = [&](double factor, int& earlyStops) {
    UniformizationOptions options;
    options.earlyReflexFactor = factor;
    earlyStops = 0;
    options.progress = [&](const std::string& line) {
      if (line.find("clearly reflex") != std::string::npos) ++earlyStops;
    };
    return uniformize(input, options);
  };
  int early = 0, late = 0;
  const Uniformization a = run(10, early), b = run(0, late);
  INFO("Newton steps " << a.report.newtonSteps << " (early) and " << b.report.newtonSteps << " (at solutions)");
  CHECK(early > 0);
  CHECK(late == 0);
  CHECK(a.report.punctureVertex == b.report.punctureVertex);
  CHECK(a.report.newtonSteps < b.report.newtonSteps);
  double worst = 0;
  for (std::size_t v = 0; v < a.lambda.size(); ++v) worst = std::max(worst, std::abs(a.lambda[v] - b.lambda[v]));
  // Both flows stop below 1e-10 rad; λ responds to the residual through the inverse Laplacian (≈ 10² here).
  CHECK(worst < 1e-8);
  CHECK(maxInteriorAngleError(roundTrip(a, "box-early")) < 1e-10);
  // Möbius centring: the input's area measure (a third of each face's area at its corners) has its centroid at the
  // origin to the tolerance, reached by Newton's method in a few iterations (the fixed step (3/4)c needed 29 here).
  std::vector<double> weight(input.mesh.nVertices(), 0.0);
  for (int f = 0; f < input.mesh.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) weight[input.mesh.faceVertex(f, k)] += faceArea(input, f) / 3;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double total = 0;
  for (std::size_t v = 0; v < weight.size(); ++v) {
    centroid += weight[v] * a.positions[v];
    total += weight[v];
  }
  CHECK((centroid / total).norm() <= UniformizationOptions().centringTolerance);
  CHECK(a.report.centringIterations <= 6);
}

TEST_CASE("uniformize reports inputs it cannot handle") {
  // Two disjoint triangles: two components.
  IntrinsicTriangulation two;
  two.mesh = HalfedgeMesh::fromFaces({{0, 1, 2}, {3, 4, 5}}, 6);
  two.edgeLengths.assign(two.mesh.nEdges(), 1.0);
  CHECK_THROWS_WITH(uniformize(two), Catch::Contains("2 connected components"));
  // A flat torus asked for with a single Newton step does not converge, and says how far it got.
  const IntrinsicTriangulation torus = toTriangulation(makeTorus({}));
  UniformizationOptions options;
  options.flow.maxNewtonSteps = 1;
  CHECK_THROWS_WITH(uniformize(torus, options), Catch::Contains("did not converge") && Catch::Contains("max |"));
}

namespace {

// A triangulated polygon from planar points (faces ccw), Euclidean lengths.
IntrinsicTriangulation planarPolygon(const std::vector<Eigen::Vector2d>& p, const std::vector<std::array<int, 3>>& f) {
  IntrinsicTriangulation t;
  t.mesh = HalfedgeMesh::fromFaces(f, static_cast<int>(p.size()));
  t.edgeLengths.resize(t.mesh.nEdges());
  for (int e = 0; e < t.mesh.nEdges(); ++e) {
    const int h = t.mesh.edgeHalfedge(e);
    t.edgeLengths[e] = (p[t.mesh.tail(h)] - p[t.mesh.tip(h)]).norm();
  }
  return t;
}

// A disk with no interior vertex uniformized: every vertex on the unit circle about the origin (positions) to
// `circleBound`; Gauss–Bonnet Σ (π − Θ_v) = 2π and the flow residual to `angleBound`. Exact inputs (`exact`): also
// each angle sum equal to the inscribed angle of its two neighbours seen from its position (acos of the positions
// resolves it to ~1e-13), and no Newton step (the direct development of uniformization.cpp).
void checkInscribed(const Uniformization& out, bool exact, double angleBound, double circleBound) {
  const IntrinsicTriangulation& t = out.uniform;
  REQUIRE(out.positions.size() == static_cast<std::size_t>(t.mesh.nVertices()));
  for (const Eigen::Vector3d& x : out.positions) CHECK(std::abs(x.head<2>().norm() - 1) < circleBound);
  const std::vector<double> sums = angleSums(t);
  double turning = 0;
  const std::vector<std::vector<int>> loops = t.mesh.boundaryLoops();
  for (int h : loops[0]) {
    const int v = t.mesh.tip(h), p = t.mesh.tail(h), n = t.mesh.tip(t.mesh.nextBoundaryHalfedge(h));
    const Eigen::Vector2d a = out.positions[p].head<2>(), b = out.positions[n].head<2>(),
                          x = out.positions[v].head<2>();
    const double inscribed = std::acos(std::clamp((a - x).normalized().dot((b - x).normalized()), -1.0, 1.0));
    if (exact) CHECK(std::abs(sums[v] - inscribed) < 1e-12);
    turning += M_PI - sums[v];
  }
  CHECK(std::abs(turning - 2 * M_PI) < angleBound);
  CHECK(out.report.maxResidual < angleBound);
  if (exact) CHECK(out.report.newtonSteps == 0);
}

}  // namespace

TEST_CASE("disks with no interior vertex: a triangle is its own circle domain, a quad becomes concyclic") {
  // One right triangle (CGAL's tetra_intersected_by_triangle.off, component 1, in its plane): already inscribed, so
  // the output is the input scaled by 1/R (λ = log R for every vertex, R = hypotenuse/2), angles unchanged.
  const IntrinsicTriangulation triangle =
      planarPolygon({{0, 0}, {std::sqrt(0.5), 0}, {std::sqrt(0.5), 0.1}}, {{{0, 1, 2}}});
  const Uniformization t = uniformize(triangle);
  checkInscribed(t, true, 1e-13, 1e-12);
  for (double lambda : t.lambda) CHECK(std::abs(lambda - std::log(std::sqrt(0.51) / 2)) < 1e-14);
  // A rectangle 1 × 4 (boeing.off's component 1 is a 0.25 × 1.914 one) is cyclic: scaled by 2/√17.
  const Uniformization r = uniformize(planarPolygon({{0, 0}, {4, 0}, {4, 1}, {0, 1}}, {{{0, 1, 2}}, {{0, 2, 3}}}));
  checkInscribed(r, true, 1e-13, 1e-12);
  for (double lambda : r.lambda) CHECK(std::abs(lambda - std::log(std::sqrt(17.0) / 2)) < 1e-14);
  // A quad that is not cyclic: vertex scaling keeps the cross-ratio ℓ_ab ℓ_cd / (ℓ_bc ℓ_da) of its boundary, and the
  // result is cyclic: opposite angles sum to π.
  const IntrinsicTriangulation kite = planarPolygon({{0, 0}, {2, 0}, {1.5, 1}, {0, 1.2}}, {{{0, 1, 2}}, {{0, 2, 3}}});
  const Uniformization k = uniformize(kite);
  checkInscribed(k, true, 1e-13, 1e-12);
  auto crossRatio = [](const IntrinsicTriangulation& t) {
    std::map<std::pair<int, int>, double> len;
    for (int e = 0; e < t.mesh.nEdges(); ++e) {
      const int h = t.mesh.edgeHalfedge(e), a = t.mesh.tail(h), b = t.mesh.tip(h);
      len[{std::min(a, b), std::max(a, b)}] = t.edgeLengths[e];
    }
    return len[{0, 1}] * len[{2, 3}] / (len[{1, 2}] * len[{0, 3}]);
  };
  CHECK(crossRatio(k.uniform) == Approx(crossRatio(kite)).epsilon(1e-14));
  const std::vector<double> sums = angleSums(k.uniform);
  CHECK(std::abs(sums[0] + sums[2] - M_PI) < 1e-13);
  CHECK(std::abs(sums[1] + sums[3] - M_PI) < 1e-13);
}

TEST_CASE("disks with no interior vertex in CGAL's boeing.off: on their circle, or refused as long strips") {
  // boeing.off: 122 components; among them 92 disks whose vertices all lie on the boundary (strips of 4 to 51
  // vertices). Developed by cross-ratios in quadruple precision (inscribed_disk.h), their lengths computed there and
  // rounded once, all 92 are on their circle with the residual below the tolerance 10⁻¹⁰ and circles to 10⁻⁸ (the
  // layout check), the 51-vertex strip (component 20) among them; before, the recursion in u through the placed
  // faces' angles multiplied its round-off near the crowded ends and refused every strip of 14 or more vertices but a
  // few. The 32-vertex strip (component 68; smallest angle 2.9·10⁻⁶ rad, ε/θ ≈ 7.7·10⁻¹¹) was refused while its
  // lengths came from u rounded to double (1.15·10⁻¹⁰ after the flow); rounded once, 4.0·10⁻¹¹. A strip refused here
  // would be named as a long strip at double's round-off floor, never laid out wrongly.
  const IntrinsicTriangulation input = toTriangulation(readMesh(dataFile("boeing.off")));
  int inscribed = 0, refused = 0, longest = 0;
  for (const MeshComponent& c : splitComponents(input)) {
    const HalfedgeMesh& m = c.triangulation.mesh;
    bool interior = false;
    for (int v = 0; v < m.nVertices(); ++v) interior = interior || !m.isBoundaryVertex(v);
    if (interior || c.topology.genus != 0 || c.topology.boundaryLoops != 1) continue;
    try {
      const Uniformization out = uniformize(c.triangulation);
      checkInscribed(out, false, 1e-10, 1e-8);
      ++inscribed;
      longest = std::max(longest, m.nVertices());
    } catch (const conformesh::ConvergenceError& e) {
      INFO(m.nVertices() << " vertices: " << e.what());
      CHECK_THAT(e.what(), Catch::Contains("a long strip") && Catch::Contains("round-off"));
      CHECK(m.nVertices() >= 28);
      ++refused;
    }
  }
  CHECK(inscribed + refused == 92);
  CHECK(inscribed == 92);
  CHECK(longest == 51);
}

TEST_CASE("an all-boundary strip below double's resolution on its circle is refused, naming it (ALSTOM_TEST4.off)") {
  // Component 1 of CGAL's ALSTOM_TEST4.off (36 vertices, no interior vertex): developed onto its circle in quadruple
  // precision, its shortest chord is 3.5·10⁻⁹ diameters, where three vertices on the circle leave the triangle
  // inequality a relative margin ≈ δ²/2 ≈ 6·10⁻¹⁸, below a double length's rounding: refused, not laid out wrongly.
  const IntrinsicTriangulation strip =
      splitComponents(toTriangulation(readMesh(dataFile("ALSTOM_TEST4.off"))))[1].triangulation;
  REQUIRE(strip.mesh.nVertices() == 36);
  CHECK_THROWS_WITH(uniformize(strip), Catch::Contains("not representable in double precision") &&
                                           Catch::Contains("shortest finite chord 3.51e-09 diameters"));
}

TEST_CASE("a disk whose circle-domain flow hits the step cap converges from its double's sphere (ALSTOM_TEST4.off)") {
  // Component 0 of CGAL's ALSTOM_TEST4.off (518 vertices, one loop): the flow from u = 0 reaches 1.17e-4 rad in 100
  // Newton steps; restarted from the double's spherical solution, projected stereographically (docs/ricci_flow.md
  // §3.3, "The double"), it converges. Checked: interior angle sums 2π and the flow residual to the tolerance 1e-10,
  // Gauss–Bonnet with the boundary turning to round-off, the loop on the unit circle to the layout check's 1e-8.
  const IntrinsicTriangulation disk =
      splitComponents(toTriangulation(readMesh(dataFile("ALSTOM_TEST4.off"))))[0].triangulation;
  REQUIRE(disk.mesh.nVertices() == 518);
  std::vector<std::string> lines;
  UniformizationOptions options;
  options.progress = [&lines](const std::string& line) { lines.push_back(line); };
  const Uniformization out = uniformize(disk, options);
  CHECK(std::any_of(lines.begin(), lines.end(),
                    [](const std::string& l) { return l.find("restarting from the double") != std::string::npos; }));
  CHECK(out.report.maxResidual < 1e-10);
  CHECK(maxInteriorAngleSumError(out.uniform) < 1e-10);
  CHECK(std::abs(curvatureTotals(out.uniform).gaussBonnetResidual) < 1e-10);
  for (int v = 0; v < out.uniform.mesh.nVertices(); ++v)
    if (out.uniform.mesh.isBoundaryVertex(v)) CHECK(std::abs(out.positions[v].head<2>().norm() - 1) < 1e-8);
}

TEST_CASE("a thin appendage below double-precision resolution on the unit sphere gets exact Penner-form lengths") {
  // CGAL's cow: the tail's conformal factor is ~10⁻¹⁵, so its vertices coincide as unit vectors; the lengths come from
  // e^{(w_i+w_j)/2} c⁰_ij. The smallest written spherical length shows that the tail is really resolved, and the angle
  // sums computed back from these tiny lengths (in the real-mesh test above) are 2π to 1e-10.
  const IntrinsicTriangulation cow = toTriangulation(readMesh(dataFile("cow.off")));
  const Uniformization u = uniformize(cow);
  CHECK(u.report.pennerLengths);
  const double shortest = *std::min_element(u.uniform.edgeLengths.begin(), u.uniform.edgeLengths.end());
  INFO("shortest spherical edge " << shortest);
  CHECK(shortest < 1e-12);
  CHECK(shortest > 0);
  // Ordinary meshes keep the chords of their points (angle sums 2π to round-off whatever the flow residual).
  CHECK_FALSE(uniformize(toTriangulation(readMesh(dataFile("blobby.off")))).report.pennerLengths);
}

namespace {

// A spherical cap {θ ≤ θ0} of the unit sphere triangulated in rings: the pole, then ring i = 1..N of 6i vertices at
// polar angle θ0 i/N, consecutive rings zipped by angle; Euclidean chord lengths (an inscribed polyhedral surface).
struct Cap {
  IntrinsicTriangulation tri;
  std::vector<double> theta;
};

Cap sphericalCap(double theta0, int N) {
  Cap cap;
  std::vector<Eigen::Vector3d> p{Eigen::Vector3d(0, 0, 1)};
  cap.theta.push_back(0);
  std::vector<std::vector<int>> ring{{0}};
  for (int i = 1; i <= N; ++i) {
    ring.emplace_back();
    const double t = theta0 * i / N;
    for (int j = 0; j < 6 * i; ++j) {
      const double phi = 2 * M_PI * j / (6 * i);
      ring.back().push_back(static_cast<int>(p.size()));
      p.emplace_back(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
      cap.theta.push_back(t);
    }
  }
  std::vector<std::array<int, 3>> faces;
  for (int i = 1; i <= N; ++i) {
    const std::vector<int>&A = ring[i - 1], &B = ring[i];
    const int a = static_cast<int>(A.size()), b = static_cast<int>(B.size());
    if (a == 1) {
      for (int k = 0; k < b; ++k) faces.push_back({A[0], B[k], B[(k + 1) % b]});
      continue;
    }
    // Advance on whichever ring's next vertex comes first in angle (counter-clockwise seen from outside).
    int j = 0, k = 0;
    while (j < a || k < b) {
      const double nextA = double(j + 1) / a, nextB = double(k + 1) / b;
      if (k < b && (j == a || nextB <= nextA)) {
        faces.push_back({A[j % a], B[k], B[(k + 1) % b]});
        ++k;
      } else {
        faces.push_back({A[j % a], B[k % b], A[(j + 1) % a]});
        ++j;
      }
    }
  }
  cap.tri.mesh = HalfedgeMesh::fromFaces(faces, static_cast<int>(p.size()));
  cap.tri.edgeLengths.resize(cap.tri.mesh.nEdges());
  for (int e = 0; e < cap.tri.mesh.nEdges(); ++e) {
    const int h = cap.tri.mesh.edgeHalfedge(e);
    cap.tri.edgeLengths[e] = (p[cap.tri.mesh.tail(h)] - p[cap.tri.mesh.tip(h)]).norm();
  }
  return cap;
}

}  // namespace

TEST_CASE("a spherical cap converges to its stereographic projection onto the unit disk") {
  // Independent reference: stereographic projection from the antipode of the pole is conformal and maps the cap
  // {θ ≤ θ0} onto the disk of radius tan(θ0/2), so the conformal map to the unit disk is r(θ) = tan(θ/2)/tan(θ0/2),
  // unique up to the disk's Möbius automorphisms. Those are removed by sending the pole's image to 0
  // (z → (z − a)/(1 − ā z)); the remaining rotation does not change |z|. Error: max over vertices of ||z_v| − r(θ_v)|.
  const double theta0 = 1.2;
  std::vector<double> h, error;
  for (int N : {8, 16, 32}) {
    const Cap cap = sphericalCap(theta0, N);
    REQUIRE(cap.tri.mesh.components()[0].boundaryLoops == 1);
    const Uniformization u = uniformize(cap.tri);
    REQUIRE(u.report.target == UniformizationTarget::CircleDomain);
    CHECK(maxInteriorAngleError(u.uniform) < 1e-10);
    const std::complex<double> a(u.positions[0].x(), u.positions[0].y());
    double worst = 0;
    for (int v = 0; v < cap.tri.mesh.nVertices(); ++v) {
      const std::complex<double> z(u.positions[v].x(), u.positions[v].y());
      const double r = std::abs((z - a) / (1.0 - std::conj(a) * z));
      worst = std::max(worst, std::abs(r - std::tan(0.5 * cap.theta[v]) / std::tan(0.5 * theta0)));
    }
    h.push_back(theta0 / N);
    error.push_back(worst);
  }
  const double order = fitLogLogSlope(h, error);
  INFO("cap errors " << error[0] << ", " << error[1] << ", " << error[2] << ", order " << order);
  // Vertex scaling converges at least linearly in h on Delaunay meshes (Gu–Luo–Wu, Math. Comp. 2019); this ring mesh
  // is not regular, so no more than that is asserted; the measured order is reported in docs/ricci_flow.md.
  CHECK(order > 0.9);
  CHECK(error.back() < error.front());
}

namespace {

// min over piecewise-linear f of the Dirichlet energy Σ_h ½ cot θ_h (f_tip − f_tail + ω_h)² (θ_h the angle opposite
// halfedge h: the exact energy of the linear interpolant, face by face), with f = fixed[v] where fixed[v] is finite
// and f_0 = 0 when nothing is fixed (the energy only sees differences).
double minDirichletEnergy(const IntrinsicTriangulation& tri, const std::vector<double>& fixed,
                          const std::vector<double>& omega) {
  const int nv = tri.mesh.nVertices();
  const bool pinFirst = std::none_of(fixed.begin(), fixed.end(), [](double x) { return std::isfinite(x); });
  std::vector<int> unknown(nv, -1);
  int n = 0;
  for (int v = pinFirst ? 1 : 0; v < nv; ++v)
    if (!std::isfinite(fixed[v])) unknown[v] = n++;
  std::vector<double> known(nv, 0.0);
  for (int v = 0; v < nv; ++v)
    if (std::isfinite(fixed[v])) known[v] = fixed[v];
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (int h = 0; h < tri.mesh.nHalfedges(); ++h) {
    const double w = 0.5 * cotanOpposite(tri, h);
    const int a = tri.mesh.tail(h), b = tri.mesh.tip(h);
    // Gradient of w (f_b − f_a + c)², c the known part, with respect to the unknowns among f_a, f_b.
    const double c = (unknown[b] < 0 ? known[b] : 0.0) - (unknown[a] < 0 ? known[a] : 0.0) + omega[h];
    const int ia = unknown[a], ib = unknown[b];
    if (ia >= 0) {
      entries.emplace_back(ia, ia, w);
      rhs[ia] += w * c;
    }
    if (ib >= 0) {
      entries.emplace_back(ib, ib, w);
      rhs[ib] -= w * c;
    }
    if (ia >= 0 && ib >= 0) {
      entries.emplace_back(ia, ib, -w);
      entries.emplace_back(ib, ia, -w);
    }
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(L);
  REQUIRE(solver.info() == Eigen::Success);
  const Eigen::VectorXd x = solver.solve(rhs);
  std::vector<double> f = known;
  for (int v = 0; v < nv; ++v)
    if (unknown[v] >= 0) f[v] = x[unknown[v]];
  double energy = 0;
  for (int h = 0; h < tri.mesh.nHalfedges(); ++h) {
    const double d = f[tri.mesh.tip(h)] - f[tri.mesh.tail(h)] + omega[h];
    energy += 0.5 * cotanOpposite(tri, h) * d * d;
  }
  return energy;
}

// Two-sided bounds on log(R/r), the conformal modulus times 2π, of a flat-with-cone-points annulus (the input's own
// piecewise-flat surface) by the Dirichlet principle, independently of the flow. For {r < |z| < R}: the harmonic
// measure h (0 on one loop, 1 on the other) has energy 2π/log(R/r), the angle function θ/2π (period 1 around the
// core) has energy log(R/r)/2π, and each is the minimum over its class; piecewise-linear functions are a subclass, so
// 2π/E_h ≤ log(R/r) ≤ 2π E*_h. The period-1 class is f + ω with ω the closed 1-form that is ±1 on the edges a dual
// path from loop A to loop B crosses (and on its two boundary edges), 0 elsewhere.
std::pair<double, double> annulusLogRadiusRatioBounds(const IntrinsicTriangulation& tri) {
  const std::vector<std::vector<int>> loops = tri.mesh.boundaryLoops();
  REQUIRE(loops.size() == 2);
  std::vector<int> loopOf(tri.mesh.nHalfedges(), -1);
  for (int l = 0; l < 2; ++l)
    for (int h : loops[l]) loopOf[h] = l;

  std::vector<double> fixed(tri.mesh.nVertices(), std::numeric_limits<double>::quiet_NaN());
  for (int l = 0; l < 2; ++l)
    for (int h : loops[l]) fixed[tri.mesh.tail(h)] = l;
  const double energyHarmonic = minDirichletEnergy(tri, fixed, std::vector<double>(tri.mesh.nHalfedges(), 0.0));

  // Breadth-first search over faces through interior edges, from the face of loop A's first halfedge to a face with a
  // halfedge on loop B.
  const int nf = tri.mesh.nFaces();
  std::vector<int> cameThrough(nf, -2);  // the halfedge of the previous face crossed into this one; −1 at the start
  const int start = HalfedgeMesh::face(loops[0][0]);
  cameThrough[start] = -1;
  std::vector<int> queue{start};
  int end = -1;
  for (std::size_t q = 0; q < queue.size() && end < 0; ++q) {
    const int f = queue[q];
    for (int k = 0; k < 3; ++k) {
      const int h = HalfedgeMesh::halfedge(f, k);
      if (loopOf[h] == 1) {
        end = f;
        break;
      }
      const int t = tri.mesh.twin(h);
      if (t != kInvalid && cameThrough[HalfedgeMesh::face(t)] == -2) {
        cameThrough[HalfedgeMesh::face(t)] = h;
        queue.push_back(HalfedgeMesh::face(t));
      }
    }
  }
  REQUIRE(end >= 0);
  std::vector<double> omega(tri.mesh.nHalfedges(), 0.0);
  omega[loops[0][0]] = -1;  // entering the start face from outside across loop A
  for (int k = 0; k < 3; ++k)
    if (loopOf[HalfedgeMesh::halfedge(end, k)] == 1) {
      omega[HalfedgeMesh::halfedge(end, k)] += 1;  // leaving the end face across loop B
      break;
    }
  for (int f = end; cameThrough[f] >= 0; f = HalfedgeMesh::face(cameThrough[f])) {
    omega[cameThrough[f]] += 1;
    omega[tri.mesh.twin(cameThrough[f])] -= 1;
  }
  for (int f = 0; f < nf; ++f)  // closed: the path enters and leaves every face it visits
    REQUIRE(omega[3 * f] + omega[3 * f + 1] + omega[3 * f + 2] == 0);
  const double energyAngle = minDirichletEnergy(
      tri, std::vector<double>(tri.mesh.nVertices(), std::numeric_limits<double>::quiet_NaN()), omega);
  return {2 * M_PI / energyHarmonic, 2 * M_PI * energyAngle};
}

// Centre and radius of the circle through three spread vertices of each boundary loop of a flat triangulation laid
// out in the plane (the frame of loopCircles, which checks that every vertex is on it).
std::vector<std::pair<Eigen::Vector2d, double>> loopCentres(const IntrinsicTriangulation& tri) {
  const std::vector<Eigen::Vector2d> p = layoutFlat(tri);
  std::vector<std::pair<Eigen::Vector2d, double>> out;
  for (const auto& loop : tri.mesh.boundaryLoops()) {
    const int n = static_cast<int>(loop.size());
    const Eigen::Vector2d A = p[tri.mesh.tail(loop[0])], B = p[tri.mesh.tail(loop[n / 3])],
                          C = p[tri.mesh.tail(loop[2 * n / 3])];
    // The centre solves (B − A)·c = (|B|² − |A|²)/2, (C − A)·c = (|C|² − |A|²)/2 (Cramer's rule).
    const Eigen::Vector2d b = B - A, e = C - A;
    const double rb = 0.5 * (B.squaredNorm() - A.squaredNorm()), re = 0.5 * (C.squaredNorm() - A.squaredNorm());
    const double det = b.x() * e.y() - b.y() * e.x();
    const Eigen::Vector2d c((rb * e.y() - re * b.y()) / det, (b.x() * re - e.x() * rb) / det);
    out.emplace_back(c, (A - c).norm());
  }
  return out;
}

}  // namespace

TEST_CASE("a real annulus (CGAL's blobby_3cc.off, its two-loop component) becomes a circle domain of its modulus") {
  // blobby_3cc.off holds three surfaces: two disks and a band of 701 vertices with two boundary loops, genus 0.
  std::vector<IntrinsicTriangulation> annuli;
  for (const MeshData& part : conformesh::testing::connectedComponents(readMesh(dataFile("blobby_3cc.off")))) {
    IntrinsicTriangulation tri = toTriangulation(part);
    const ComponentTopology topology = tri.mesh.components().at(0);
    if (topology.genus == 0 && topology.boundaryLoops == 2) annuli.push_back(std::move(tri));
  }
  REQUIRE(annuli.size() == 1);
  const IntrinsicTriangulation& input = annuli[0];

  const Uniformization u = uniformize(input);
  CHECK(u.report.target == UniformizationTarget::CircleDomain);
  CHECK(u.report.boundaryLoops == 2);
  const IntrinsicTriangulation out = roundTrip(u, "blobby_3cc-annulus");
  INFO("Newton steps " << u.report.newtonSteps << ", flips " << u.report.flips);
  CHECK(maxInteriorAngleError(out) < 1e-10);
  CHECK(std::abs(curvatureTotals(out).gaussBonnetResidual) < 1e-9);
  CHECK(countNonDelaunayEdges(out) == 0);
  const auto circles = loopCircles(out);
  REQUIRE(circles.size() == 2);
  for (const auto& [R, dev] : circles) CHECK(dev < 1e-8);
  CHECK(std::max(circles[0].first, circles[1].first) == Approx(1.0).epsilon(1e-8));  // the longer loop: unit circle
  checkLambda(input, u);

  // The modulus against the input's own Dirichlet-principle bracket. Two nested circles (radii R1, R2, centres d
  // apart) are Möbius-equivalent to {r < |z| < R} with log(R/r) = acosh((R1² + R2² − d²)/(2 R1 R2)), the inversive
  // distance (Möbius-invariant; for d = 0 it is cosh log(R1/R2)).
  const auto fits = loopCentres(out);
  const double R1 = fits[0].second, R2 = fits[1].second, d = (fits[0].first - fits[1].first).norm();
  const double logRatio = std::acosh((R1 * R1 + R2 * R2 - d * d) / (2 * R1 * R2));
  const auto [lower, upper] = annulusLogRadiusRatioBounds(input);
  INFO("log(R/r): flow " << logRatio << " (radii " << R1 << ", " << R2 << ", centres " << d << " apart), Dirichlet "
                         << "bracket [" << lower << ", " << upper << "]");
  CHECK(lower < upper);
  CHECK(logRatio > lower);
  CHECK(logRatio < upper);
}

namespace {

// A flat cylinder's figures from its own lengths: the worst |angle sum − π| over boundary vertices (both loops closed
// geodesics) and the loops' lengths.
std::pair<double, std::vector<double>> cylinderEnds(const IntrinsicTriangulation& tri) {
  const std::vector<double> sums = angleSums(tri);
  double worst = 0;
  for (int v = 0; v < tri.mesh.nVertices(); ++v)
    if (tri.mesh.isBoundaryVertex(v)) worst = std::max(worst, std::abs(sums[v] - M_PI));
  std::vector<double> lengths;
  for (const auto& loop : tri.mesh.boundaryLoops()) {
    double total = 0;
    for (int h : loop) total += tri.length(h);
    lengths.push_back(total);
  }
  return {worst, lengths};
}

}  // namespace

TEST_CASE("an annulus too long for planar coordinates (CGAL's blade.off) becomes the flat cylinder of its modulus") {
  // blade.off is a tube of circumference ≈ 24 and length ≈ 130: its circle domain's inner circle would be ~10⁻¹⁷ of
  // the outer one, below planar double precision. The flat cylinder (circumference 2π, both loops geodesics) is the
  // same conformal class by z = e^{iw}; its height is log(R/r), which the input's own Dirichlet bracket must contain.
  const IntrinsicTriangulation input = toTriangulation(readMesh(dataFile("blade.off")));
  const auto [lower, upper] = annulusLogRadiusRatioBounds(input);
  REQUIRE(lower > std::log(1e-8 / std::numeric_limits<double>::epsilon()));  // really beyond 1e-8 in the plane
  const Uniformization u = uniformize(input);
  CHECK(u.report.target == UniformizationTarget::FlatCylinder);
  CHECK(u.uniform.background == Background::Euclidean);
  CHECK(u.positions.empty());
  const IntrinsicTriangulation out = roundTrip(u, "blade");
  INFO("Newton steps " << u.report.newtonSteps << ", flips " << u.report.flips << ", height " << u.report.cylinderHeight
                       << ", Dirichlet bracket [" << lower << ", " << upper << "]");
  CHECK(maxInteriorAngleError(out) < 1e-10);
  const auto [worstEnd, lengths] = cylinderEnds(out);
  CHECK(worstEnd < 1e-10);  // geodesic loops, from the written lengths
  REQUIRE(lengths.size() == 2);
  for (double l : lengths) CHECK(l == Approx(2 * M_PI).epsilon(1e-10));
  CHECK(std::abs(curvatureTotals(out).gaussBonnetResidual) < 1e-9);
  CHECK(countNonDelaunayEdges(out) == 0);
  // Area of the cylinder = 2π × height, from the written lengths.
  CHECK(totalArea(out) == Approx(2 * M_PI * u.report.cylinderHeight).epsilon(1e-12));
  CHECK(u.report.cylinderHeight > lower);
  CHECK(u.report.cylinderHeight < upper);
  checkLambda(input, u);
}

TEST_CASE(
    "flat cylinders of growing modulus: circles of the right modulus, or the flat cylinder, never a wrong domain") {
  // The 24-gon tube of height H is exactly a flat cylinder, conformal to {r < |z| < 1} with log(1/r) = 2πH/C. Where
  // the plane resolves the inner circle: every loop a circle and the modulus within the discretization error of
  // vertex scaling (measured 0.6 % at log(1/r) = 8). Beyond: the flat cylinder, of height log(1/r).
  const int n = 24;
  const double C = 2 * n * std::sin(M_PI / n);
  // log(R/r) = 2π/n ≈ 0.26 with one row of triangles: every vertex on a loop (the pre-check has no unknowns then).
  for (double logRatio : {2 * M_PI / n, 4.0, 8.0, 12.0, 15.0, 17.0, 20.0, 30.0}) {
    const int rows = std::max(1, static_cast<int>(std::lround(logRatio * n / (2 * M_PI))));
    const double height = logRatio * C / (2 * M_PI);
    const IntrinsicTriangulation input = toTriangulation(conformesh::testing::cylinderGrid(n, rows, height));
    INFO("log(R/r) = " << logRatio);
    const Uniformization u = uniformize(input);
    const IntrinsicTriangulation out = roundTrip(u, "cylinder");
    CHECK(maxInteriorAngleError(out) < 1e-10);
    if (u.report.target == UniformizationTarget::CircleDomain) {
      const auto fits = loopCentres(out);
      const auto circles = loopCircles(out);
      for (const auto& [R, dev] : circles) CHECK(dev < 1e-8);
      const double R1 = fits[0].second, R2 = fits[1].second, d = (fits[0].first - fits[1].first).norm();
      CHECK(std::acosh((R1 * R1 + R2 * R2 - d * d) / (2 * R1 * R2)) == Approx(logRatio).epsilon(0.01));
    } else {
      REQUIRE(u.report.target == UniformizationTarget::FlatCylinder);
      CHECK(logRatio > 10);  // the plane resolves the smaller moduli (measured: circle domains up to 8)
      const auto [worstEnd, lengths] = cylinderEnds(out);
      CHECK(worstEnd < 1e-10);
      for (double l : lengths) CHECK(l == Approx(2 * M_PI).epsilon(1e-10));
      // The rows are staggered by half a step, so the tube is not developable and its modulus is 2πH/C only up to the
      // discretization (measured 5.4e-4 relative at 12 … 30, as the circle domains' 0.6 % at 8); the input's own
      // Dirichlet bracket is the sharp, independent check. On these tubes it closes to a point (the piecewise-linear
      // harmonic measure and angle function are exact), so it holds to the round-off of two sparse solves, 1e-10.
      CHECK(u.report.cylinderHeight == Approx(logRatio).epsilon(0.01));
      const auto [lower, upper] = annulusLogRadiusRatioBounds(input);
      CHECK(u.report.cylinderHeight >= lower * (1 - 1e-10));
      CHECK(u.report.cylinderHeight <= upper * (1 + 1e-10));
    }
  }
}

TEST_CASE("uniformizeComponents: a sphere, a torus and a genus-2 surface in one mesh, each to its own target") {
  TorusOptions torus;
  torus.n = 20;
  torus.m = 8;
  GenusSurfaceOptions genus2;
  genus2.resolution = 2;
  const IntrinsicTriangulation input = toTriangulation(
      conformesh::testing::joinByHand({makeIcosphere({2, 1.0}), makeTorus(torus), makeGenusSurface(genus2)}));
  REQUIRE_THROWS_AS(uniformize(input), conformesh::InputError);
  const ComponentUniformization cu = uniformizeComponents(input);
  REQUIRE(cu.parts.size() == 3);
  struct Want {
    UniformizationTarget target;
    Background background;
    int chi;
    double area;  // Gauss–Bonnet with constant K and no deficits: K·A = 2πχ; the flat torus is scaled to area 1
  };
  const Want want[] = {{UniformizationTarget::Sphere, Background::Spherical, 2, 4 * M_PI},
                       {UniformizationTarget::FlatTorus, Background::Euclidean, 0, 1.0},
                       {UniformizationTarget::Hyperbolic, Background::Hyperbolic, -2, 4 * M_PI}};
  for (int i = 0; i < 3; ++i) {
    const Uniformization& u = cu.parts[i];
    INFO("component " << i);
    CHECK(u.report.target == want[i].target);
    CHECK(u.uniform.background == want[i].background);
    CHECK(cu.components[i].topology.eulerCharacteristic == want[i].chi);
    CHECK(u.uniform.mesh.nVertices() == static_cast<int>(cu.components[i].vertices.size()));
    CHECK(maxInteriorAngleError(u.uniform) < 1e-10);
    const CurvatureTotals t = curvatureTotals(u.uniform);
    CHECK(t.eulerCharacteristic == want[i].chi);
    // 2πχ of the component alone, to the round-off of its own faces.
    CHECK(std::abs(t.gaussBonnetResidual) < conformesh::testing::gaussBonnetRoundoff(u.uniform.mesh.nFaces()));
    CHECK(totalArea(u.uniform) == Approx(want[i].area).epsilon(1e-9));
  }
}

TEST_CASE("uniformizeComponents: a failing component is named by index, size and topology") {
  const IntrinsicTriangulation input =
      toTriangulation(conformesh::testing::joinByHand({makeIcosphere({1, 1.0}), makeIcosphere({0, 1.0})}));
  const ComponentFlow failSecond = [](const IntrinsicTriangulation& t, const UniformizationOptions& o) {
    if (t.mesh.nVertices() == 12) throw conformesh::ConvergenceError("did not converge");
    return uniformize(t, o);
  };
  try {
    uniformizeComponents(input, {}, failSecond);
    FAIL("no error");
  } catch (const conformesh::ConvergenceError& e) {
    CHECK(std::string(e.what()) ==
          "uniformize: component 1 of 2 (12 vertices, 20 faces, genus 0, 0 boundary loops): did not converge");
  }
}
