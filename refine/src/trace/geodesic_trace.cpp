// geodesic_trace.cpp — straight-segment walks through unfolded triangles with exact orientation decisions
// (geodesic_trace.h); one walk serves the refinement, input_location.h and the mesh pull-back.
#include "conformesh/refine/trace/geodesic_trace.h"

#include "trace/corner_angle.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/trace/robust_predicates.h"

namespace conformesh::refine {

using detail::fastCornerAngle;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

namespace {

// Euclidean third vertex: with L = |AB|, a = |AX|, b = |BX|, X = A + x·u + y·u⊥ where x = (L² + a² − b²) / (2L) is the
// projection on u = (B − A)/|B − A| and y = 2·area / L its height (area by Kahan's Heron: accurate for needles). The
// coordinates carry an absolute error of a few ulps of the side lengths, as the rotate-by-the-angle construction does.
Vec3 euclideanThird(const Vec3& A, const Vec3& B, double L, double a, double b) {
  const double x = (L * L + a * a - b * b) / (2 * L), y = detail::fourAreaEuclidean(L, a, b) / (2 * L);
  // The direction is normalized by the stored length L rather than the layout's |B − A| (they differ by round-off):
  // this spares a hypot in the innermost loop of every walk.
  const double ux = (B.x() - A.x()) / L, uy = (B.y() - A.y()) / L;
  return Vec3(A.x() + x * ux - y * uy, A.y() + x * uy + y * ux, 1.0);
}

}  // namespace

std::array<Vec3, 3> layoutAtHalfedge(const IntrinsicTriangulation& tri, const BackgroundModel& model, int h) {
  const int k = h % 3;
  std::array<Vec3, 3> c;
  c[k] = BackgroundModel::origin();
  if (tri.background == intrinsic::Background::Euclidean) {
    const double L = tri.length(h), a = tri.length(HalfedgeMesh::prev(h)), b = tri.length(HalfedgeMesh::next(h));
    c[(k + 1) % 3] = Vec3(L, 0, 1);
    c[(k + 2) % 3] = Vec3((L * L + a * a - b * b) / (2 * L), detail::fourAreaEuclidean(L, a, b) / (2 * L), 1.0);
    return c;
  }
  c[(k + 1) % 3] = model.polar(tri.length(h), 0.0);
  c[(k + 2) % 3] = model.polar(tri.length(HalfedgeMesh::prev(h)), fastCornerAngle(tri, h));
  return c;
}

Vec3 unfoldThirdVertex(const IntrinsicTriangulation& tri, const BackgroundModel& model, int g, const Vec3& tailG,
                       const Vec3& tipG) {
  if (tri.background == intrinsic::Background::Euclidean)
    return euclideanThird(tailG, tipG, tri.length(g), tri.length(HalfedgeMesh::prev(g)),
                          tri.length(HalfedgeMesh::next(g)));
  return model.thirdVertex(tailG, tipG, fastCornerAngle(tri, g), tri.length(HalfedgeMesh::prev(g)));
}

std::array<Vec3, 3> layoutFace(const IntrinsicTriangulation& tri, const BackgroundModel& model, int f) {
  return layoutAtHalfedge(tri, model, 3 * f);
}

namespace {

// The crossing of s → t with edge (P[k], P[k+1]): in all three models geodesics are planes through 0, so the crossing
// is the intersection line of the two planes; projective barycentric coordinates ignore its scale and sign.
EdgeCrossing crossingOf(const BackgroundModel& model, const std::array<Vec3, 3>& P, const Vec3& s, const Vec3& t,
                        int face, int k) {
  const Vec3 X = (s.cross(t)).cross(P[k].cross(P[(k + 1) % 3]));
  Eigen::Vector3d beta = model.barycentric(P[0], P[1], P[2], X);
  beta[(k + 2) % 3] = 0;
  for (int i = 0; i < 3; ++i) beta[i] = std::max(beta[i], 0.0);
  return {3 * face + k, beta / beta.sum()};
}

// The walk. `exitMask` bit k allows leaving through the edge of halfedge 3f+k of the first face: from a vertex only
// the opposite edge is a way out; from a general point all three are (the first face is the one containing the start,
// or the boundary face whose cap contains it, for which the boundary edge is an entry and fails the exit test).
TraceResult walk(const IntrinsicTriangulation& tri, const BackgroundModel& model, int face, std::array<Vec3, 3> P,
                 const Vec3& s, const Vec3& t, unsigned exitMask, const TraceOptions& options) {
  const HalfedgeMesh& m = tri.mesh;
  // NaN coordinates would make every orientation test false (and the exact fallback meaningless): stop with the face.
  if (!s.allFinite() || !t.allFinite() || !P[0].allFinite() || !P[1].allFinite() || !P[2].allFinite())
    throw ConvergenceError("geodesic trace from face " + std::to_string(face) + ": start (" + formatNumber(s.x()) +
                           ", " + formatNumber(s.y()) + ", " + formatNumber(s.z()) + ") or target (" +
                           formatNumber(t.x()) + ", " + formatNumber(t.y()) + ", " + formatNumber(t.z()) +
                           ") or the face's layout is not finite");
  TraceResult r;
  r.start = s;
  r.end = t;
  // A geodesic of length ℓ crosses O(ℓ/h) triangles; 20 visits per face plus a constant is far beyond any legitimate
  // walk (which crosses each triangle of a copy of the surface once per wrap) and stops a walk that cycles around a
  // vertex on exactly degenerate input instead of hanging.
  const long long maxSteps = 20LL * m.nFaces() + 1000;
  for (;;) {
    ++r.steps;
    int o[3];
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
      o[k] = orientationSign(P[k], P[(k + 1) % 3], t);
      if ((exitMask >> k & 1) && o[k] < 0) inside = false;
    }
    if (inside) {
      r.face = face;
      r.corners = P;
      r.bary = model.barycentric(P[0], P[1], P[2], t);
      return r;
    }
    // Leave through edge k = (P[k], P[k+1]) when t is beyond it and the segment passes between its ends: P[k] on the
    // right of s→t, P[k+1] on its left.
    int exitK = -1;
    for (int k = 0; k < 3 && exitK < 0; ++k) {
      if (!(exitMask >> k & 1) || o[k] >= 0) continue;
      if (orientationSign(s, t, P[k]) <= 0 && orientationSign(s, t, P[(k + 1) % 3]) >= 0) exitK = k;
    }
    if (exitK < 0) {
      // Possible only when the layout's round-off makes t look beyond an edge that s→t does not cross (t within a few
      // ulps of that edge): the end point is in this face.
      r.face = face;
      r.corners = P;
      r.bary = model.barycentric(P[0], P[1], P[2], t);
      return r;
    }
    const int h = 3 * face + exitK, g = m.twin(h);
    if (g == kInvalid) {
      r.face = face;
      r.corners = P;
      r.bary = model.barycentric(P[0], P[1], P[2], t);
      r.boundaryHalfedge = h;
      return r;
    }
    if (r.steps > maxSteps)
      throw ConvergenceError("geodesic trace did not reach its end after " + std::to_string(r.steps) +
                             " triangles (the cap 20·faces + 1000 = " + std::to_string(maxSteps) + "; last face " +
                             std::to_string(face) + "): degenerate layout");
    if (options.crossings) options.crossings->push_back(crossingOf(model, P, s, t, face, exitK));
    // g runs Q = P[exitK+1] -> Pp = P[exitK] in the next face; its third vertex is unfolded on the far side.
    const Vec3 Pp = P[exitK], Q = P[(exitK + 1) % 3];
    const int kg = g % 3;
    face = HalfedgeMesh::face(g);
    P[kg] = Q;
    P[(kg + 1) % 3] = Pp;
    P[(kg + 2) % 3] = options.unfolding == Unfolding::LawOfCosines
                          ? unfoldThirdVertex(tri, model, g, Q, Pp)
                          : model.thirdVertex(Q, Pp, fastCornerAngle(tri, g), tri.length(HalfedgeMesh::prev(g)));
    exitMask = 7u & ~(1u << kg);
  }
}

// The walk from the vertex at the tail of w.halfedge, at angle w.offset from it inside its corner.
TraceResult walkFromWedge(const IntrinsicTriangulation& tri, const BackgroundModel& model, const Wedge& w,
                          double length, const TraceOptions& options) {
  const int h = w.halfedge, k = h % 3;
  const std::array<Vec3, 3> P = layoutAtHalfedge(tri, model, h);
  const Vec3 t = model.polar(length, w.offset);
  TraceResult r =
      walk(tri, model, HalfedgeMesh::face(h), P, BackgroundModel::origin(), t, 1u << ((k + 1) % 3), options);
  r.startHalfedge = h;
  return r;
}

}  // namespace

