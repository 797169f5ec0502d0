// refinement_quality.h — the quality figures reported after every refinement run (paper §6.1, Fig. 10): counts,
// smallest angle, mean per-triangle smallest angle, largest and mean circumradius, share of triangles with an angle
// under 30°, a histogram of all corner angles, and the checks the output must pass (Delaunay, Gauss–Bonnet).
// Circumradii are in the background metric of the triangulation (the uniformized domain), not the original surface's.
// Reads the triangulation only.
#pragma once

#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::refine {

struct QualityReport {
  int vertices = 0, triangles = 0;
  double minAngleDeg = 0;      // smallest corner angle over all triangles
  double meanMinAngleDeg = 0;  // mean over triangles of each triangle's smallest angle
  double maxAngleDeg = 0;
  double maxCircumradius = 0;  // +inf if a hyperbolic triangle has no circumcircle
  double meanCircumradius = 0;
  double maxRadiusEdgeRatio = 0;    // max circumradius / shortest edge
  double fractionBelow30 = 0;       // share of triangles whose smallest angle is < 30°
  std::vector<int> angleHistogram;  // all corner angles, bins of histogramBinDeg degrees over [0°, 180°)
  double histogramBinDeg = 10;
  int nonDelaunayEdges = 0;        // interior edges with delaunayMargin < −1e-12 (0 for a refinement output)
  double gaussBonnetResidual = 0;  // Σ curvature + K·area − 2πχ (round-off for any valid triangulation)
};

// The report of `tri` (any background, with or without boundary); angles in degrees, circumradii in its lengths' unit.
QualityReport measureQuality(const intrinsic::IntrinsicTriangulation& tri);

}  // namespace conformesh::refine
