// test_circle_packing.cpp — the circle-packing Ricci flow (circle_packing.h): edge lengths against the closed forms
// (tangency ℓ = r_i + r_j, the Euclidean and hyperbolic theorems of Pythagoras for orthogonal circles); the angle
// Jacobian against finite differences, its symmetry and the power-diagram form h_ij/ℓ_ij; CGAL's genus-1
// and genus-2 meshes with every angle sum 2π recomputed from the output lengths, Gauss–Bonnet with the area term, the
// inversive distances unchanged and Newton converging quadratically; a flat torus of a known lattice giving back its
// modulus (inversive distances, from a perturbed start) or the hexagonal one (tangency); a torus of revolution
// converging to its exact modulus at order 2 (inversive distances) while tangency gives the resolution-independent
// modulus of its combinatorics; the angle distortion against vertex scaling; an inversive-distance packing blocked by a
// degenerating triangle, reported with the face and the residual; inadmissible inputs.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "conformesh/intrinsic/flow/circle_packing.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/io/mesh_io.h"

#include "support/flat_torus_modulus.h"

using namespace conformesh::intrinsic;
using conformesh::ConvergenceError;
using conformesh::InputError;
using conformesh::testing::flatTorusModulus;

namespace {

std::string dataFile(const std::string& name) {
  return std::string(CONFORMESH_TEST_DATA_DIR) + "/" + name;
}

double maxAngleSumError(const IntrinsicTriangulation& tri) {
  const std::vector<double> sums = angleSums(tri);
  double worst = 0;
  for (double s : sums) worst = std::max(worst, std::abs(s - 2 * M_PI));
  return worst;
}

// Mean |θ* − θ⁰| over the corners of the faces not marked in `skip` (same connectivity and numbering).
double meanAngleDistortion(const IntrinsicTriangulation& input, const IntrinsicTriangulation& out,
                           const std::vector<char>& skip) {
  const std::vector<double> a = allCornerAngles(input), b = allCornerAngles(out);
  double total = 0;
  int count = 0;
  for (int h = 0; h < input.mesh.nHalfedges(); ++h)
    if (!skip[HalfedgeMesh::face(h)]) {
      total += std::abs(a[h] - b[h]);
      ++count;
    }
  return total / count;
}

// Newton's quadratic convergence, from the residual history: every step that starts below 1e-3 and ends above the
// round-off floor (1e-11) satisfies h_{k+1} ≤ 20 h_k² (measured constants up to 4 on these meshes; a linearly
// convergent iteration, e.g. with a wrong Hessian, gives h_{k+1} ≈ c h_k and fails). Returns how many steps were
// checked.
int checkQuadratic(const std::vector<double>& h) {
  int checked = 0;
  for (std::size_t k = 0; k + 1 < h.size(); ++k)
    if (h[k] < 1e-3 && h[k + 1] > 1e-11) {
      INFO("step " << k << ": " << h[k] << " -> " << h[k + 1]);
      CHECK(h[k + 1] <= 20 * h[k] * h[k]);
      ++checked;
    }
  return checked;
}

}  // namespace

