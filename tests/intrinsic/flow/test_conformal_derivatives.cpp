// test_conformal_derivatives.cpp — finite-difference checks of the derivatives the discrete conformal flow is built on
// (geometry-central style: a central difference against the closed form, with the error shown to fall at the scheme's
// truncation order O(h²) by a log–log fit over several steps h).
//
// * discrete_conformal.h: lengthDerivativeInU(g, ℓ) = ∂ℓ_ij/∂u_i for ℓ(u) = lengthFromPenner(g, e^{u/2} c⁰), in all three
//   backgrounds, and lengthFromPenner / pennerFromLength against their closed forms (c = ℓ, 2 sinh(ℓ/2), 2 sin(ℓ/2)).
// * triangle_geometry.h: dθ_i/du_j of angleOpposite under the vertex-scaling law written here (Euclidean ℓ_ij =
//   e^{(u_i+u_j)/2} ℓ⁰_ij, hyperbolic sinh(ℓ_ij/2) = e^{(u_i+u_j)/2} sinh(ℓ⁰_ij/2), spherical sin(ℓ_ij/2) = …), against
//   the closed forms of docs/ricci_flow.md §2: Euclidean ∂θ_i/∂u_j = ½ cot θ_k, ∂θ_i/∂u_i = −½(cot θ_j + cot θ_k);
//   hyperbolic (and spherical) dθ_k = A_k (dℓ_k − cos θ_{k+2} dℓ_{k+1} − cos θ_{k+1} dℓ_{k+2}) with A_k = sinh ℓ_k /
//   (sinh ℓ_{k+1} sinh ℓ_{k+2} sin θ_k) (sin for the sphere) and dℓ_ij = tanh(ℓ/2) (du_i + du_j) (tan for the sphere),
//   its angles from the law of cosines written here. These 3×3 blocks are the per-face Hessians −∂Θ/∂u that
//   ricci_flow.cpp assembles; the assembled Hessian is not reachable through a public header, so its sum over faces is
//   checked instead through flowAngleSums on a small mesh (the gradient of Θ the flow's Newton steps follow).
//
// Step sizes and tolerances. For a smooth f, the central difference D_h f = (f(x+h) − f(x−h))/2h has error
// f'''(x) h²/6 + O(h⁴) plus round-off ≈ ε|f|/h. The steps h = 0.08 · 2^−k, k = 0..4 keep the truncation term (≥ 1e-8
// at the smallest h for the third derivatives here, all of order 0.1–10) five orders above round-off (≤ 1e-14/0.005 ≈
// 2e-12), so the fitted slope of log error against log h is 2 to within the O(h²) relative correction of the leading
// term: asserted in [1.9, 2.1]. A wrong closed form (a sign, a factor, a wrong cot) leaves an O(1) difference that
// does not fall with h (slope ≈ 0), so the slope alone detects it; the error at the smallest step is also held below
// 1e-3 of max(1, |f'|), a bound on the truncation term |f'''|h²/6 there (h² = 2.5e-5) that holds for |f'''| ≤
// 240·max(1, |f'|); the largest error seen is 1.8e-4·max(1, |f'|), on the 138° triangle, whose smallest angle is 18°.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "conformesh/intrinsic/flow/discrete_conformal.h"
#include "conformesh/intrinsic/flow/ricci_flow.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"

using namespace conformesh::intrinsic;

