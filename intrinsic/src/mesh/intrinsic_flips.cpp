// intrinsic_flips.cpp — isometric intrinsic edge flips and Lawson's flip algorithm to the intrinsic Delaunay
// triangulation (Bobenko–Springborn, "A discrete Laplace–Beltrami operator for simplicial surfaces", 2007).
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"

#include <cmath>
#include <string>
#include <algorithm>
#include <vector>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

bool flipEdge(IntrinsicTriangulation& tri, int e) {
  HalfedgeMesh& m = tri.mesh;
  const int ha = m.edgeHalfedge(e), hb = m.twin(ha);
  if (hb == kInvalid || HalfedgeMesh::face(ha) == HalfedgeMesh::face(hb)) return false;
  // Faces (a, b, c) and (b, a, d). The quad is convex at a and b iff the two corner angles there sum below π; only then
  // is the other diagonal a geodesic inside the quad and the flip an isometry.
  const double thetaA = cornerAngle(tri, ha) + cornerAngle(tri, HalfedgeMesh::next(hb));
  const double thetaB = cornerAngle(tri, HalfedgeMesh::next(ha)) + cornerAngle(tri, hb);
  if (!(thetaA < M_PI && thetaB < M_PI)) return false;
  const double lCa = tri.length(HalfedgeMesh::prev(ha)), lAd = tri.length(HalfedgeMesh::next(hb));
  const double lBc = tri.length(HalfedgeMesh::next(ha)), lDb = tri.length(HalfedgeMesh::prev(hb));
  const double lCd = thirdSide(tri.background, lCa, lAd, thetaA);
  // Round-off can make a nearly degenerate new triangle fail the strict inequality; refuse rather than create it.
  if (!isValidTriangle(tri.background, lCd, lCa, lAd) || !isValidTriangle(tri.background, lCd, lDb, lBc)) return false;
  m.flip(e);
  tri.edgeLengths[e] = lCd;
  return true;
}

int countNonDelaunayEdges(const IntrinsicTriangulation& tri, double tolerance) {
  int count = 0;
  for (int e = 0; e < tri.mesh.nEdges(); ++e)
    if (delaunayMargin(tri, e) < -tolerance) ++count;
  return count;
}

DelaunayReport makeDelaunay(IntrinsicTriangulation& tri, const DelaunayOptions& options) {
  HalfedgeMesh& m = tri.mesh;
  DelaunayReport report;
  std::vector<int> stack;
  std::vector<char> queued(m.nEdges(), 0);
  stack.reserve(m.nEdges());
  for (int e = m.nEdges() - 1; e >= 0; --e) {
    if (m.isBoundaryEdge(e)) continue;
    if (delaunayMargin(tri, e) < -options.tolerance) ++report.nonDelaunayBefore;
    stack.push_back(e);
    queued[e] = 1;
  }
  const std::int64_t cap = options.maxFlipsPerEdge * static_cast<std::int64_t>(std::max(1, m.nEdges()));
  while (!stack.empty()) {
    const int e = stack.back();
    stack.pop_back();
    queued[e] = 0;
    if (delaunayMargin(tri, e) >= -options.tolerance) continue;
    if (!flipEdge(tri, e)) continue;  // a non-Delaunay edge of a valid metric is flippable; see countNonDelaunayEdges
    if (++report.flips > cap)
      throw ConvergenceError("Delaunay flipping exceeded " + std::to_string(cap) +
                             " flips; the edge lengths are probably not a valid metric");
    if (options.onFlip) options.onFlip(e);
    const int h = m.edgeHalfedge(e), t = m.twin(h);
    for (int g : {HalfedgeMesh::next(h), HalfedgeMesh::prev(h), HalfedgeMesh::next(t), HalfedgeMesh::prev(t)}) {
      const int eg = m.edge(g);
      if (!queued[eg] && !m.isBoundaryEdge(eg)) {
        queued[eg] = 1;
        stack.push_back(eg);
      }
    }
  }
  return report;
}

}  // namespace conformesh::intrinsic