TEST_CASE("circle-packing edge lengths follow the closed forms and invert to the inversive distance") {
  const Background E = Background::Euclidean, H = Background::Hyperbolic;
  // Tangency: ℓ = r_i + r_j in both backgrounds (cosh(a + b) = cosh a cosh b + sinh a sinh b).
  for (const auto& [a, b] : {std::pair{1e-4, 3e-4}, std::pair{0.3, 0.5}, std::pair{2.0, 3.5}}) {
    CHECK(circlePackingLength(E, a, b, 1.0) == Approx(a + b).epsilon(1e-15));
    CHECK(circlePackingLength(H, a, b, 1.0) == Approx(a + b).epsilon(1e-14));
    // Orthogonal circles (I = 0): Pythagoras, Euclidean ℓ² = a² + b², hyperbolic cosh ℓ = cosh a cosh b.
    CHECK(circlePackingLength(E, a, b, 0.0) == Approx(std::hypot(a, b)).epsilon(1e-15));
    CHECK(circlePackingLength(H, a, b, 0.0) == Approx(std::acosh(std::cosh(a) * std::cosh(b))).epsilon(1e-8));
  }
  // Small hyperbolic circles keep full relative accuracy where acosh(cosh a cosh b) has lost every digit.
  CHECK(circlePackingLength(H, 1e-9, 2e-9, 0.0) == Approx(std::sqrt(5.0) * 1e-9).epsilon(1e-12));
  for (Background g : {E, H})
    for (double I : {0.0, 0.5, 1.0, 3.5, 40.0})
      for (double a : {1e-3, 0.2, 1.5}) {
        const double b = 0.7 * a, l = circlePackingLength(g, a, b, I);
        INFO(toString(g) << " I = " << I << " r = " << a);
        CHECK(inversiveDistanceOf(g, a, b, l) == Approx(I).margin(1e-11).epsilon(1e-11));
      }
  // Initial radii on the square flat torus with n = 4: edges 1/4, 1/4 and the diagonal √2/4 at every vertex.
  const IntrinsicTriangulation square = toTriangulation(makeFlatTorus({{1, 0}, {0, 1}, 4}));
  for (double r : initialCircleRadii(square, InitialRadii::ThirdOfShortestEdge)) CHECK(r == Approx(1.0 / 12));
  for (double r : initialCircleRadii(square, InitialRadii::ThirdOfMeanEdge))
    CHECK(r == Approx((2 + std::sqrt(2.0)) / 36));
}

namespace {

// The angles of a circle-packing triangle as functions of the flow variables u (log r, resp. log tanh(r/2)).
std::array<double, 3> packingAngles(Background g, const std::array<double, 3>& u, const std::array<double, 3>& I) {
  std::array<double, 3> r, L, theta;
  for (int k = 0; k < 3; ++k) r[k] = g == Background::Euclidean ? std::exp(u[k]) : 2 * std::atanh(std::exp(u[k]));
  for (int k = 0; k < 3; ++k) L[k] = circlePackingLength(g, r[(k + 1) % 3], r[(k + 2) % 3], I[k]);
  for (int k = 0; k < 3; ++k) theta[k] = angleOpposite(g, L[k], L[(k + 1) % 3], L[(k + 2) % 3]);
  return theta;
}

}  // namespace