namespace {

const std::vector<double> kSteps = {0.08, 0.04, 0.02, 0.01, 0.005};

const char* name(Background g) {
  return g == Background::Euclidean ? "euclidean" : (g == Background::Hyperbolic ? "hyperbolic" : "spherical");
}

// Max over the components of |D_h f − f'| at every step, and the log–log slope of that error against h.
struct FdFit {
  std::vector<double> errors;
  double slope = 0;
};
FdFit fitCentralDifference(const std::function<double(double)>& f, double exact) {
  FdFit fit;
  for (double h : kSteps) fit.errors.push_back(std::abs((f(h) - f(-h)) / (2 * h) - exact));
  fit.slope = fitLogLogSlope(kSteps, fit.errors);
  return fit;
}

// Closed forms written here, independent of triangle_geometry.h: the vertex-scaling law and the laws of cosines.
double scaledLength(Background g, double l0, double ui, double uj) {
  const double s = std::exp((ui + uj) / 2);
  switch (g) {
    case Background::Euclidean:
      return s * l0;
    case Background::Hyperbolic:
      return 2 * std::asinh(s * std::sinh(l0 / 2));
    case Background::Spherical:
      return 2 * std::asin(s * std::sin(l0 / 2));
  }
  return 0;
}
double cosineLawAngle(Background g, double a, double b, double c) {  // the angle opposite a
  switch (g) {
    case Background::Euclidean:
      return std::acos((b * b + c * c - a * a) / (2 * b * c));
    case Background::Hyperbolic:
      return std::acos((std::cosh(b) * std::cosh(c) - std::cosh(a)) / (std::sinh(b) * std::sinh(c)));
    case Background::Spherical:
      return std::acos((std::cos(a) - std::cos(b) * std::cos(c)) / (std::sin(b) * std::sin(c)));
  }
  return 0;
}

// A triangle with vertices 0, 1, 2; side k is opposite vertex k (joins k+1 and k+2).
using Sides = std::array<double, 3>;
Sides scaledSides(Background g, const Sides& l0, const std::array<double, 3>& u) {
  Sides l;
  for (int k = 0; k < 3; ++k) l[k] = scaledLength(g, l0[k], u[(k + 1) % 3], u[(k + 2) % 3]);
  return l;
}
double angleAt(Background g, const Sides& l, int i) { return angleOpposite(g, l[i], l[(i + 1) % 3], l[(i + 2) % 3]); }

// J[i][j] = ∂θ_i/∂u_j at u = 0, closed forms.
using Block = std::array<std::array<double, 3>, 3>;
Block closedFormJacobian(Background g, const Sides& l) {
  std::array<double, 3> th;
  for (int i = 0; i < 3; ++i) th[i] = cosineLawAngle(g, l[i], l[(i + 1) % 3], l[(i + 2) % 3]);
  Block J{};
  if (g == Background::Euclidean) {
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      J[i][j] = 0.5 / std::tan(th[k]);
      J[i][k] = 0.5 / std::tan(th[j]);
      J[i][i] = -0.5 * (1 / std::tan(th[j]) + 1 / std::tan(th[k]));
    }
    return J;
  }
  const bool hyp = g == Background::Hyperbolic;
  auto sn = [&](double x) { return hyp ? std::sinh(x) : std::sin(x); };
  auto dl = [&](double x) { return hyp ? std::tanh(x / 2) : std::tan(x / 2); };
  // ∂ℓ_k/∂u_j: side k joins vertices k+1 and k+2.
  Block dLdU{};
  for (int k = 0; k < 3; ++k) dLdU[k][(k + 1) % 3] = dLdU[k][(k + 2) % 3] = dl(l[k]);
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    const double A = sn(l[k]) / (sn(l[k1]) * sn(l[k2]) * std::sin(th[k]));
    for (int j = 0; j < 3; ++j)
      J[k][j] = A * (dLdU[k][j] - std::cos(th[k2]) * dLdU[k1][j] - std::cos(th[k1]) * dLdU[k2][j]);
  }
  return J;
}

}  // namespace

