// test_teapot_data.cpp — the Utah teapot patches: the data's structure (shared boundaries between neighbouring patches,
// the body's fourfold symmetry, collapsed sides only where expected), a patch's metric against an independent
// computation (area of the patch by fine 3-D triangulation), and T0 of a patch converging at second order (the paper's
// Fig. 8 experiment starts here).
#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/teapot_data.h"

using namespace conformesh;
using namespace conformesh::intrinsic;

TEST_CASE("teapot data: shared boundaries, symmetry, degenerate patches") {
  // Rim patch 0's v = 1 side is body patch 4's v = 0 side (indices 13..16 in both).
  for (double u : {0.0, 0.3, 0.8, 1.0}) {
    const Eigen::Vector3d a = evaluateBezierPatch(teapotPatch(0), u, 1).x,
                          b = evaluateBezierPatch(teapotPatch(4), u, 0).x;
    CHECK((a - b).norm() < 1e-15);
  }
  // Body patches 4..7 are quarter turns of each other about the z axis (Newell's data, up to the rounding of the
  // circle-approximating control points, which is symmetric).
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (double u : {0.2, 0.7})
    for (double v : {0.1, 0.6}) {
      const Eigen::Vector3d p4 = evaluateBezierPatch(teapotPatch(4), u, v).x;
      const Eigen::Vector3d p5 = evaluateBezierPatch(teapotPatch(5), u, v).x;
      CHECK((quarter * p4 - p5).norm() < 1e-12);
    }
  int degenerate = 0;
  for (int k = 0; k < kTeapotPatchCount; ++k) degenerate += teapotPatchIsDegenerate(k);
  CHECK(degenerate == 8);
  CHECK(teapotPatchIsDegenerate(20));
  CHECK(teapotPatchIsDegenerate(31));
  REQUIRE_THROWS_WITH(makeTeapotPatch(21), Catch::Contains("patch 21") && Catch::Contains("collapsed"));
  REQUIRE_THROWS_WITH(makeTeapotPatch(32), Catch::Contains("0..31"));
}

TEST_CASE("teapot patch metric: area against a fine 3-D triangulation, K consistent with Brioschi") {
  auto m = makeTeapotPatch(4);
  const double area = metricArea(*m).value;
  // Independent: Σ of 3-D triangle areas on an n×n grid of the patch (error O(1/n²), Richardson-extrapolated).
  auto meshArea = [&](int n) {
    double s = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Eigen::Vector3d a = m->position(double(i) / n, double(j) / n),
                              b = m->position(double(i + 1) / n, double(j) / n),
                              c = m->position(double(i + 1) / n, double(j + 1) / n),
                              d = m->position(double(i) / n, double(j + 1) / n);
        s += 0.5 * ((b - a).cross(c - a).norm() + (c - a).cross(d - a).norm());
      }
    return s;
  };
  const double extrapolated = (4 * meshArea(400) - meshArea(200)) / 3;
  CHECK(area == Approx(extrapolated).epsilon(1e-8));
  for (double u : {0.1, 0.5, 0.9})
    for (double v : {0.2, 0.7})
      CHECK(brioschiCurvature(m->jet(u, v)) == Approx(m->gaussianCurvature(u, v)).margin(1e-7));
}

TEST_CASE("teapot patch T0: grid of the rectangle, area at second order, Gauss-Bonnet") {
  auto m = makeTeapotPatch(4);
  const double area = metricArea(*m).value;
  std::vector<double> hs, errors;
  for (int N : {4, 8, 16, 32}) {
    DiscretizationOptions o;
    o.resolution = N;
    DiscretizationReport rep;
    const IntrinsicTriangulation tri = toTriangulation(discretizeMetric(*m, o, &rep));
    CHECK(tri.mesh.eulerCharacteristic() == 1);
    CHECK(std::abs(curvatureTotals(tri).gaussBonnetResidual) < 1e-10);
    hs.push_back(1.0 / N);
    errors.push_back(std::abs(totalArea(tri) - area) / area);
    std::cout << "teapot patch 4 N=" << N << " V=" << rep.vertices << " area rel.err=" << errors.back() << " min angle "
              << rep.minAngle * 180 / M_PI << " deg\n";
  }
  const double order = fitLogLogSlope(hs, errors);
  std::cout << "teapot patch 4: area order " << order << "\n";
  CHECK(order == Approx(2).margin(0.2));
}