TEST_CASE("the per-triangle angle Jacobian: finite differences, symmetry and the Euclidean power-diagram form") {
  struct Case {
    Background g;
    std::array<double, 3> r, I;
  };
  const Case cases[] = {
      {Background::Euclidean, {0.3, 0.5, 0.4}, {1, 1, 1}},      // tangency
      {Background::Euclidean, {0.3, 0.5, 0.4}, {0, 0.5, 0.2}},  // Thurston's intersection angles
      {Background::Euclidean, {0.3, 0.5, 0.2}, {3.5, 4, 6}},    // inversive distances, disjoint circles
      {Background::Euclidean, {1.0, 0.05, 0.3}, {2, 1.2, 5}},   // an obtuse triangle
      {Background::Hyperbolic, {0.3, 0.5, 0.4}, {1, 1, 1}},
      {Background::Hyperbolic, {1.5, 2.0, 1.0}, {0, 0.5, 0.2}},
      {Background::Hyperbolic, {0.01, 0.02, 0.015}, {3.5, 4, 6}},
  };
  for (const Case& c : cases) {
    const auto J = circlePackingAngleJacobian(c.g, c.r, c.I);
    std::array<double, 3> u;
    for (int k = 0; k < 3; ++k)
      u[k] = c.g == Background::Euclidean ? std::log(c.r[k]) : std::log(std::tanh(0.5 * c.r[k]));
    double scale = 0;
    for (const auto& row : J)
      for (double x : row) scale = std::max(scale, std::abs(x));
    INFO(toString(c.g) << " r = " << c.r[0] << ", " << c.r[1] << ", " << c.r[2] << "; I = " << c.I[0] << ", " << c.I[1]
                       << ", " << c.I[2]);
    // Central differences with step 1e-6: truncation O(1e-12), round-off O(1e-16/1e-6) = O(1e-10) of the angles.
    for (int n = 0; n < 3; ++n) {
      std::array<double, 3> up = u, down = u;
      up[n] += 1e-6;
      down[n] -= 1e-6;
      const auto tp = packingAngles(c.g, up, c.I), tm = packingAngles(c.g, down, c.I);
      for (int k = 0; k < 3; ++k) CHECK(std::abs((tp[k] - tm[k]) / 2e-6 - J[k][n]) < 1e-8 * std::max(1.0, scale));
    }
    // Symmetric: an energy exists (Chow–Luo 2003; Guo 2011).
    for (int k = 0; k < 3; ++k)
      for (int n = 0; n < k; ++n) CHECK(std::abs(J[k][n] - J[n][k]) < 1e-13 * scale);
    if (c.g != Background::Euclidean) continue;
    // Euclidean: scaling all radii keeps the angles (rows sum to 0), and ∂θ_i/∂u_j = h_ij/ℓ_ij with h_ij the signed
    // distance from the power centre c (equal power |c − p|² − r² for the three circles) to side ij, positive on the
    // side of the third vertex.
    for (int k = 0; k < 3; ++k) CHECK(std::abs(J[k][0] + J[k][1] + J[k][2]) < 1e-13 * scale);
    std::array<double, 3> L;
    for (int k = 0; k < 3; ++k) L[k] = circlePackingLength(c.g, c.r[(k + 1) % 3], c.r[(k + 2) % 3], c.I[k]);
    const double theta0 = angleOpposite(c.g, L[0], L[1], L[2]);
    const Eigen::Vector2d p[3] = {{0, 0}, {L[2], 0}, {L[1] * std::cos(theta0), L[1] * std::sin(theta0)}};
    Eigen::Matrix2d A;
    A.row(0) = 2 * p[1].transpose();
    A.row(1) = 2 * p[2].transpose();
    const Eigen::Vector2d rhs(p[1].squaredNorm() - c.r[1] * c.r[1] + c.r[0] * c.r[0],
                              p[2].squaredNorm() - c.r[2] * c.r[2] + c.r[0] * c.r[0]);
    const Eigen::Vector2d centre = A.lu().solve(rhs);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i == j) continue;
        const int k = 3 - i - j;
        const Eigen::Vector2d e = p[j] - p[i];
        const auto side = [&](const Eigen::Vector2d& q) { return e.x() * (q - p[i]).y() - e.y() * (q - p[i]).x(); };
        const double h = std::copysign(std::abs(side(centre)) / e.norm(), side(centre) * side(p[k]));
        CHECK(std::abs(J[i][j] - h / e.norm()) < 1e-12 * scale);
      }
  }
  // Two unit circles at inversive distance 10 (centres √22 apart) and a tiny third one near both: no triangle.
  CHECK_THROWS_AS(circlePackingAngleJacobian(Background::Euclidean, {1.0, 1.0, 1e-3}, {40, 40, 10}), InputError);
}