TEST_CASE("Penner lengths: closed forms, round trip, and ∂ℓ/∂u against central differences at order 2") {
  for (Background g : {Background::Euclidean, Background::Hyperbolic, Background::Spherical}) {
    for (double l0 : {0.05, 0.4, 1.0, 2.2}) {
      if (g == Background::Spherical && l0 > 1.5) continue;  // keep e^{h/2} sin(ℓ/2) < 1 for the largest step
      CAPTURE(name(g), l0);
      // Closed forms of the chord (Penner) length: Euclidean ℓ, hyperboloid 2 sinh(ℓ/2), sphere 2 sin(ℓ/2); round off
      // of sinh/asinh and sin/asin is a few ulps.
      const double c = pennerFromLength(g, l0);
      const double expected = g == Background::Euclidean
                                  ? l0
                                  : (g == Background::Hyperbolic ? 2 * std::sinh(l0 / 2) : 2 * std::sin(l0 / 2));
      CHECK(std::abs(c - expected) <= 8e-16 * expected);
      CHECK(std::abs(lengthFromPenner(g, c) - l0) <= 8e-16 * l0);
      // ℓ(u) with u_i = u, u_j = 0: c = e^{u/2} c⁰.
      auto length = [&](double u) { return lengthFromPenner(g, std::exp(u / 2) * c); };
      const double exact = lengthDerivativeInU(g, l0);
      const double closed = g == Background::Euclidean
                                ? l0 / 2
                                : (g == Background::Hyperbolic ? std::tanh(l0 / 2) : std::tan(l0 / 2));
      CHECK(std::abs(exact - closed) <= 4e-16 * closed);
      const FdFit fit = fitCentralDifference(length, exact);
      INFO("errors " << fit.errors.front() << " … " << fit.errors.back() << ", slope " << fit.slope);
      CHECK(fit.errors.back() < 1e-3 * std::max(1.0, exact));
      CHECK(fit.slope > 1.9);
      CHECK(fit.slope < 2.1);
    }
  }
}

TEST_CASE("per-triangle angle Jacobians ∂θ_i/∂u_j: angleOpposite's central differences match the closed forms") {
  // Scalene triangles, acute and obtuse, of several sizes; the hyperbolic ones also large (curvature matters), the
  // spherical ones below a hemisphere.
  struct Case {
    Background g;
    Sides l0;
  };
  const std::vector<Case> cases = {
      {Background::Euclidean, {1.0, 0.8, 0.7}},   {Background::Euclidean, {1.0, 0.45, 0.62}},  // 119° at vertex 0
      {Background::Euclidean, {0.03, 0.025, 0.02}}, {Background::Hyperbolic, {1.0, 0.8, 0.7}},
      {Background::Hyperbolic, {2.5, 1.4, 1.9}},  {Background::Hyperbolic, {0.05, 0.03, 0.04}},
      {Background::Spherical, {1.0, 0.8, 0.7}},   {Background::Spherical, {0.3, 0.2, 0.25}}};
  int checked = 0;
  for (const Case& cs : cases) {
    CAPTURE(name(cs.g), cs.l0[0], cs.l0[1], cs.l0[2]);
    REQUIRE(isValidTriangle(cs.g, cs.l0[0], cs.l0[1], cs.l0[2]));
    const Block J = closedFormJacobian(cs.g, cs.l0);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        CAPTURE(i, j, J[i][j]);
        auto theta = [&](double t) {
          std::array<double, 3> u{0, 0, 0};
          u[j] = t;
          return angleAt(cs.g, scaledSides(cs.g, cs.l0, u), i);
        };
        const FdFit fit = fitCentralDifference(theta, J[i][j]);
        INFO("errors " << fit.errors.front() << " … " << fit.errors.back() << ", slope " << fit.slope);
        CHECK(fit.errors.back() < 1e-3 * std::max(1.0, std::abs(J[i][j])));
        // Where the third derivative happens to vanish the error sits at round-off and no order is seen; none of
        // these triangles is such a case (checked by the first error being above 1e-9).
        CHECK(fit.errors.front() > 1e-9);
        CHECK(fit.slope > 1.9);
        CHECK(fit.slope < 2.1);
        ++checked;
      }
    }
    // Structure of the closed forms: the Hessian is symmetric (the energy exists); the Euclidean rows sum to 0 (a
    // global scale changes no angle). Round-off: the law of cosines loses ε/ℓ_min² relative in its angles (cos ℓ ≈ 1 −
    // ℓ²/2 cancels), so the allowance is 8ε(1 + |J|)/min(1, ℓ_min)² (2e-12 at ℓ_min = 0.03, 1e-15 for unit sides).
    const double lmin = std::min({1.0, cs.l0[0], cs.l0[1], cs.l0[2]});
    const double roundOff = 8 * 2.2e-16 / (lmin * lmin);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(std::abs(J[i][j] - J[j][i]) <= roundOff * (1 + std::abs(J[i][j])));
    if (cs.g == Background::Euclidean)
      for (int i = 0; i < 3; ++i)
        CHECK(std::abs(J[i][0] + J[i][1] + J[i][2]) <= roundOff * (1 + std::abs(J[i][i])));
    // Hyperbolic: Σ_j ∂θ_i/∂u_j < 0 (a uniform scale-up shrinks every angle; the diagonal dominates, the Hessian is
    // positive definite).
    if (cs.g == Background::Hyperbolic)
      for (int i = 0; i < 3; ++i) CHECK(J[i][0] + J[i][1] + J[i][2] < 0);
  }
  CHECK(checked == 9 * static_cast<int>(cases.size()));
}

