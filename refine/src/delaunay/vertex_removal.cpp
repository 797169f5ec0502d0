// vertex_removal.cpp — flipping an inserted vertex down to degree 3 and merging its last three faces
// (vertex_removal.h).
#include "conformesh/refine/delaunay/vertex_removal.h"

#include "trace/corner_angle.h"

#include <algorithm>
#include <cmath>

namespace conformesh::refine {

using detail::fastCornerAngle;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

// Why a flip exists. Lay v's star out in the model (geodesics are straight there): the link is a simple polygon P with
// d ≥ 4 vertices u_i and v in its kernel. Flipping edge v u_i is admissible iff the quad (v, u_{i−1}, u_i, u_{i+1}) is
// strictly convex: convex at u_i, and v outside the closed triangle u_{i−1} u_i u_{i+1} (then the angle at v is below
// π). An ear of P (Meisters' two-ears theorem: P has two, with disjoint interiors) is convex at its tip, and v lies in
// the interior of at most one of the two; v cannot lie on an ear's sides along P (it is interior to P), so the other
// ear is admissible unless v lies exactly on its diagonal — a degenerate star, e.g. v at the crossing of the diagonals
// of a convex quad, where no strict flip exists. Each flip cuts an ear off and leaves v in the kernel of the smaller
// link, so the argument repeats down to degree 3. In floating point a flip may also be refused near that degeneracy.
VertexRemovalResult removeInsertedVertex(IntrinsicTriangulation& tri, Signposts& sp, int v, int inputVertices,
                                         const std::function<void(int)>& onFlip) {
  VertexRemovalResult res;
  HalfedgeMesh& m = tri.mesh;
  if (v < inputVertices || v >= m.nVertices() || m.isBoundaryVertex(v)) return res;
  double sum = 0;
  int degree = 0;
  const int start = m.vertexHalfedge(v);
  int h = start;
  do {
    if (m.tip(h) == v) return res;  // self-loop: v is its own neighbour, the star is not a disk around v
    res.regionEdges.push_back(m.edge(HalfedgeMesh::next(h)));
    sum += fastCornerAngle(tri, h);
    ++degree;
    h = m.nextOutgoing(h);
  } while (h != start);
  // 1e-9 rad, as for vertex relocation: far above the round-off of a few corner angles, far below any cone angle.
  if (std::abs(sum - 2 * M_PI) > 1e-9) return res;

  // Which ear to cut: the admissible one with the widest margin min(π − angle at v, π − angle at u_i) of its quad. A
  // quad that is barely convex at v would leave a sliver (v, u_{i−1}, u_{i+1}) whose small angles the lengths fix only
  // poorly (measured: a 2·10⁻⁸ error in neighbouring angle sums on a flat torus when the first admissible flip was
  // taken); the widest margin keeps every intermediate triangle as fat as the star allows.
  const int maxFlips = 10 * degree;
  while (degree > 3) {
    int best = kInvalid;
    double bestMargin = 0;
    const int s = m.vertexHalfedge(v);
    h = s;
    do {
      const int g = m.twin(h);
      const double atV = fastCornerAngle(tri, h) + fastCornerAngle(tri, HalfedgeMesh::next(g));
      const double atU = fastCornerAngle(tri, HalfedgeMesh::next(h)) + fastCornerAngle(tri, g);
      const double margin = std::min(M_PI - atV, M_PI - atU);
      if (margin > bestMargin) bestMargin = margin, best = m.edge(h);
      h = m.nextOutgoing(h);
    } while (h != s);
    if (best == kInvalid || !flipWithSignposts(tri, sp, best)) return res;
    ++res.flips;
    --degree;
    res.regionEdges.push_back(best);  // edge indices survive flips: `best` is now a diagonal of the link
    if (onFlip) onFlip(best);
    if (res.flips > maxFlips) return res;
  }
  // The merged face's lengths must form a triangle; they do whenever v is strictly inside it, but a star flattened
  // by round-off could leave them degenerate.
  const int h0 = m.vertexHalfedge(v);
  const int h1 = m.nextOutgoing(h0), h2 = m.nextOutgoing(h1);
  if (!intrinsic::isValidTriangle(tri.background, tri.length(HalfedgeMesh::next(h0)),
                                  tri.length(HalfedgeMesh::next(h1)), tri.length(HalfedgeMesh::next(h2))))
    return res;
  if (!m.removeDegree3Vertex(v, res.moves, res.mergedFace)) return res;
  res.removed = true;
  intrinsic::applyMoves(tri.edgeLengths, res.moves.edges, m.nEdges());
  intrinsic::applyMoves(sp.angle, res.moves.halfedges, m.nHalfedges());
  intrinsic::applyMoves(sp.period, res.moves.vertices, m.nVertices());
  for (int& e : res.regionEdges)
    for (const auto& mv : res.moves.edges)
      if (mv.first == e) {
        e = mv.second;
        break;
      }
  std::sort(res.regionEdges.begin(), res.regionEdges.end());
  res.regionEdges.erase(std::unique(res.regionEdges.begin(), res.regionEdges.end()), res.regionEdges.end());
  return res;
}

}  // namespace conformesh::refine