TEST_CASE("CGAL's genus-1 and genus-2 meshes are uniformized by circle packings") {
  struct Case {
    const char* file;
    int genus;
  };
  for (const Case c : {Case{"knot1.off", 1}, Case{"double-torus-example.off", 2}})
    for (CirclePackingScheme scheme : {CirclePackingScheme::Tangential, CirclePackingScheme::InversiveDistance}) {
      SECTION(std::string(c.file) + " " + toString(scheme)) {
        const IntrinsicTriangulation input = toTriangulation(readMesh(dataFile(c.file)));
        CirclePackingOptions options;
        options.scheme = scheme;
        const CirclePacking cp = uniformizeByCirclePacking(input, options);
        const IntrinsicTriangulation& out = cp.result.uniform;
        const Background g = c.genus == 1 ? Background::Euclidean : Background::Hyperbolic;
        INFO("Newton steps " << cp.result.report.newtonSteps << ", residual " << cp.result.report.maxResidual);
        CHECK(cp.result.report.genus == c.genus);
        CHECK(cp.result.report.flips == 0);
        CHECK(out.background == g);
        CHECK(out.mesh.nFaces() == input.mesh.nFaces());
        // Angle sums and Gauss–Bonnet from the output lengths alone.
        CHECK(maxAngleSumError(out) < 1e-10);
        CHECK(std::abs(curvatureTotals(out).gaussBonnetResidual) < 1e-9);
        const double chi = 2.0 - 2 * c.genus;
        if (c.genus == 1) CHECK(totalArea(out) == Approx(1.0).epsilon(1e-12));
        if (c.genus >= 2) CHECK(totalArea(out) == Approx(-2 * M_PI * chi).epsilon(1e-9));
        // The packing's inversive distances: recomputed from the output lengths and radii, and (independently) from
        // the input lengths and initial radii (inversive distances) or 1 (tangency).
        const std::vector<double> r0 = initialCircleRadii(input, InitialRadii::ThirdOfShortestEdge);
        double worstOut = 0, worstIn = 0;
        for (int e = 0; e < input.mesh.nEdges(); ++e) {
          const int h = input.mesh.edgeHalfedge(e), a = input.mesh.tail(h), b = input.mesh.tip(h);
          const double expected = scheme == CirclePackingScheme::Tangential
                                      ? 1.0
                                      : inversiveDistanceOf(Background::Euclidean, r0[a], r0[b], input.edgeLengths[e]);
          worstIn = std::max(worstIn, std::abs(cp.inversiveDistance[e] - expected) / expected);
          const double now = inversiveDistanceOf(g, cp.radii[a], cp.radii[b], out.edgeLengths[e]);
          worstOut = std::max(worstOut, std::abs(now - expected) / expected);
        }
        INFO("relative inversive-distance change " << worstOut);
        CHECK(worstIn < 1e-14);
        CHECK(worstOut < 1e-13);  // regression bound, calibrated on earlier runs (measured ≤ 1.6e-15), not derived
        for (double l : cp.result.lambda) CHECK(std::isfinite(l));
        CHECK(checkQuadratic(cp.residualHistory) >= 1);
      }
    }
}

TEST_CASE("a flat torus of a known lattice: inversive distances give its modulus back, tangency the hexagonal one") {
  const std::complex<double> omega2(0.3, 1.1);  // with ω1 = 1 a reduced basis: |ω2| ≤ |ω2 − 1|
  const IntrinsicTriangulation input = toTriangulation(makeFlatTorus({{1, 0}, omega2, 12}));
  CHECK(maxAngleSumError(input) < 1e-12);

  SECTION("inversive distances, from a perturbed start") {
    // The input is already flat, so u = u⁰ solves; starting 0.3 away in every log radius, Newton must find it again
    // (the solution is unique up to scale: Luo 2011).
    std::mt19937 rng(7);
    for (InitialRadii rule : {InitialRadii::ThirdOfShortestEdge, InitialRadii::ThirdOfMeanEdge}) {
      CirclePackingOptions options;
      options.initialRadii = rule;
      options.startPerturbation.resize(input.mesh.nVertices());
      for (double& x : options.startPerturbation) x = 0.3 * (2.0 * rng() / rng.max() - 1);
      const CirclePacking cp = uniformizeByCirclePacking(input, options);
      CHECK(cp.result.report.newtonSteps >= 2);
      const std::complex<double> tau = flatTorusModulus(cp.result.uniform);
      CHECK(tau.real() == Approx(0.3).margin(1e-9));
      CHECK(tau.imag() == Approx(1.1).margin(1e-9));
      // The result is the input scaled to area 1 (area 1.1): every length by 1/√1.1, so λ = ½ log 1.1 everywhere.
      for (double l : cp.result.lambda) CHECK(l == Approx(0.5 * std::log(1.1)).margin(1e-9));
    }
  }
  SECTION("tangency forgets the lattice") {
    // Every vertex of the grid has degree 6: equal radii give equilateral triangles, so the periods become 2rn and
    // 2rn·e^{iπ/3} whatever the input lattice (Koebe–Andreev–Thurston: the packing is unique up to scale).
    CirclePackingOptions options;
    options.scheme = CirclePackingScheme::Tangential;
    const CirclePacking cp = uniformizeByCirclePacking(input, options);
    const std::complex<double> tau = flatTorusModulus(cp.result.uniform);
    CHECK(tau.real() == Approx(0.5).margin(1e-9));
    CHECK(tau.imag() == Approx(std::sqrt(3.0) / 2).margin(1e-9));
    for (double r : cp.radii) CHECK(r == Approx(cp.radii[0]).epsilon(1e-10));
  }
}