TraceResult traceFromPoint(const IntrinsicTriangulation& tri, const BackgroundModel& model, int face,
                           const std::array<Vec3, 3>& corners, const Vec3& start, const Vec3& target,
                           const TraceOptions& options) {
  return walk(tri, model, face, corners, start, target, 7u, options);
}

TraceResult traceFromVertex(const IntrinsicTriangulation& tri, const Signposts& sp, const BackgroundModel& model, int v,
                            double theta, double length, int hint, const TraceOptions& options) {
  const HalfedgeMesh& m = tri.mesh;
  // A non-finite direction or length (a circumcentre computed from a degenerate layout) matches no wedge; it would be
  // taken below for a direction leaving the surface, so it is stopped here with the numbers that produced it.
  if (!std::isfinite(theta) || !std::isfinite(length) || !(length >= 0))
    throw ConvergenceError("geodesic trace from vertex " + std::to_string(v) + ": direction " + formatNumber(theta) +
                           " rad, length " + formatNumber(length) + " (not finite): degenerate triangle at the start");
  Wedge w;
  if (hint != kInvalid) {
    const double off = sp.reduce(v, theta - sp.angle[hint]);
    if (off < fastCornerAngle(tri, hint)) w = {hint, off};
  }
  if (w.halfedge == kInvalid) w = findWedge(tri, sp, v, theta);
  if (w.halfedge == kInvalid && !m.isBoundaryVertex(v)) {
    // The wedges of an interior vertex cover its whole period, so every finite direction lies in one (findWedge
    // absorbs round-off at the seams). Reaching this means the signposts or corner angles around v are corrupt
    // (NaN after a degenerate insertion); the boundary fan walk below would never end on v's closed fan.
    double sum = 0;
    int h = m.vertexHalfedge(v);
    do {
      sum += fastCornerAngle(tri, h);
      h = m.nextOutgoing(h);
    } while (h != m.vertexHalfedge(v));
    throw ConvergenceError("geodesic trace from interior vertex " + std::to_string(v) + ": direction " +
                           formatNumber(theta) + " rad lies in no corner of its fan (signpost period " +
                           formatNumber(sp.period[v]) + ", corner angles summing to " + formatNumber(sum) +
                           "): corrupt signposts or a degenerate triangle");
  }
  if (w.halfedge == kInvalid) {
    // A direction pointing out of the surface at a boundary vertex: the nearer of v's two boundary edges. Either the
    // geodesic leaves at once through it (the target extrapolated in the plane of that edge's face), or the direction
    // is snapped onto it.
    const int hOut = m.vertexHalfedge(v);  // outgoing boundary halfedge (angle φ(hOut) starts the fan)
    int hIn = hOut;
    for (int h = hOut; h != kInvalid; h = m.nextOutgoing(h)) hIn = h;  // last outgoing; its prev is incoming boundary
    const double beforeFirst = sp.reduce(v, sp.angle[hOut] - theta);
    const double afterLast = sp.reduce(v, theta - sp.angle[hIn] - fastCornerAngle(tri, hIn));
    const bool useOut = beforeFirst <= afterLast;
    if (options.outward == OutwardDirection::FollowBoundary)
      return walkFromWedge(tri, model, useOut ? Wedge{hOut, 0.0} : Wedge{hIn, fastCornerAngle(tri, hIn)}, length,
                           options);
    const int h = useOut ? hOut : hIn;
    const std::array<Vec3, 3> P = layoutAtHalfedge(tri, model, h);
    TraceResult r;
    r.start = BackgroundModel::origin();
    r.end = model.polar(length, useOut ? -beforeFirst : fastCornerAngle(tri, hIn) + afterLast);
    r.face = HalfedgeMesh::face(h);
    r.corners = P;
    r.bary = model.barycentric(P[0], P[1], P[2], r.end);
    r.boundaryHalfedge = useOut ? h : HalfedgeMesh::prev(h);
    r.steps = 1;
    return r;
  }
  return walkFromWedge(tri, model, w, length, options);
}

}  // namespace conformesh::refine
