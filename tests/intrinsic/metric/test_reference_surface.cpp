// Tests for reference_surface.h: seams of periodic charts, wrapping, interpolation on the reference sphere, orientation.
#include <catch2/catch.hpp>

#include <cmath>

#include "conformesh/intrinsic/metric/reference_surface.h"

using namespace conformesh::intrinsic;

TEST_CASE("torus charts: a triangle across the seam is unwrapped, and wrapped back into the chart") {
  ChartDomain d;
  d.u0 = 0;
  d.u1 = 2 * M_PI;
  d.v0 = 0;
  d.v1 = 2 * M_PI;
  d.periodicU = d.periodicV = true;
  const Eigen::Vector3d a(2 * M_PI - 0.01, 0.02, 0), b(0.01, 2 * M_PI - 0.01, 0);
  const Eigen::Vector3d bu = unwrapNear(d, a, b);
  CHECK(bu.x() == Approx(2 * M_PI + 0.01));
  CHECK(bu.y() == Approx(-0.01));
  const Eigen::Vector2d uv = chartCoordinates(d, Eigen::Vector3d(2 * M_PI + 0.01, -0.01, 0));
  CHECK(uv.x() == Approx(0.01));
  CHECK(uv.y() == Approx(2 * M_PI - 0.01));
  // Interpolating across the seam stays near the seam instead of crossing the chart.
  const Eigen::Vector3d mid = interpolateOnReference(d, a, b, a, Eigen::Vector3d(0.5, 0.5, 0));
  CHECK(std::abs(mid.x() - 2 * M_PI) < 1e-12);
}

TEST_CASE("sphere charts: interpolation lands on the sphere; orientation is the sign of det") {
  ChartDomain d;
  d.u0 = 0;
  d.u1 = 2 * M_PI;
  d.v0 = 0;
  d.v1 = M_PI;
  d.periodicU = true;
  d.poleAtV0 = d.poleAtV1 = true;
  REQUIRE(d.shape() == ChartShape::Sphere);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d p = interpolateOnReference(d, x, y, z, Eigen::Vector3d(1, 1, 1) / 3);
  CHECK(p.norm() == Approx(1).epsilon(1e-15));
  CHECK(p.x() == Approx(1 / std::sqrt(3.0)));
  CHECK(referenceOrientation(d, x, y, z) > 0);  // counter-clockwise seen from outside
  CHECK(referenceOrientation(d, x, z, y) < 0);
  const Eigen::Vector2d uv = chartCoordinates(d, y);
  CHECK(uv.x() == Approx(M_PI / 2));
  CHECK(uv.y() == Approx(M_PI / 2));
}
