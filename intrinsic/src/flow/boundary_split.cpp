// boundary_split.cpp — boundary edges split at their midpoints (boundary_split.h).
#include "flow/boundary_split.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic::detail {

namespace {

// The angle opposite side l of a Euclidean triangle with sides l, a, b, with the flow's extension to lengths that
// violate the triangle inequality (π opposite a side at least the sum of the other two, 0 opposite the others).
double extendedOppositeAngle(double l, double a, double b) {
  if (l >= a + b) return M_PI;
  if (a >= l + b || b >= l + a) return 0;
  return std::acos(std::clamp((a * a + b * b - l * l) / (2 * a * b), -1.0, 1.0));
}

}  // namespace

std::vector<int> boundaryEdgesOpposite(const IntrinsicTriangulation& current, double minAngle) {
  const HalfedgeMesh& m = current.mesh;
  std::vector<std::pair<double, int>> found;
  for (int e = 0; e < m.nEdges(); ++e) {
    if (!m.isBoundaryEdge(e)) continue;
    const int h = m.edgeHalfedge(e);
    const double opposite = extendedOppositeAngle(current.length(h), current.length(HalfedgeMesh::next(h)),
                                                  current.length(HalfedgeMesh::prev(h)));
    if (opposite >= minAngle) found.emplace_back(-opposite, e);
  }
  std::sort(found.begin(), found.end());
  std::vector<int> edges;
  for (const auto& [angle, e] : found) edges.push_back(e);
  return edges;
}

std::vector<int> boundaryEdgesAt(const IntrinsicTriangulation& current, int v) {
  const HalfedgeMesh& m = current.mesh;
  std::vector<int> edges;
  if (v < 0 || v >= m.nVertices() || !m.isBoundaryVertex(v)) return edges;
  for (int e = 0; e < m.nEdges(); ++e) {
    if (!m.isBoundaryEdge(e)) continue;
    const int h = m.edgeHalfedge(e);
    if ((m.tail(h) == v) != (m.tip(h) == v)) edges.push_back(e);
  }
  return edges;
}

BoundarySplit splitBoundaryEdges(const IntrinsicTriangulation& input, const std::vector<int>& edges) {
  BoundarySplit out{input, {}};
  HalfedgeMesh& m = out.tri.mesh;
  std::vector<double>& length = out.tri.edgeLengths;
  for (const int e : edges) {
    if (e < 0 || e >= input.mesh.nEdges() || !input.mesh.isBoundaryEdge(e) ||
        input.mesh.tail(input.mesh.edgeHalfedge(e)) == input.mesh.tip(input.mesh.edgeHalfedge(e)))
      throw InputError("splitBoundaryEdges: edge " + std::to_string(e) +
                       ": expected a boundary edge of the input with two distinct ends");
    // The face (a, b, c) on e = a → b, with its lengths before the split (an earlier split may have changed it).
    const int h = m.edgeHalfedge(e);
    const double l = length[e], ca = length[m.edge(HalfedgeMesh::prev(h))], bc = length[m.edge(HalfedgeMesh::next(h))];
    const int p = m.splitEdge(e);  // e keeps a → p; new edges p → b, p – c (halfedge_mesh.h)
    length.resize(m.nEdges());
    length[e] = length[m.nEdges() - 2] = 0.5 * l;
    length[m.nEdges() - 1] = std::sqrt(std::max(0.0, 0.5 * (ca * ca + bc * bc) - 0.25 * l * l));
    out.inserted.push_back({p, e, 0.5});
  }
  validateLengths(out.tri, "the input with boundary edges split");
  return out;
}

std::vector<Uniformization::InsertedVertex> composeInserted(const IntrinsicTriangulation& input,
                                                            const BoundarySplit& split,
                                                            const std::vector<Uniformization::InsertedVertex>& inner) {
  const HalfedgeMesh& in = input.mesh;
  const HalfedgeMesh& sub = split.tri.mesh;
  const int n = in.nVertices();
  std::vector<Uniformization::InsertedVertex> out = split.inserted;
  // A vertex of split.tri on input edge ie, at parameter t along it: input vertices at 0 or 1, new ones at ½.
  auto parameterOn = [&](int v, int ie) {
    if (v >= n) return 0.5;
    return v == in.tail(in.edgeHalfedge(ie)) ? 0.0 : 1.0;
  };
  for (const Uniformization::InsertedVertex& q : inner) {
    const int h = sub.edgeHalfedge(q.inputEdge), x = sub.tail(h), y = sub.tip(h);
    // The input edge the sub edge lies on: its own index when unsplit (edges below in.nEdges() keep theirs), else the
    // edge its new end halves.
    const int ie = q.inputEdge < in.nEdges() ? q.inputEdge : split.inserted[std::max(x, y) - n].inputEdge;
    const double tx = parameterOn(x, ie), ty = parameterOn(y, ie);
    out.push_back({q.vertex, ie, tx + q.parameter * (ty - tx)});
  }
  return out;
}

}  // namespace conformesh::intrinsic::detail
