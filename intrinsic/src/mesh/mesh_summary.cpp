// mesh_summary.cpp — gathers the figures of MeshSummary in a few linear passes.
#include "conformesh/intrinsic/mesh/mesh_summary.h"

#include <algorithm>

#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/mesh/mesh_components.h"

namespace conformesh::intrinsic {

MeshSummary summarize(const IntrinsicTriangulation& tri) {
  const HalfedgeMesh& m = tri.mesh;
  MeshSummary s;
  s.background = tri.background;
  s.vertices = m.nVertices();
  s.edges = m.nEdges();
  s.faces = m.nFaces();
  s.components = m.components();
  for (const auto& c : s.components) {
    s.boundaryLoops += c.boundaryLoops;
    s.genus += c.genus;
  }
  s.eulerCharacteristic = m.eulerCharacteristic();
  s.curvature = curvatureTotals(tri);
  s.totalArea = totalArea(tri);
  const std::vector<double> angles = allCornerAngles(tri);
  const auto [lo, hi] = std::minmax_element(angles.begin(), angles.end());
  s.minCornerAngle = *lo;
  s.maxCornerAngle = *hi;
  const std::vector<double> sums = angleSums(tri);
  if (!sums.empty()) {
    const auto low = std::min_element(sums.begin(), sums.end());
    s.minAngleSum = *low;
    s.minAngleSumVertex = static_cast<int>(low - sums.begin());
  }
  const auto [lmin, lmax] = std::minmax_element(tri.edgeLengths.begin(), tri.edgeLengths.end());
  s.minEdgeLength = *lmin;
  s.maxEdgeLength = *lmax;
  int interior = 0;
  for (int e = 0; e < m.nEdges(); ++e) interior += !m.isBoundaryEdge(e);
  s.nonDelaunayEdges = countNonDelaunayEdges(tri);
  s.nonDelaunayFraction = interior > 0 ? static_cast<double>(s.nonDelaunayEdges) / interior : 0.0;
  if (s.components.size() > 1)
    for (const MeshComponent& c : splitComponents(tri))
      s.componentFigures.push_back({totalArea(c.triangulation), curvatureTotals(c.triangulation)});
  return s;
}

}  // namespace conformesh::intrinsic
