// Tests for triangle_geometry.h against independent references: 50-digit evaluations of the textbook formulas
// (Boost.Multiprecision), triangles constructed on known circles, and closed forms (octant, equilateral).
#include <catch2/catch.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <random>

#include "conformesh/intrinsic/mesh/triangle_geometry.h"

using namespace conformesh::intrinsic;
using Real = boost::multiprecision::cpp_bin_float_50;

namespace {
// The law of cosines in 50 digits: exact enough to be the reference for any double input.
double refAngle(Background g, double a, double b, double c) {
  const Real A(a), B(b), C(c);
  Real cosA;
  if (g == Background::Euclidean) cosA = (B * B + C * C - A * A) / (2 * B * C);
  if (g == Background::Spherical) cosA = (cos(A) - cos(B) * cos(C)) / (sin(B) * sin(C));
  if (g == Background::Hyperbolic) cosA = (cosh(B) * cosh(C) - cosh(A)) / (sinh(B) * sinh(C));
  return static_cast<double>(acos(cosA));
}
double refThird(Background g, double b, double c, double theta) {
  const Real B(b), C(c), T(theta);
  if (g == Background::Euclidean) return static_cast<double>(sqrt(B * B + C * C - 2 * B * C * cos(T)));
  if (g == Background::Spherical) return static_cast<double>(acos(cos(B) * cos(C) + sin(B) * sin(C) * cos(T)));
  return static_cast<double>(acosh(cosh(B) * cosh(C) - sinh(B) * sinh(C) * cos(T)));
}
double relErr(double x, double ref) { return std::abs(x - ref) / std::abs(ref); }
}  // namespace

TEST_CASE("closed forms: equilateral, right, octant") {
  CHECK(angleOpposite(Background::Euclidean, 1, 1, 1) == Approx(M_PI / 3).epsilon(1e-15));
  CHECK(triangleArea(Background::Euclidean, 1, 1, 1) == Approx(std::sqrt(3.0) / 4).epsilon(1e-15));
  CHECK(circumradius(Background::Euclidean, 1, 1, 1) == Approx(1 / std::sqrt(3.0)).epsilon(1e-15));
  CHECK(circumradius(Background::Euclidean, 5, 3, 4) == Approx(2.5).epsilon(1e-15));
  CHECK(cotOpposite(Background::Euclidean, 5, 3, 4) == Approx(0).margin(1e-15));
  // The octant of the unit sphere: sides π/2, angles π/2, area π/2, circumcentre (1,1,1)/√3.
  const double q = M_PI / 2;
  CHECK(angleOpposite(Background::Spherical, q, q, q) == Approx(q).epsilon(1e-15));
  CHECK(triangleArea(Background::Spherical, q, q, q) == Approx(q).epsilon(1e-15));
  CHECK(circumradius(Background::Spherical, q, q, q) == Approx(std::acos(1 / std::sqrt(3.0))).epsilon(1e-14));
}

TEST_CASE("angles agree with 50-digit law of cosines in all three geometries, including needles and caps") {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.05, 1.0);
  for (Background g : {Background::Euclidean, Background::Spherical, Background::Hyperbolic}) {
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
      const double b = u(rng), c = u(rng), theta = std::uniform_real_distribution<double>(1e-7, M_PI - 1e-7)(rng);
      const double a = refThird(g, b, c, theta);
      if (!isValidTriangle(g, a, b, c)) continue;
      worst = std::max(worst, relErr(angleOpposite(g, a, b, c), refAngle(g, a, b, c)));
    }
    // A handful of ulps: the half-angle form is backward stable and the angle is well conditioned in the lengths.
    CHECK(worst < 1e-12);
  }
  // Needle (tiny side) and cap (angle near π): the naive law of cosines in double loses most digits here.
  for (Background g : {Background::Euclidean, Background::Spherical, Background::Hyperbolic}) {
    const double needle = angleOpposite(g, 1e-9, 0.5, 0.5 + 3e-10);
    CHECK(relErr(needle, refAngle(g, 1e-9, 0.5, 0.5 + 3e-10)) < 1e-12);
    const double b = 0.3, c = 0.4, a = refThird(g, b, c, M_PI - 1e-6);
    CHECK(relErr(angleOpposite(g, a, b, c), refAngle(g, a, b, c)) < 1e-12);
  }
}

TEST_CASE("thirdSide matches the 50-digit law of cosines and is accurate for tiny angles") {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.01, 1.2);
  for (Background g : {Background::Euclidean, Background::Spherical, Background::Hyperbolic})
    for (int i = 0; i < 1000; ++i) {
      const double b = u(rng), c = u(rng), t = std::uniform_real_distribution<double>(1e-9, 3.1)(rng);
      CHECK(relErr(thirdSide(g, b, c, t), refThird(g, b, c, t)) < 1e-12);
    }
  // b = c and theta tiny: the naive form cancels completely; the haversine form keeps every digit.
  CHECK(relErr(thirdSide(Background::Euclidean, 1, 1, 1e-10), refThird(Background::Euclidean, 1, 1, 1e-10)) < 1e-14);
}

