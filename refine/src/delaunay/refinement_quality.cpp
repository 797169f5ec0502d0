// refinement_quality.cpp — per-triangle angle and circumradius statistics of a triangulation (refinement_quality.h).
#include "conformesh/refine/delaunay/refinement_quality.h"

#include <algorithm>
#include <cmath>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"

namespace conformesh::refine {

QualityReport measureQuality(const intrinsic::IntrinsicTriangulation& tri) {
  QualityReport q;
  const int nF = tri.mesh.nFaces();
  q.vertices = tri.mesh.nVertices();
  q.triangles = nF;
  q.angleHistogram.assign(static_cast<int>(180 / q.histogramBinDeg), 0);
  const double deg = 180 / M_PI;
  q.minAngleDeg = nF > 0 ? 180 : 0;
  int below30 = 0;
  for (int f = 0; f < nF; ++f) {
    double smallest = INFINITY, shortest = INFINITY;
    for (int k = 0; k < 3; ++k) {
      const double a = intrinsic::cornerAngle(tri, 3 * f + k) * deg;
      smallest = std::min(smallest, a);
      q.maxAngleDeg = std::max(q.maxAngleDeg, a);
      const int bin =
          std::clamp(static_cast<int>(a / q.histogramBinDeg), 0, static_cast<int>(q.angleHistogram.size()) - 1);
      ++q.angleHistogram[bin];
      shortest = std::min(shortest, tri.length(3 * f + k));
    }
    q.minAngleDeg = std::min(q.minAngleDeg, smallest);
    q.meanMinAngleDeg += smallest;
    if (smallest < 30) ++below30;
    const double r = intrinsic::faceCircumradius(tri, f);
    q.maxCircumradius = std::max(q.maxCircumradius, r);
    q.meanCircumradius += r;
    q.maxRadiusEdgeRatio = std::max(q.maxRadiusEdgeRatio, r / shortest);
  }
  if (nF > 0) {
    q.meanMinAngleDeg /= nF;
    q.meanCircumradius /= nF;
    q.fractionBelow30 = static_cast<double>(below30) / nF;
  }
  q.nonDelaunayEdges = intrinsic::countNonDelaunayEdges(tri, 1e-12);
  q.gaussBonnetResidual = intrinsic::curvatureTotals(tri).gaussBonnetResidual;
  return q;
}

}  // namespace conformesh::refine