TEST_CASE("angle distortion against the input: inversive distances stay with vertex scaling, tangency does not") {
  // Jin–Kim–Luo–Gu's argument for inversive distances: they keep the input's conformal data, tangency keeps only the
  // connectivity. Compared on the faces that the Yamabe flow's flips did not touch (same corners in all three).
  for (const char* file : {"knot1.off", "double-torus-example.off"}) {
    SECTION(file) {
      const IntrinsicTriangulation input = toTriangulation(readMesh(dataFile(file)));
      const Uniformization yamabe = uniformize(input);
      std::vector<char> touched(input.mesh.nFaces(), 0);
      for (const PtolemyFlip& f : yamabe.correspondence.flips()) touched[f.faceA] = touched[f.faceB] = 1;
      CirclePackingOptions tangential, inversive;
      tangential.scheme = CirclePackingScheme::Tangential;
      inversive.scheme = CirclePackingScheme::InversiveDistance;
      const double dY = meanAngleDistortion(input, yamabe.uniform, touched);
      const double dT =
          meanAngleDistortion(input, uniformizeByCirclePacking(input, tangential).result.uniform, touched);
      const double dI = meanAngleDistortion(input, uniformizeByCirclePacking(input, inversive).result.uniform, touched);
      INFO("mean |θ* − θ⁰|: yamabe " << dY << ", tangential " << dT << ", inversive distance " << dI);
      // Regression bound, calibrated on earlier runs (measured 13× on knot1, 3.7× on the double torus), not derived.
      CHECK(dT > 2 * dI);
      CHECK(dT > 2 * dY);
    }
  }
}

TEST_CASE("an inversive-distance packing blocked by a degenerating triangle is reported with face and residual") {
  // CGAL's elk.off (genus 1): Newton's steps are cut ever shorter by triangles whose inequality fails. Tangency on the
  // same triangulation always exists (Koebe–Andreev–Thurston) and converges.
  const IntrinsicTriangulation input = toTriangulation(readMesh(dataFile("elk.off")));
  CirclePackingOptions options;
  try {
    uniformizeByCirclePacking(input, options);
    FAIL("the inversive-distance flow on elk.off was expected to fail");
  } catch (const ConvergenceError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("blocked") != std::string::npos);
    CHECK(what.find("face ") != std::string::npos);
    CHECK(what.find("triangle inequality") != std::string::npos);
    CHECK(what.find("max |Θ̂ − Θ| = ") != std::string::npos);
  }
  options.scheme = CirclePackingScheme::Tangential;
  const CirclePacking cp = uniformizeByCirclePacking(input, options);
  CHECK(maxAngleSumError(cp.result.uniform) < 1e-10);
  // A step cap that is too small is a ConvergenceError with the residual reached, too.
  options.maxNewtonSteps = 1;
  CHECK_THROWS_WITH(uniformizeByCirclePacking(input, options),
                    Catch::Contains("Newton step cap") && Catch::Contains("max |Θ̂ − Θ| = "));
}

