// curvature.cpp — angle sums, angle deficits / boundary turning angles, and the Gauss–Bonnet balance.
#include "conformesh/intrinsic/mesh/curvature.h"

#include <cmath>

namespace conformesh::intrinsic {

namespace {
// Neumaier's compensated sum: Gauss–Bonnet residuals must reach round-off at a million vertices.
struct CompensatedSum {
  double sum = 0, comp = 0;
  void add(double x) {
    const double t = sum + x;
    comp += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  }
  double value() const { return sum + comp; }
};
}  // namespace

std::vector<double> angleSums(const IntrinsicTriangulation& tri) {
  std::vector<double> sums(tri.mesh.nVertices(), 0.0);
  const std::vector<double> angles = allCornerAngles(tri);
  for (int h = 0; h < tri.mesh.nHalfedges(); ++h) sums[tri.mesh.tail(h)] += angles[h];
  return sums;
}

std::vector<double> vertexCurvatures(const IntrinsicTriangulation& tri) {
  std::vector<double> k = angleSums(tri);
  for (int v = 0; v < tri.mesh.nVertices(); ++v) k[v] = (tri.mesh.isBoundaryVertex(v) ? M_PI : 2 * M_PI) - k[v];
  return k;
}

CurvatureTotals curvatureTotals(const IntrinsicTriangulation& tri) {
  const std::vector<double> k = vertexCurvatures(tri);
  CompensatedSum interior, boundary;
  for (int v = 0; v < tri.mesh.nVertices(); ++v) (tri.mesh.isBoundaryVertex(v) ? boundary : interior).add(k[v]);
  CurvatureTotals t;
  t.interiorDeficit = interior.value();
  t.boundaryTurning = boundary.value();
  const double kb = backgroundCurvature(tri.background);
  t.backgroundTerm = kb == 0 ? 0.0 : kb * totalArea(tri);
  t.eulerCharacteristic = tri.mesh.eulerCharacteristic();
  CompensatedSum residual;
  residual.add(t.interiorDeficit);
  residual.add(t.boundaryTurning);
  residual.add(t.backgroundTerm);
  residual.add(-2 * M_PI * t.eulerCharacteristic);
  t.gaussBonnetResidual = residual.value();
  return t;
}

}  // namespace conformesh::intrinsic