TEST_CASE("the assembled ∂Θ/∂u of a small mesh: flowAngleSums' central differences match the sum of face blocks") {
  // A perturbed icosphere (Euclidean) and the same connectivity with hyperbolic lengths: Θ_v(u) through
  // DiscreteConformalMetric at a fixed u where the triangulation is Delaunay with margin (no flip within the steps, as
  // the flip count shows), against Σ over faces of the closed-form blocks at the current lengths.
  MeshData d = makeIcosphere({1, 1.0});  // 42 vertices, 80 faces, angles 50°–70° (perturbed by ≤ 5 %)
  perturbLengths(d, 0.05, 7);
  for (Background g : {Background::Euclidean, Background::Hyperbolic}) {
    CAPTURE(name(g));
    IntrinsicTriangulation tri = toTriangulation(d);
    if (g == Background::Hyperbolic) {
      tri.background = g;
      for (double& l : tri.edgeLengths) l = 1.2 * l;  // hyperbolic equilateral-ish triangles of side ≈ 0.7
    }
    for (double& c : tri.edgeLengths) c = pennerFromLength(g, c);
    DiscreteConformalMetric metric(tri, g);
    const int n = metric.nVertices();
    std::vector<double> u0(n);
    for (int v = 0; v < n; ++v) u0[v] = 0.05 * std::sin(1.7 * v);
    metric.u() = u0;
    REQUIRE(metric.makeDelaunay(1e-12, nullptr) >= 0);
    // Closed-form assembly at u0: the lengths of the current metric.
    const HalfedgeMesh& m = metric.mesh();
    std::vector<std::vector<double>> H(n, std::vector<double>(n, 0.0));
    for (int f = 0; f < m.nFaces(); ++f) {
      const std::array<int, 3> he{HalfedgeMesh::halfedge(f, 0), HalfedgeMesh::halfedge(f, 1),
                                  HalfedgeMesh::halfedge(f, 2)};
      // Vertex k is opposite halfedge he[(k+1)%3]: with he[k] from vertex k to k+1, side k (opposite vertex k) is
      // he[(k+1)%3].
      std::array<int, 3> vtx;
      Sides l;
      for (int k = 0; k < 3; ++k) {
        vtx[k] = m.tail(he[k]);
        l[k] = metric.length(m.edge(he[(k + 1) % 3]));
      }
      const Block J = closedFormJacobian(g, l);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) H[vtx[i]][vtx[j]] += J[i][j];
    }
    double worstSlope = 10, bestSlope = 0, worstError = 0, scale = 1;
    for (const auto& row : H)
      for (double x : row) scale = std::max(scale, std::abs(x));
    for (int j : {0, 5, 17, 33}) {
      std::vector<double> errors;
      for (double h : kSteps) {
        metric.u() = u0;
        metric.u()[j] += h;
        const std::vector<double> plus = flowAngleSums(metric);
        metric.u()[j] -= 2 * h;
        const std::vector<double> minus = flowAngleSums(metric);
        double e = 0;
        for (int i = 0; i < n; ++i) e = std::max(e, std::abs((plus[i] - minus[i]) / (2 * h) - H[i][j]));
        errors.push_back(e);
      }
      const double slope = fitLogLogSlope(kSteps, errors);
      worstSlope = std::min(worstSlope, slope);
      bestSlope = std::max(bestSlope, slope);
      worstError = std::max(worstError, errors.back());
    }
    metric.u() = u0;
    CHECK(metric.makeDelaunay(1e-12, nullptr) == 0);
    INFO("slopes " << worstSlope << " … " << bestSlope << ", error at h = 0.005: " << worstError);
    CHECK(worstError < 1e-3 * scale);
    CHECK(worstSlope > 1.9);
    CHECK(bestSlope < 2.1);
  }
}
