// signposts.cpp — initial signposts, wedge lookup, and signpost bookkeeping through flips and vertex insertions.
#include "conformesh/refine/trace/signposts.h"

#include "trace/corner_angle.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"

namespace conformesh::refine {

using detail::fastCornerAngle;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

constexpr double kTwoPi = 2 * M_PI;

double Signposts::reduce(int v, double a) const {
  const double p = period[v];
  // Updates turn an angle in [0, p) by less than one period, so one conditional shift usually suffices (a − p is exact
  // for a in [p, 2p] by Sterbenz's lemma; a + p for a small negative a rounds by at most half an ulp of p, far below
  // the angles' own round-off); fmod handles anything else. This runs several times per insertion and flip.
  if (a >= p) a -= p;
  if (a < 0) a += p;
  if (a < 0 || a >= p) a = std::fmod(a, p);
  if (a < 0) a += p;
  if (a >= p) a = 0;  // fmod of a tiny negative number can round to p
  return a;
}

double Signposts::turned(const IntrinsicTriangulation& tri, int h, double delta) const {
  return reduce(tri.mesh.tail(h), angle[h] + delta);
}

Signposts initialSignposts(const IntrinsicTriangulation& tri) {
  const HalfedgeMesh& m = tri.mesh;
  Signposts sp;
  sp.angle.assign(m.nHalfedges(), 0.0);
  sp.period.assign(m.nVertices(), kTwoPi);
  const std::vector<double> sums = intrinsic::angleSums(tri);
  for (int v = 0; v < m.nVertices(); ++v) {
    if (!m.isBoundaryVertex(v)) sp.period[v] = sums[v];
    const int start = m.vertexHalfedge(v);
    double acc = 0;
    int h = start;
    do {
      sp.angle[h] = acc;
      acc += fastCornerAngle(tri, h);
      h = m.nextOutgoing(h);
    } while (h != kInvalid && h != start);
  }
  return sp;
}

Wedge findWedge(const IntrinsicTriangulation& tri, const Signposts& sp, int v, double theta) {
  const HalfedgeMesh& m = tri.mesh;
  const int start = m.vertexHalfedge(v);
  int h = start;
  Wedge best;
  double bestExcess = INFINITY;
  do {
    const double corner = fastCornerAngle(tri, h);
    const double off = sp.reduce(v, theta - sp.angle[h]);
    if (off < corner) return {h, off};
    // Round-off at a wedge's far side: the offset can land a few ulps above the corner angle, or wrap to just below
    // the period. Remember the closest wedge so that such directions still find their corner.
    const double excess = std::min(off - corner, sp.period[v] - off);
    if (excess < bestExcess) {
      bestExcess = excess;
      best = {h, off - corner < sp.period[v] - off ? corner : 0.0};
    }
    h = m.nextOutgoing(h);
  } while (h != kInvalid && h != start);
  // 1e-12 rad: the round-off of a sum of a vertex's corner angles (a few hundred ulps of 2π); anything farther is a
  // direction genuinely outside the fan (possible only at a boundary vertex).
  if (bestExcess < 1e-12) return best;
  return {};
}

namespace {

// New edge lengths must be finite and positive: a zero length (a point inserted on top of a vertex) or a NaN makes
// every later corner angle and signpost at the new vertex NaN, and a NaN direction matches no wedge of any fan. Checked
// before the mesh is touched, so the error leaves the triangulation as it was.
void requireLengths(const char* what, int element, std::initializer_list<double> lengths) {
  for (double l : lengths)
    if (!(l > 0) || !std::isfinite(l)) {
      std::string list;
      for (double x : lengths) list += (list.empty() ? "" : ", ") + formatNumber(x);
      throw ConvergenceError(std::string("refine: ") + what + " " + std::to_string(element) +
                             " would get a new edge of length " + formatNumber(l) + " (new lengths " + list +
                             "): the inserted point coincides with a vertex or was computed from a degenerate layout");
    }
}

// The signposts the split set come from corner angles of the new triangles; a NaN among them (a triangle that is
// invalid beyond round-off) would corrupt every later trace through these vertices. Only the stored angles are checked
// (a few comparisons per insertion; re-evaluating the corner angles cost 2% of a whole refinement).
void requireFiniteSignposts(const IntrinsicTriangulation& tri, const Signposts& sp, int p,
                            std::initializer_list<int> faces) {
  for (int f : faces)
    for (int h = 3 * f; h < 3 * f + 3; ++h)
      if (!std::isfinite(sp.angle[h]))
        throw ConvergenceError("refine: inserting vertex " + std::to_string(p) + " gave halfedge " + std::to_string(h) +
                               " a non-finite direction (its triangle has edge lengths " + formatNumber(tri.length(h)) +
                               ", " + formatNumber(tri.length(HalfedgeMesh::next(h))) + ", " +
                               formatNumber(tri.length(HalfedgeMesh::prev(h))) + "): degenerate triangle");
}

}  // namespace

bool flipWithSignposts(IntrinsicTriangulation& tri, Signposts& sp, int e) {
  const HalfedgeMesh& m = tri.mesh;
  const int ha = m.edgeHalfedge(e), hb = m.twin(ha);
  if (hb == kInvalid) return false;
  const int fa = HalfedgeMesh::face(ha), fb = HalfedgeMesh::face(hb);
  if (fa == fb) return false;
  // Before: fa = (a->b, b->c = na, c->a = pa), fb = (b->a, a->d = nb, d->b = pb). After (halfedge_mesh.cpp):
  // fa = (d->c, c->a, a->d), fb = (c->d, d->b, b->c), each starting at slot 0.
  const double sNa = sp.angle[HalfedgeMesh::next(ha)], sPa = sp.angle[HalfedgeMesh::prev(ha)];
  const double sNb = sp.angle[HalfedgeMesh::next(hb)], sPb = sp.angle[HalfedgeMesh::prev(hb)];
  const int h0 = 3 * fa, h1 = h0 + 1, h2 = h0 + 2, g0 = 3 * fb, g1 = g0 + 1, g2 = g0 + 2;
  double angleAtD = 0, angleAtC = 0;
  if (tri.background == intrinsic::Background::Euclidean) {
    // The quad laid out with a = (0, 0), b = (ℓ, 0), c above and d below the axis, by lengths only (heights from
    // Kahan-Heron areas, accurate for thin triangles): the convexity test, the new diagonal and the two corner angles
    // the signposts need come from these coordinates without the half-angle arctangents of flipEdge. Same decisions
    // and lengths as flipEdge up to round-off.
    const double l = tri.edgeLengths[e];
    const double lCa = tri.length(HalfedgeMesh::prev(ha)), lBc = tri.length(HalfedgeMesh::next(ha));
    const double lAd = tri.length(HalfedgeMesh::next(hb)), lDb = tri.length(HalfedgeMesh::prev(hb));
    const double xc = (l * l + lCa * lCa - lBc * lBc) / (2 * l), yc = detail::fourAreaEuclidean(l, lBc, lCa) / (2 * l);
    const double xd = (l * l + lAd * lAd - lDb * lDb) / (2 * l), yd = -detail::fourAreaEuclidean(l, lAd, lDb) / (2 * l);
    if (!(yc > 0 && yd < 0)) return false;
    const double x = xc + (xd - xc) * (yc / (yc - yd));  // where the diagonal c–d meets the line of a–b
    if (!(x > 0 && x < l)) return false;                 // the quad is not strictly convex at a or b
    const double lCd = std::hypot(xc - xd, yc - yd);
    if (!intrinsic::isValidTriangle(tri.background, lCd, lCa, lAd) ||
        !intrinsic::isValidTriangle(tri.background, lCd, lDb, lBc))
      return false;
    // Corner of fb = (c, d, b) at d, between d->b and d->c; corner of fa = (d, c, a) at c, between c->a and c->d.
    angleAtD = std::atan2(std::abs((l - xd) * (yc - yd) - (-yd) * (xc - xd)), (l - xd) * (xc - xd) + (-yd) * (yc - yd));
    angleAtC = std::atan2(std::abs((-xc) * (yd - yc) - (-yc) * (xd - xc)), (-xc) * (xd - xc) + (-yc) * (yd - yc));
    tri.mesh.flip(e);
    tri.edgeLengths[e] = lCd;
  } else {
    if (!intrinsic::flipEdge(tri, e)) return false;
    angleAtD = fastCornerAngle(tri, g1);
    angleAtC = fastCornerAngle(tri, h1);
  }
  sp.angle[h1] = sPa;
  sp.angle[h2] = sNb;
  sp.angle[g1] = sPb;
  sp.angle[g2] = sNa;
  // d->c is d->b turned counter-clockwise by the corner of fb at d; c->d is c->a turned by the corner of fa at c.
  sp.angle[h0] = sp.turned(tri, g1, angleAtD);
  sp.angle[g0] = sp.turned(tri, h1, angleAtC);
  return true;
}

int splitFaceWithSignposts(IntrinsicTriangulation& tri, Signposts& sp, int f, const std::array<double, 3>& toCorner,
                           double angleToCorner0) {
  requireLengths("splitting face", f, {toCorner[0], toCorner[1], toCorner[2]});
  if (!std::isfinite(angleToCorner0))
    throw ConvergenceError("refine: splitting face " + std::to_string(f) +
                           ": the new vertex's direction to corner 0 is " + formatNumber(angleToCorner0));
  HalfedgeMesh& m = tri.mesh;
  const double sBc = sp.angle[3 * f + 1], sCa = sp.angle[3 * f + 2];
  const int p = m.splitFace(f);
  // f = (a->b, b->p, p->a), f1 = (b->c, c->p, p->b), f2 = (c->a, a->p, p->c); new edges eA = p-a, eB = p-b, eC = p-c.
  const int nE = m.nEdges();
  tri.edgeLengths.resize(nE);
  tri.edgeLengths[nE - 3] = toCorner[0];
  tri.edgeLengths[nE - 2] = toCorner[1];
  tri.edgeLengths[nE - 1] = toCorner[2];
  const int f1 = m.nFaces() - 2, f2 = m.nFaces() - 1;
  sp.angle.resize(m.nHalfedges());
  sp.period.push_back(kTwoPi);
  sp.angle[3 * f1] = sBc;
  sp.angle[3 * f2] = sCa;
  sp.angle[3 * f + 1] = sp.turned(tri, 3 * f1, fastCornerAngle(tri, 3 * f1));           // b->p
  sp.angle[3 * f1 + 1] = sp.turned(tri, 3 * f2, fastCornerAngle(tri, 3 * f2));          // c->p
  sp.angle[3 * f2 + 1] = sp.turned(tri, 3 * f, fastCornerAngle(tri, 3 * f));            // a->p
  sp.angle[3 * f + 2] = sp.reduce(p, angleToCorner0);                                   // p->a
  sp.angle[3 * f1 + 2] = sp.turned(tri, 3 * f + 2, fastCornerAngle(tri, 3 * f + 2));    // p->b
  sp.angle[3 * f2 + 2] = sp.turned(tri, 3 * f1 + 2, fastCornerAngle(tri, 3 * f1 + 2));  // p->c
  requireFiniteSignposts(tri, sp, p, {f, f1, f2});
  return p;
}

int splitEdgeWithSignposts(IntrinsicTriangulation& tri, Signposts& sp, int e, double ap, double pb, double pc,
                           double pd, double angleToB, double turnAtA) {
  HalfedgeMesh& m = tri.mesh;
  const int ha = m.edgeHalfedge(e), hb = m.twin(ha);
  if (hb == kInvalid)
    requireLengths("splitting edge", e, {ap, pb, pc});
  else
    requireLengths("splitting edge", e, {ap, pb, pc, pd});
  if (!std::isfinite(angleToB) || !std::isfinite(turnAtA))
    throw ConvergenceError("refine: splitting edge " + std::to_string(e) + ": the new vertex's directions are " +
                           formatNumber(angleToB) + ", " + formatNumber(turnAtA));
  const int na = HalfedgeMesh::next(ha), pa = HalfedgeMesh::prev(ha);
  const double sNa = sp.angle[na];
  const double sNb = hb == kInvalid ? 0.0 : sp.angle[HalfedgeMesh::next(hb)];
  const int nE0 = m.nEdges(), nF0 = m.nFaces();
  const int p = m.splitEdge(e);
  // Edge e keeps a-p; appended: p-b (nE0), p-c (nE0+1), and p-d (nE0+2) when interior.
  tri.edgeLengths.resize(m.nEdges());
  tri.edgeLengths[e] = ap;
  tri.edgeLengths[nE0] = pb;
  tri.edgeLengths[nE0 + 1] = pc;
  if (hb != kInvalid) tri.edgeLengths[nE0 + 2] = pd;
  sp.angle.resize(m.nHalfedges());
  sp.period.push_back(kTwoPi);
  // (a->p = ha, p->c = na, c->a = pa) + (p->b = q0, b->c = q1, c->p = q2).
  const int q0 = 3 * nF0, q1 = q0 + 1, q2 = q0 + 2;
  sp.angle[ha] = sp.turned(tri, ha, turnAtA);
  sp.angle[q1] = sNa;
  sp.angle[q2] = sp.turned(tri, pa, fastCornerAngle(tri, pa));
  sp.angle[q0] = sp.reduce(p, angleToB);
  sp.angle[na] = sp.turned(tri, q0, fastCornerAngle(tri, q0));
  if (hb != kInvalid) {
    // (b->p = hb, p->d = nb, d->b = pb) + (p->a = r0, a->d = r1, d->p = r2).
    const int nb = HalfedgeMesh::next(hb), pbh = HalfedgeMesh::prev(hb);
    const int r0 = 3 * (nF0 + 1), r1 = r0 + 1, r2 = r0 + 2;
    sp.angle[r1] = sNb;
    sp.angle[r2] = sp.turned(tri, pbh, fastCornerAngle(tri, pbh));
    sp.angle[r0] = sp.turned(tri, na, fastCornerAngle(tri, na));
    sp.angle[nb] = sp.turned(tri, r0, fastCornerAngle(tri, r0));
    requireFiniteSignposts(tri, sp, p, {HalfedgeMesh::face(ha), nF0, HalfedgeMesh::face(hb), nF0 + 1});
  } else {
    requireFiniteSignposts(tri, sp, p, {HalfedgeMesh::face(ha), nF0});
  }
  return p;
}

}  // namespace conformesh::refine