TEST_CASE("inputs the circle-packing flows do not take are reported") {
  CHECK_THROWS_WITH(uniformizeByCirclePacking(toTriangulation(makeIcosphere({2, 1.0}))),
                    Catch::Contains("genus 0") && Catch::Contains("genus >= 1 only"));
  CHECK_THROWS_WITH(uniformizeByCirclePacking(toTriangulation(makeDisk({3, 1.0}))),
                    Catch::Contains("1 boundary loops") && Catch::Contains("genus >= 1 only"));
  // A long thin lattice cell: at every vertex the mean edge is 3.3× the shortest, so a third of the mean overlaps the
  // short edges' circles by more than orthogonality and I < 0 (the energy is not convex there).
  FlatTorusOptions thin{{1, 0}, {5, 0.2}, 6};
  thin.reduceBasis = false;
  CirclePackingOptions mean;
  mean.initialRadii = InitialRadii::ThirdOfMeanEdge;
  CHECK_THROWS_WITH(uniformizeByCirclePacking(toTriangulation(makeFlatTorus(thin)), mean),
                    Catch::Contains("edge ") && Catch::Contains("inversive distance") && Catch::Contains("< 0"));
  CirclePackingOptions wrong;
  wrong.startPerturbation = {0.1, 0.2};
  CHECK_THROWS_AS(uniformizeByCirclePacking(toTriangulation(makeFlatTorus({{1, 0}, {0, 1}, 4})), wrong), InputError);
}

TEST_CASE("a torus of revolution: inversive distances converge to its modulus at order 2, tangency does not move") {
  // The exact conformal modulus of the torus of revolution (R, r) is i·r/√(R² − r²) (Im of the reduced modulus: the
  // larger of that and its inverse). Every vertex of the n × m grid has degree 6, so the tangential packing has equal
  // radii and equilateral triangles: periods n·2ρ and m·2ρ·e^{iπ/3}, modulus (n/m)·e^{iπ/3} reduced — the same at every
  // resolution, i.e. tangency does not converge to the smooth map (Jin–Kim–Luo–Gu's reason for inversive distances).
  const double R = 1.0, r = 0.4, a = r / std::sqrt(R * R - r * r), expected = std::max(a, 1 / a);
  std::vector<double> logH, logErr;
  for (int k : {1, 2, 4}) {
    TorusOptions options;
    options.majorRadius = R;
    options.minorRadius = r;
    options.n = 25 * k;
    options.m = 10 * k;
    const IntrinsicTriangulation input = toTriangulation(makeTorus(options));
    const CirclePacking cp = uniformizeByCirclePacking(input);
    logH.push_back(std::log(2 * M_PI * R / options.n));
    logErr.push_back(std::log(std::abs(flatTorusModulus(cp.result.uniform) - std::complex<double>(0, expected))));
    if (k <= 2) {
      CirclePackingOptions tangential;
      tangential.scheme = CirclePackingScheme::Tangential;
      const std::complex<double> tau = flatTorusModulus(uniformizeByCirclePacking(input, tangential).result.uniform);
      // 2.5·e^{iπ/3} = 1.25 + 2.165i, reduced by τ → τ − 1: 0.25 + 2.165i.
      CHECK(tau.real() == Approx(0.25).margin(1e-9));
      CHECK(tau.imag() == Approx(2.5 * std::sqrt(3.0) / 2).margin(1e-9));
    }
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
  CHECK(order > 1.8);  // measured 2.00 (errors 4.3e-2, 1.1e-2, 2.7e-3)
  CHECK(std::exp(logErr[2]) < 5e-3);
}
