// curvature.h — discrete Gaussian curvature of an intrinsic triangulation: angle deficits at interior vertices (paper
// eq. 1's G(v)), geodesic curvature (turning angle) at boundary vertices, and the Gauss–Bonnet balance.
#pragma once

#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

// Σ of corner angles at each vertex.
std::vector<double> angleSums(const IntrinsicTriangulation& tri);

// Per vertex: 2π − Σθ at interior vertices (angle deficit), π − Σθ at boundary vertices (turning angle, the discrete
// geodesic curvature of the boundary).
std::vector<double> vertexCurvatures(const IntrinsicTriangulation& tri);

struct CurvatureTotals {
  double interiorDeficit = 0;   // Σ over interior vertices of 2π − Σθ
  double boundaryTurning = 0;   // Σ over boundary vertices of π − Σθ
  double backgroundTerm = 0;    // K_background · total area (0 for Euclidean)
  int eulerCharacteristic = 0;
  // interiorDeficit + boundaryTurning + backgroundTerm − 2πχ: zero up to round-off for any valid triangulation.
  double gaussBonnetResidual = 0;
};
CurvatureTotals curvatureTotals(const IntrinsicTriangulation& tri);

}  // namespace conformesh::intrinsic
