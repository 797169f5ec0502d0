// The issue-21 core: the Kerr horizon r = r₊ of Kerr–Schild coordinates (a coordinate spheroid), fitted as a
// Strahlkörper in the analytic Kerr–Schild γ (also with the black hole and the shape translated), remeshed by the
// whole pipeline: Gauss–Bonnet with the output's own lengths to round-off, the mesh area close to Smarr's 8πMr₊, and
// the Gaussian curvature measure converging at first order (paper Theorem 3.4) over three coarse sizes.
#include <catch2/catch.hpp>

#include "support/gauss_bonnet_bound.h"

#include <cmath>
#include <cstdio>

#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/refine/pipeline/metric_remesh.h"

using namespace conformesh;
using namespace conformesh::intrinsic;
using namespace conformesh::refine;

TEST_CASE("horizon remesh: Kerr horizons in Kerr-Schild coordinates, Gauss-Bonnet and first-order e_G") {
  for (double a : {0.8, 0.95})
    for (const Eigen::Vector3d& c : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.7, -1.3, 2.1)}) {
      const double rp = 1 + std::sqrt(1 - a * a), A2 = rp * rp + a * a, C2 = rp * rp;
      const Strahlkorper shape = fitStrahlkorper(
          [&](double t, double) {
            return 1 / std::sqrt(std::pow(std::sin(t), 2) / A2 + std::pow(std::cos(t), 2) / C2);
          },
          16, c);
      const HorizonSurfaceMetric m(shape, std::make_shared<KerrSchildMetric>(1.0, a, c));
      INFO(m.description());
      std::vector<double> meanR, eG;
      for (double eps : {0.12, 0.085, 0.06}) {
        RemeshOptions o;
        o.epsilon = eps;
        o.t0Resolution = 8;  // the coarsest T0, so that ε, not T0, sets the output size
        const RemeshResult r = remeshMetric(m, o);
        REQUIRE(r.invertedTriangles == 0);
        CHECK(r.mesh.mesh.eulerCharacteristic() == 2);
        CHECK(std::abs(curvatureTotals(r.mesh).gaussBonnetResidual) <= conformesh::testing::gaussBonnetRoundoff(r.mesh.mesh.nFaces()));
        // Chords for arcs: the mesh area is below the smooth one by O(ε²/R²) < 1 % at ε = 0.12, R ≈ 1.8.
        CHECK(std::abs(totalArea(r.mesh) - 8 * M_PI * rp) < 0.03 * 8 * M_PI * rp);
        CHECK(r.quality.minAngleDeg >= 20.7);
        meanR.push_back(r.quality.meanCircumradius);
        eG.push_back(gaussianCurvatureMeasure(r.mesh, r.reference, m).meanAbsoluteError);
      }
      std::printf("%s: e_G %g %g %g, mean circumradius %g %g %g, slope %g\n", m.description().c_str(), eG[0], eG[1], eG[2], meanR[0], meanR[1], meanR[2], fitLogLogSlope(meanR, eG));
      INFO("e_G " << eG[0] << " " << eG[1] << " " << eG[2] << " slope " << fitLogLogSlope(meanR, eG));
      CHECK(fitLogLogSlope(meanR, eG) >= 0.9);
    }
}
