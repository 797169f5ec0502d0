// refiner_insertion.cpp — the Refiner's mutations (refiner.h): Lawson's flips with a filtered Delaunay test, and the
// insertion of a new vertex inside a face, on an interior edge or on a boundary segment, each with its signposts,
// input location and λ, followed by the flips and queue updates around it.
#include <algorithm>
#include <cmath>
#include <string>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/refine/trace/robust_predicates.h"
#include "delaunay/refiner.h"
#include "trace/corner_angle.h"

namespace conformesh::refine::detail {

using intrinsic::Background;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

namespace {

// The barycentric distance from an edge below which a new point is inserted on the edge (Refiner::insertAt).
constexpr double kEdgeSnap = 1e-3;

// Angle difference reduced to (−π, π].
double wrapPi(double a) {
  a = std::remainder(a, 2 * M_PI);
  return a;
}

}  // namespace

void Refiner::flip(int e) {
  const int h = tri_.mesh.edgeHalfedge(e), g = tri_.mesh.twin(h);
  if (flipWithSignposts(tri_, sp_, e)) {
    ++res_.statistics.flips;
    pushFace(HalfedgeMesh::face(h));
    pushFace(HalfedgeMesh::face(g));
  }
}

int Refiner::delaunaySign(int e) const {
  // A fast filtered test in the Euclidean background, which spares the six half-angle arctangents of delaunayMargin
  // for the great majority of edges: e is Delaunay iff cot α + cot β ≥ 0, and cot α = (b² + c² − a²) / (4·area) needs
  // one square root per triangle (Kahan's ordering of Heron's formula, accurate for needles too). The sum's absolute
  // round-off is below 1e-14 times the sum of the magnitudes of the quotients. Returns +1 (certainly Delaunay, with
  // room for delaunayMargin's 1e-12 tolerance), −1 (certainly not Delaunay: α + β > π, so the quad is convex and the
  // flip is admissible), 0 (too close to call: delaunayMargin decides).
  if (tri_.background == Background::Spherical) return sphericalBothAcute(e) ? 1 : 0;
  if (tri_.background != Background::Euclidean) return 0;
  const HalfedgeMesh& m = tri_.mesh;
  const int h = m.edgeHalfedge(e), g = m.twin(h);
  const double a = tri_.edgeLengths[e], a2 = a * a;
  // Both opposite angles certainly acute (b² + c² − a² above 1e-14 of its magnitude, far above its round-off): then
  // α + β < π and the edge is Delaunay, with no square root. This settles most edges of a good mesh.
  bool bothAcute = true;
  for (int x : {h, g}) {
    const double b = tri_.length(HalfedgeMesh::next(x)), c = tri_.length(HalfedgeMesh::prev(x));
    const double num = b * b + c * c - a2;
    if (!(num > 1e-14 * (b * b + c * c + a2))) bothAcute = false;
  }
  if (bothAcute) return 1;
  double sum = 0, scale = 0;
  for (int x : {h, g}) {
    const double b = tri_.length(HalfedgeMesh::next(x)), c = tri_.length(HalfedgeMesh::prev(x));
    const double area4 = detail::fourAreaEuclidean(a, b, c);
    if (!(area4 > 0)) return 0;
    sum += (b * b + c * c - a2) / area4;
    scale += (b * b + c * c + a2) / area4;
  }
  const double bound = 1e-14 * scale;
  if (sum > bound + 1e-12) return 1;
  if (sum < -bound) return -1;
  return 0;
}

bool Refiner::sphericalBothAcute(int e) const {
  // The spherical filter of delaunaySign. On the unit sphere the angles of a triangle sum to π + E (E > 0 its area), so
  // delaunayMargin = ½(ρ − α − β) = π + (E₁ + E₂)/2 − α − β, with α, β the angles opposite e and ρ the sum of the four
  // others: two acute opposite angles make the edge Delaunay with a margin above (E₁ + E₂)/2. The sign of cos α is
  // that of cos a − cos b · cos c (spherical law of cosines; sin b · sin c > 0 for sides in (0, π)), whose absolute
  // round-off is a few units of 1e-16 since every term is at most 1: above 1e-14 the angle is certainly acute. Five
  // cosines instead of the six angles' 24 sines and 6 arctangents; an edge that fails goes to delaunayMargin.
  const HalfedgeMesh& m = tri_.mesh;
  const int h = m.edgeHalfedge(e), g = m.twin(h);
  const double a = tri_.edgeLengths[e];
  if (!(a < M_PI)) return false;
  const double cosA = std::cos(a);
  for (int x : {h, g}) {
    const double b = tri_.length(HalfedgeMesh::next(x)), c = tri_.length(HalfedgeMesh::prev(x));
    if (!(b < M_PI && c < M_PI)) return false;
    if (!(cosA - std::cos(b) * std::cos(c) > 1e-14)) return false;
  }
  return true;
}

void Refiner::restoreDelaunay(std::vector<int>& stack, int center) {
  const HalfedgeMesh& m = tri_.mesh;
  // Lawson's algorithm terminates (Bobenko–Springborn in each background); the cap only guards against invalid input.
  std::int64_t budget = 1000LL * (m.nEdges() + 16);
  while (!stack.empty()) {
    const int e = stack.back();
    stack.pop_back();
    if (m.isBoundaryEdge(e)) continue;
    const int sign = delaunaySign(e);
    if (sign > 0 || (sign == 0 && intrinsic::delaunayMargin(tri_, e) >= -opt_.delaunayTolerance)) continue;
    const int h = m.edgeHalfedge(e), g = m.twin(h);
    const int quad[4] = {m.edge(HalfedgeMesh::next(h)), m.edge(HalfedgeMesh::prev(h)), m.edge(HalfedgeMesh::next(g)),
                         m.edge(HalfedgeMesh::prev(g))};
    const std::int64_t before = res_.statistics.flips;
    flip(e);
    if (res_.statistics.flips == before)
      continue;  // not flippable (non-convex quad); cannot happen for a non-Delaunay
                 // edge of a valid triangulation, and is harmless if it does
    // After inserting `center`, only the two quad sides away from it can have become non-Delaunay (the classical
    // incremental-insertion argument); a generic pass (or a degenerate quad with center at both ends) checks all four.
    int pushed = 0;
    for (int q : quad) {
      const int hq = m.edgeHalfedge(q);
      if (center != kInvalid && (m.tail(hq) == center || m.tip(hq) == center)) continue;
      stack.push_back(q);
      ++pushed;
    }
    if (pushed == 0)
      for (int q : quad) stack.push_back(q);
    if (--budget < 0)
      throw ConvergenceError("refine: Lawson flipping did not terminate (last edge " + std::to_string(e) +
                             "): the metric is not valid");
  }
}

void Refiner::countInsertion() {
  ++insertions_;
  if (insertions_ > opt_.maxInsertions)
    throw ConvergenceError("refine: stopped after " + std::to_string(opt_.maxInsertions) +
                           " insertions (the cap maxInsertions): epsilon " + num(opt_.epsilon) +
                           " is too small for this surface, or raise the cap");
  if (!opt_.progress) return;
  // Every progressEvery insertions, and at least every 2 s of work (checked every 64 insertions, far below the cost of
  // the insertions themselves), so that a long run on a surface with slow insertions still reports.
  bool report = opt_.progressEvery > 0 && insertions_ % opt_.progressEvery == 0;
  if (!report && insertions_ % 64 == 0)
    report = std::chrono::steady_clock::now() - lastProgress_ >= std::chrono::seconds(2);
  if (report) {
    lastProgress_ = std::chrono::steady_clock::now();
    opt_.progress({insertions_, tri_.mesh.nVertices(), faceQueue_.size()});
  }
}

void Refiner::afterInsertion(int p) {
  const HalfedgeMesh& m = tri_.mesh;
  edgeLoop_.resize(m.nEdges(), -1);
  sharpCorner_.resize(m.nVertices(), 0);
  flipStack_.clear();
  const int start = m.vertexHalfedge(p);
  int h = start;
  do {
    flipStack_.push_back(m.edge(HalfedgeMesh::next(h)));
    h = m.nextOutgoing(h);
  } while (h != kInvalid && h != start);
  restoreDelaunay(flipStack_, p);
  pushFacesAround(p);
}

void Refiner::appendVertexData(const InputLocation& location) {
  res_.locations.push_back(location);
  res_.lambda.push_back(uniform_ ? 0.0 : inputPtr_->interpolate(opt_.lambda, location));
}

void Refiner::splitSegment(int e) {
  countInsertion();
  const HalfedgeMesh& m = tri_.mesh;
  const int ha = m.edgeHalfedge(e), pa = HalfedgeMesh::prev(ha);
  const int loop = edgeLoop_[e];
  const LoopCircle& lc = loops_[loop];
  const double L = tri_.edgeLengths[e];
  const std::array<Vec3, 3> P = layoutAtHalfedge(tri_, model_, ha);
  const int k = ha % 3;
  const Vec3 A = P[k], B = P[(k + 1) % 3], C = P[(k + 2) % 3];
  const Vec3 M = segmentSplitPoint(e, lc);
  const double ap = model_.distance(A, M), pb = model_.distance(M, B), pc = model_.distance(M, C);
  if (L / 2 < minSize_ || orientationSign(A, M, C) <= 0 || orientationSign(M, B, C) <= 0) {
    // Ruppert's algorithm need not terminate next to a boundary corner smaller than 60°: it keeps splitting the two
    // segments there until they are degenerate. Name the sharpest boundary corner of this edge.
    const std::vector<double> sums = intrinsic::angleSums(tri_);
    const int u = m.tail(ha), w = m.tip(ha);
    throw ConvergenceError(
        "refine: boundary edge " + std::to_string(e) + " (vertices " + std::to_string(u) + ", " + std::to_string(w) +
        ", length " + num(L) + ") cannot be split any more (smallest size " + num(minSize_) + "; apex " +
        std::to_string(m.tail(pa)) + (L / 2 < minSize_ ? "" : " on the edge to round-off") +
        "): refinement is cascading into a boundary corner of " + num(std::min(sums[u], sums[w]) * 180 / M_PI) +
        "°; below 60° Ruppert's rules need not terminate — raise the shape bound B or remove the "
        "sharp corner");
  }
  // Where the new vertex lies on the input: follow the geodesic from the apex c to it, on the input.
  const int c = m.tail(pa);
  const double psi =
      wrapPi(model_.angleOf(C, model_.tangentToward(C, M)) - model_.angleOf(C, model_.tangentToward(C, A)));
  const double theta = sp_.turned(tri_, pa, psi);
  const InputSurface::Arrival arr =
      inputPtr_->follow(c, c < res_.statistics.inputVertices, res_.locations[c], theta, pc);
  const double arrivalHere = model_.angleOf(M, -model_.tangentToward(M, C));
  const double angleToB = model_.angleOf(M, model_.tangentToward(M, B)) - arrivalHere + arr.angle;
  const double turnAtA = lc.circle ? std::atan2(M.y(), M.x()) : 0.0;
  const int p = splitEdgeWithSignposts(tri_, sp_, e, ap, pb, pc, 0.0, angleToB, turnAtA);
  edgeLoop_.resize(m.nEdges(), -1);
  edgeLoop_[m.nEdges() - 2] = loop;  // the half p-b (halfedge_mesh.cpp: appended first on a boundary split)
  appendVertexData(arr.location);
  ++res_.statistics.boundarySplits;
  afterInsertion(p);
}

Vec3 Refiner::segmentSplitPoint(int e, const LoopCircle& lc) const {
  // In the layout of e's face at edgeHalfedge(e) = a → b: a at origin(), b along e1.
  const HalfedgeMesh& m = tri_.mesh;
  const int ha = m.edgeHalfedge(e);
  const double L = tri_.edgeLengths[e];
  Vec3 M;
  if (lc.circle) {
    // The arc midpoint: the circle through a and b of radius R has its centre at height ±√(R² − L²/4) over the chord
    // (left of a→b for an outer loop); the arc's midpoint is R from the centre, on the far side from it.
    const double R = std::max(lc.radius, L / 2);
    const double hC = std::sqrt(std::max(0.0, R * R - L * L / 4));
    M = Vec3(L / 2, lc.centerOnLeft ? hC - R : R - hC, 1.0);
  } else if (sharpCorner_[m.tail(ha)] || sharpCorner_[m.tip(ha)]) {
    // Ruppert's concentric shells: a segment at a corner below 60° is split at the power of two (times the corner's
    // scale, here 1) in [L/3, 2L/3] from the corner, so that the vertices on the corner's two segments lie on common
    // circles around it and stop encroaching upon each other's segments (Ruppert 1995, Shewchuk 2002).
    double d = std::exp2(std::round(std::log2(L / 2)));
    if (d < L / 3) d *= 2;
    if (d > 2 * L / 3) d /= 2;
    M = model_.polar(sharpCorner_[m.tail(ha)] ? d : L - d, 0.0);
  } else {
    M = model_.polar(L / 2, 0.0);
  }
  return M;
}

InputSurface::Arrival Refiner::followOnInputTo(const TraceResult& trace, int j, const Vec3& t) const {
  const int h = 3 * trace.face + j;  // corner j → corner j+1 of the face
  const int c = tri_.mesh.tail(h);
  const Vec3 &C = trace.corners[j], &next = trace.corners[(j + 1) % 3];
  const double psi =
      wrapPi(model_.angleOf(C, model_.tangentToward(C, t)) - model_.angleOf(C, model_.tangentToward(C, next)));
  return inputPtr_->follow(c, c < res_.statistics.inputVertices, res_.locations[c], sp_.turned(tri_, h, psi),
                           model_.distance(C, t));
}

void Refiner::insertOnEdge(const TraceResult& trace, int j) {
  // The point lies on the edge opposite corner j of trace.face (to within round-off): split that edge there.
  const HalfedgeMesh& m = tri_.mesh;
  const int f = trace.face, he = 3 * f + (j + 1) % 3;
  const std::array<Vec3, 3>& P = trace.corners;
  const int e = m.edge(he);
  if (m.twin(he) == kInvalid) {
    splitSegment(e);
    return;
  }
  countInsertion();
  Eigen::Vector3d b = trace.bary;
  b[j] = 0;
  b /= b.sum();
  const Vec3 t = model_.fromBarycentric(P[0], P[1], P[2], b);
  const int g = m.twin(he);
  const Vec3 &X = P[(j + 1) % 3], &Y = P[(j + 2) % 3];  // he runs X -> Y; g runs Y -> X
  const Vec3 D = unfoldThirdVertex(tri_, model_, g, Y, X);
  Vec3 a, bb, c, d;
  if (m.edgeHalfedge(e) == he) {
    a = X, bb = Y, c = P[j], d = D;
  } else {
    a = Y, bb = X, c = D, d = P[j];
  }
  // The vertex is t, not the traced point (up to ~1e-9 of the face away): its place on the input is followed again,
  // from corner j. With the traced point's place instead, an output edge within one input face was off its located
  // ends by ~1e-9 relative (hedra.off at --eps-rel 0.1: 2.2e-9; now ~4e-12).
  const InputSurface::Arrival arr = followOnInputTo(trace, j, t);
  const double arrivalHere = model_.angleOf(t, -model_.tangentToward(t, P[j]));
  const double angleToB = model_.angleOf(t, model_.tangentToward(t, bb)) - arrivalHere + arr.angle;
  const int p = splitEdgeWithSignposts(tri_, sp_, e, model_.distance(a, t), model_.distance(t, bb),
                                       model_.distance(t, c), model_.distance(t, d), angleToB, 0.0);
  appendVertexData(arr.location);
  afterInsertion(p);
}

void Refiner::insertAt(const TraceResult& trace, const InputSurface::Arrival& arr) {
  const std::array<Vec3, 3>& P = trace.corners;
  const Vec3& t = trace.end;
  // A point within kEdgeSnap (barycentric) of an edge is inserted on the edge instead, moving it by at most kEdgeSnap
  // of the face's height. Inside, it would make a sliver of height h = b·H whose lengths fix its apex only to
  // ~u·L²/h (u = 2.2e-16, L its longest side): every layout of the sliver (the Lawson flip that follows at once, the
  // corner angles its signposts are turned by) is off by ~u·L/b relative, and so are the lengths and located places
  // built from it. With the old threshold 1e-9, hedra.off at --eps-rel 0.05 had a point at b = 6.9e-9 and an output
  // edge 1.63e-9 (relative to its face) off its located ends; 3torus.off 1.08e-9 (exit 3). At 1e-3 both are ≤ 2e-14,
  // and the moved point stays far inside the bad triangle's circumcircle (processFace re-queues the face regardless).
  int j = 0;
  for (int k = 1; k < 3; ++k)
    if (trace.bary[k] < trace.bary[j]) j = k;
  std::array<double, 3> d{model_.distance(t, P[0]), model_.distance(t, P[1]), model_.distance(t, P[2])};
  const IntrinsicTriangulation& T = tri_;
  const int f = trace.face;
  bool valid = trace.bary[j] > kEdgeSnap;
  for (int k = 0; k < 3 && valid; ++k)
    valid = intrinsic::isValidTriangle(T.background, T.length(3 * f + k), d[k], d[(k + 1) % 3]);
  if (!valid) {
    insertOnEdge(trace, j);
    return;
  }
  countInsertion();
  const double arrivalHere = model_.angleOf(t, trace.arrivalTangent(model_));
  const double angleTo0 = model_.angleOf(t, model_.tangentToward(t, P[0])) - arrivalHere + arr.angle;
  const int p = splitFaceWithSignposts(tri_, sp_, f, d, angleTo0);
  appendVertexData(arr.location);
  afterInsertion(p);
}

}  // namespace conformesh::refine::detail
