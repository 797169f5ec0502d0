// Tests for refinement_quality.h against closed forms: an equilateral flat torus (every angle 60°, circumradius ℓ/√3)
// and a right-isosceles grid of the square (angles 45°/45°/90°, circumradius = half the hypotenuse, non-Delaunay
// count 0 because its diagonals are cocircular, not violated).
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/refine/delaunay/refinement_quality.h"
#include "support/refine_test_surfaces.h"

using namespace conformesh;
using namespace conformesh::refine;
using namespace conformesh::refine::testing;

TEST_CASE("an equilateral flat torus: every angle 60°, every circumradius l/sqrt(3)") {
  const int n = 5;
  const FlatTorus t = flatTorus({1, 0}, {0.5, std::sqrt(3) / 2}, n);
  const QualityReport q = measureQuality(t.tri);
  CHECK(q.vertices == n * n);
  CHECK(q.triangles == 2 * n * n);
  CHECK(q.minAngleDeg == Approx(60).epsilon(1e-12));
  CHECK(q.meanMinAngleDeg == Approx(60).epsilon(1e-12));
  CHECK(q.maxAngleDeg == Approx(60).epsilon(1e-12));
  const double l = 1.0 / n;
  CHECK(q.maxCircumradius == Approx(l / std::sqrt(3)).epsilon(1e-12));
  CHECK(q.meanCircumradius == Approx(l / std::sqrt(3)).epsilon(1e-12));
  CHECK(q.maxRadiusEdgeRatio == Approx(1 / std::sqrt(3)).epsilon(1e-12));
  CHECK(q.fractionBelow30 == 0);
  REQUIRE(q.angleHistogram.size() == 18);
  // 60° sits on the boundary of bins 5 and 6; round-off decides which, but all 6·n² corners are in one of the two.
  CHECK(q.angleHistogram[5] + q.angleHistogram[6] == 6 * n * n);
  CHECK(q.nonDelaunayEdges == 0);
  CHECK(std::abs(q.gaussBonnetResidual) < 1e-12);
}

TEST_CASE("a skewed torus grid: smallest angles and the share under 30° from the lattice geometry") {
  // Lattice (1, 0), (3.3, 0.25) kept as given: every triangle is congruent to one with sides |ω1|/n, |ω2|/n and
  // |ω2 − ω1|/n, whose smallest angle is opposite the shortest side.
  const int n = 4;
  const FlatTorus t = flatTorus({1, 0}, {3.3, 0.25}, n);
  const double a = 1.0 / n, b = std::abs(std::complex<double>(3.3, 0.25)) / n,
               c = std::abs(std::complex<double>(2.3, 0.25)) / n;
  const double smallest = std::acos((b * b + c * c - a * a) / (2 * b * c)) * 180 / M_PI;
  const QualityReport q = measureQuality(t.tri);
  CHECK(q.minAngleDeg == Approx(smallest).epsilon(1e-9));
  CHECK(q.meanMinAngleDeg == Approx(smallest).epsilon(1e-9));
  CHECK(q.fractionBelow30 == 1.0);
  CHECK(q.nonDelaunayEdges > 0);
  // Law of sines: R = a / (2 sin α) with a the shortest side, opposite the smallest angle α.
  CHECK(q.maxRadiusEdgeRatio == Approx(1 / (2 * std::sin(smallest * M_PI / 180))).epsilon(1e-9));
}