TEST_CASE("areas: Heron in 50 digits, spherical excess and hyperbolic defect from the angles") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.05, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double b = u(rng), c = u(rng), t = std::uniform_real_distribution<double>(1e-3, 3.0)(rng);
    {
      const double a = refThird(Background::Euclidean, b, c, t);
      const Real A(a), B(b), C(c), s = (A + B + C) / 2;
      CHECK(relErr(triangleArea(Background::Euclidean, a, b, c),
                   static_cast<double>(sqrt(s * (s - A) * (s - B) * (s - C)))) < 1e-11);
    }
    for (Background g : {Background::Spherical, Background::Hyperbolic}) {
      const double a = refThird(g, b, c, t);
      const double sum = refAngle(g, a, b, c) + refAngle(g, b, c, a) + refAngle(g, c, a, b);
      const double ref = g == Background::Spherical ? sum - M_PI : M_PI - sum;
      CHECK(triangleArea(g, a, b, c) == Approx(ref).epsilon(1e-10).margin(1e-14));
    }
  }
}

TEST_CASE("circumradius recovers the radius of the circle the vertices were placed on") {
  std::mt19937 rng(4);
  for (int i = 0; i < 300; ++i) {
    const double R = std::uniform_real_distribution<double>(0.01, 1.4)(rng);
    double t[3];
    for (double& x : t) x = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    auto chord = [&](Background g, double dt) {
      const Real r(R), c = cos(Real(dt));
      // Two points at distance R from a centre, seen from it at angle dt.
      if (g == Background::Euclidean) return static_cast<double>(2 * r * sin(Real(dt) / 2));
      if (g == Background::Spherical) return static_cast<double>(acos(cos(r) * cos(r) + sin(r) * sin(r) * c));
      return static_cast<double>(acosh(cosh(r) * cosh(r) - sinh(r) * sinh(r) * c));
    };
    for (Background g : {Background::Euclidean, Background::Spherical, Background::Hyperbolic}) {
      const double a = chord(g, t[1] - t[2]), b = chord(g, t[2] - t[0]), c = chord(g, t[0] - t[1]);
      if (!isValidTriangle(g, a, b, c) || std::min({a, b, c}) < 1e-3 * R) continue;
      CHECK(circumradius(g, a, b, c) == Approx(R).epsilon(1e-8));
    }
  }
}

TEST_CASE("hyperbolic triangles on a horocycle have no circumcircle") {
  // Sides 3, 1.6, 1.6 form a valid triangle (3 < 3.2) but its chords 2 sinh(l/2) do not (4.26 > 2 × 1.78): the
  // vertices lie on a hypercycle. Points on a horocycle are the borderline: in the upper half-plane on y = 1,
  // 2 sinh(d/2) = |Δx| exactly, so sides from Δx = 1, 2, 3 give a degenerate chord triangle and a huge radius.
  CHECK(isValidTriangle(Background::Hyperbolic, 3, 1.6, 1.6));
  CHECK(std::isinf(circumradius(Background::Hyperbolic, 3, 1.6, 1.6)));
  auto d = [](double dx) { return 2 * std::asinh(dx / 2); };
  CHECK(circumradius(Background::Hyperbolic, d(3), d(1), d(2)) > 15);
  // Points on a hypercycle-free circle stay finite: an equilateral triangle of side 1.
  CHECK(std::isfinite(circumradius(Background::Hyperbolic, 1, 1, 1)));
}

TEST_CASE("validity: NaN, zero, negative, inequality, spherical perimeter") {
  CHECK_FALSE(isValidTriangle(Background::Euclidean, NAN, 1, 1));
  CHECK_FALSE(isValidTriangle(Background::Euclidean, 0, 1, 1));
  CHECK_FALSE(isValidTriangle(Background::Euclidean, -1, 1, 1));
  CHECK_FALSE(isValidTriangle(Background::Euclidean, 2, 1, 1));  // degenerate: not strict
  CHECK_FALSE(isValidTriangle(Background::Euclidean, INFINITY, 1, 1));
  CHECK(isValidTriangle(Background::Euclidean, 1.999999, 1, 1));
  CHECK_FALSE(isValidTriangle(Background::Spherical, 3, 3, 1));  // perimeter 7 > 2π
  CHECK(isValidTriangle(Background::Hyperbolic, 5, 3, 3));
}
