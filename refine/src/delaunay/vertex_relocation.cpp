// vertex_relocation.cpp — star layout, validity test and the relocation of an inserted interior vertex with its input
// location re-traced and its own and its neighbours' signposts re-derived (vertex_relocation.h).
#include "conformesh/refine/delaunay/vertex_relocation.h"

#include "trace/corner_angle.h"

#include <cmath>

#include "conformesh/refine/trace/robust_predicates.h"

namespace conformesh::refine {

using detail::fastCornerAngle;
using intrinsic::Background;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

std::optional<VertexStar> layoutStar(const IntrinsicTriangulation& tri, const Signposts& sp, int v, int inputVertices) {
  const HalfedgeMesh& m = tri.mesh;
  if (v < inputVertices || v >= m.nVertices() || m.isBoundaryVertex(v)) return std::nullopt;
  const BackgroundModel model(tri.background);
  VertexStar star;
  star.vertex = v;
  double sum = 0;
  const int start = m.vertexHalfedge(v);
  int h = start;
  do {
    if (m.tip(h) == v) return std::nullopt;  // self-loop
    star.out.push_back(h);
    star.ring.push_back(model.polar(tri.length(h), sp.angle[h]));
    // The orientation predicate decides for points of an open hemisphere only: a spherical star must lie within
    // distance π/2 of v (z > 0 in the model). Refined stars are far smaller; this only guards coarse input.
    if (tri.background == Background::Spherical && !(star.ring.back().z() > 0)) return std::nullopt;
    sum += fastCornerAngle(tri, h);
    h = m.nextOutgoing(h);
  } while (h != start);
  // 1e-9 rad: far above the round-off of a sum of a few corner angles (~1e-15), far below any cone angle a
  // uniformization leaves (input vertices are excluded above anyway).
  if (std::abs(sum - 2 * M_PI) > 1e-9) return std::nullopt;
  return star;
}

bool isValidStarPosition(const IntrinsicTriangulation& tri, const VertexStar& star, const Vec3& p) {
  if (!p.allFinite()) return false;
  if (tri.background == Background::Spherical && !(p.z() > 0)) return false;
  const BackgroundModel model(tri.background);
  const int d = static_cast<int>(star.out.size());
  for (int i = 0; i < d; ++i) {
    const Vec3 &a = star.ring[i], &b = star.ring[(i + 1) % d];
    if (orientationSign(p, a, b) <= 0) return false;
    const double outer = tri.length(HalfedgeMesh::next(star.out[i]));
    if (!intrinsic::isValidTriangle(tri.background, outer, model.distance(p, a), model.distance(p, b))) return false;
  }
  return true;
}

bool relocateVertex(IntrinsicTriangulation& tri, Signposts& sp, std::vector<InputLocation>& locations,
                    const InputSurface& input, const VertexStar& star, const Vec3& p) {
  if (!isValidStarPosition(tri, star, p)) return false;
  const BackgroundModel model(tri.background);
  const Vec3 O = BackgroundModel::origin();
  const double r = model.distance(O, p);
  if (!(r > 0)) return false;
  const int v = star.vertex;
  // The geodesic v → p is the segment O → p of the layout; it stays inside the star triangle containing p (convex), so
  // it exists on the input as well (refinement never changes the metric) and is followed there from v's location.
  // Its direction at O is atan2(y, x) in every model: the canonical frame at O is (e1, e2) and the tangent toward p
  // is proportional to (p.x, p.y, 0).
  const InputSurface::Arrival arr = input.follow(v, false, locations[v], std::atan2(p.y(), p.x()), r);
  if (arr.leftSurface) return false;

  const HalfedgeMesh& m = tri.mesh;
  const int d = static_cast<int>(star.out.size());
  for (int i = 0; i < d; ++i) tri.edgeLengths[m.edge(star.out[i])] = model.distance(p, star.ring[i]);
  // v's new frame is the canonical frame of its new input face at its new location. The geodesic arrives at p with
  // tangent −tangentToward(p, O) in the layout and at angle arr.angle in the new frame; a direction at p is carried
  // from the layout's frame to the new one by that difference (as for an inserted vertex, delaunay_refinement.cpp).
  const double arrivalHere = model.angleOf(p, -model.tangentToward(p, O));
  sp.angle[star.out[0]] =
      sp.reduce(v, model.angleOf(p, model.tangentToward(p, star.ring[0])) - arrivalHere + arr.angle);
  // The others by the new corner angles, so that the invariant of signposts.h holds with the new lengths exactly.
  for (int i = 1; i < d; ++i)
    sp.angle[star.out[i]] = sp.turned(tri, star.out[i - 1], fastCornerAngle(tri, star.out[i - 1]));
  // Neighbour u_i = tip(out[i]): its halfedge u_i → v is nextOutgoing(u_i → u_{i+1}) = twin(out[i]), turned from the
  // unchanged outer halfedge next(out[i]) by the new corner of star triangle i at u_i.
  for (int i = 0; i < d; ++i) {
    const int outer = HalfedgeMesh::next(star.out[i]);
    sp.angle[m.twin(star.out[i])] = sp.turned(tri, outer, fastCornerAngle(tri, outer));
  }
  locations[v] = arr.location;
  return true;
}

}  // namespace conformesh::refine
