// delaunay_refinement.cpp — the refinement loop of delaunay_refinement.h (class Refiner, refiner.h): validate the
// options, set up the boundary, then serve the queues — encroached segments first, then bad faces, largest first —
// until no triangle is bad; a bad face is examined, its new point chosen (circumcentre, off-centre, frontal point or
// centroid), located by geodesic tracing, tested against the boundary rules and inserted (refiner_insertion.cpp).
#include "conformesh/refine/delaunay/delaunay_refinement.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/refine/trace/robust_predicates.h"
#include "delaunay/refiner.h"
#include "trace/corner_angle.h"

namespace conformesh::refine {

using intrinsic::Background;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

namespace detail {

std::string num(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// It is evaluated for every face a flip or an insertion touches, hence the Euclidean shortcut.
double circumradiusOf(const IntrinsicTriangulation& tri, int f) {
  if (tri.background != Background::Euclidean) return intrinsic::faceCircumradius(tri, f);
  const double a = tri.length(3 * f), b = tri.length(3 * f + 1), c = tri.length(3 * f + 2);
  const double area4 = detail::fourAreaEuclidean(a, b, c);
  return area4 > 0 ? a * b * c / area4 : INFINITY;
}

// === setup

RefineResult Refiner::run() {
  validate();
  initialize();
  setupBoundary();
  drainAll();
  smoothAndRefine();
  return std::move(res_);
}

void Refiner::validate() {
  intrinsic::validateLengths(in_, "refine input");
  const std::string error = opt_.validate();
  if (!error.empty()) throw InputError(error);
  const int nV = in_.mesh.nVertices();
  if (!opt_.lambda.empty() && static_cast<int>(opt_.lambda.size()) != nV)
    throw InputError("refine: the conformal factor has " + std::to_string(opt_.lambda.size()) +
                     " values, expected one per input vertex (" + std::to_string(nV) + ")");
}

void Refiner::initialize() {
  inputStore_.emplace(in_);
  inputPtr_ = &*inputStore_;
  tri_ = in_;
  const int nV = in_.mesh.nVertices();
  res_.statistics.inputVertices = nV;
  sp_ = inputPtr_->signposts();
  uniform_ =
      opt_.lambda.empty() || std::all_of(opt_.lambda.begin(), opt_.lambda.end(), [](double x) { return x == 0.0; });
  if (!uniform_) {
    lambdaMax_ = *std::max_element(opt_.lambda.begin(), opt_.lambda.end());
  }
  for (int v = 0; v < nV; ++v) {
    res_.locations.push_back(inputPtr_->vertexLocation(v));
    res_.lambda.push_back(uniform_ ? 0.0 : opt_.lambda[v]);
  }
  const double shortestInput = *std::min_element(in_.edgeLengths.begin(), in_.edgeLengths.end());
  minSize_ = opt_.minCircumradius > 0 ? opt_.minCircumradius
                                      : 1e-6 * std::min(opt_.epsilon * std::exp(-lambdaMax_), shortestInput);
}

// === queues and tests

void Refiner::pushFace(int f) {
  if (f >= tri_.mesh.nFaces()) return;  // deleted by a vertex removal since it was named
  if (faceQueued_.size() < static_cast<size_t>(tri_.mesh.nFaces())) faceQueued_.resize(tri_.mesh.nFaces(), 0);
  if (faceQueued_[f]) return;
  faceQueued_[f] = 1;
  const double R = circumradiusOf(tri_, f);
  // A face that meets both bounds even with the largest λ anywhere (the conservative size test of processFace) is not
  // queued at all: most faces a flip or an insertion touches are good, and keeping them out of the heap spares its
  // O(log n) churn and a second evaluation. Every later change of the face (flip, split) pushes it again.
  if (std::isfinite(R) && !(R > opt_.epsilon * std::exp(-lambdaMax_) * (1 + 1e-12))) {
    const double shortest = std::min({tri_.length(3 * f), tri_.length(3 * f + 1), tri_.length(3 * f + 2)});
    if (!(R > opt_.ratioBound * shortest * (1 + 1e-12))) {
      faceQueued_[f] = 0;
      return;
    }
  }
  faceQueue_.push({std::isfinite(R) ? R * std::exp(meanLambda(f)) : INFINITY, f});
}

double Refiner::meanLambda(int f) const {
  const HalfedgeMesh& m = tri_.mesh;
  return (res_.lambda[m.faceVertex(f, 0)] + res_.lambda[m.faceVertex(f, 1)] + res_.lambda[m.faceVertex(f, 2)]) / 3;
}

bool Refiner::meetsSizeTarget(int f) const {
  // The queue's estimate of the size test (λ averaged over the corners instead of interpolated at the circumcentre):
  // it only chooses where the front is, never whether a face is refined.
  return circumradiusOf(tri_, f) * std::exp(meanLambda(f)) <= opt_.epsilon;
}

void Refiner::pushFront(int f) {
  if (frontQueued_.size() < static_cast<size_t>(tri_.mesh.nFaces())) frontQueued_.resize(tri_.mesh.nFaces(), 0);
  if (frontQueued_[f] || meetsSizeTarget(f)) return;
  const HalfedgeMesh& m = tri_.mesh;
  bool nextToGood = false;
  for (int k = 0; k < 3 && !nextToGood; ++k) {
    const int g = m.twin(3 * f + k);
    nextToGood = g != kInvalid && meetsSizeTarget(HalfedgeMesh::face(g));
  }
  if (!nextToGood) return;
  frontQueued_[f] = 1;
  frontQueue_.push({circumradiusOf(tri_, f) * std::exp(meanLambda(f)), f});
}

void Refiner::pushFacesAround(int v) {
  const HalfedgeMesh& m = tri_.mesh;
  const int start = m.vertexHalfedge(v);
  int h = start;
  do {
    const int f = HalfedgeMesh::face(h);
    pushFace(f);
    if (opt_.frontal) {
      // The new faces, and the faces beyond their outer edges, may now lie on the front.
      pushFront(f);
      const int g = m.twin(HalfedgeMesh::next(h));
      if (g != kInvalid) pushFront(HalfedgeMesh::face(g));
    }
    if (hasBoundary_)
      for (int k = 0; k < 3; ++k)
        if (m.twin(3 * f + k) == kInvalid) segmentQueue_.push_back(m.edge(3 * f + k));
    h = m.nextOutgoing(h);
  } while (h != kInvalid && h != start);
}

void Refiner::processSegment(int e) {
  // Chew's rule keeps the triangulation constrained Delaunay: a vertex inside a diametral circle is allowed, segments
  // are split only for rejected circumcentres.
  if (opt_.segmentRule == SegmentRule::Chew) return;
  if (e >= tri_.mesh.nEdges() || !tri_.mesh.isBoundaryEdge(e)) return;
  if (segmentEncroached(e)) splitSegment(e);
}

void Refiner::drain() {
  for (;;) {
    if (!segmentQueue_.empty()) {
      const int e = segmentQueue_.front();
      segmentQueue_.pop_front();
      processSegment(e);
      continue;
    }
    if (!frontQueue_.empty()) {
      const int f = frontQueue_.top().second;
      frontQueue_.pop();
      if (f >= tri_.mesh.nFaces()) continue;  // deleted by a vertex removal (SegmentRule::Chew)
      frontQueued_[f] = 0;
      processFace(f);
      continue;
    }
    if (faceQueue_.empty()) break;
    const int f = faceQueue_.top().second;
    faceQueue_.pop();
    if (f >= tri_.mesh.nFaces()) continue;  // deleted by a vertex removal (SegmentRule::Chew)
    faceQueued_[f] = 0;
    processFace(f);
  }
}

void Refiner::drainAll() {
  std::vector<int> all(tri_.mesh.nEdges());
  for (int e = 0; e < tri_.mesh.nEdges(); ++e) all[e] = e;
  restoreDelaunay(all);
  for (int f = 0; f < tri_.mesh.nFaces(); ++f) pushFace(f);
  for (int e = 0; e < tri_.mesh.nEdges(); ++e)
    if (tri_.mesh.isBoundaryEdge(e)) segmentQueue_.push_back(e);
  drain();
}

void Refiner::smoothAndRefine() {
  SmoothingOptions so;
  so.rule = opt_.smoothingRule;
  so.epsilon = opt_.epsilon;
  so.ratioBound = opt_.ratioBound;
  const std::vector<double> noLambda;
  const std::int64_t before = insertions_;
  for (int pass = 0; pass < opt_.smoothingPasses; ++pass) {
    const SmoothingStatistics s =
        smoothFreeVertices(tri_, sp_, res_.locations, res_.lambda, res_.statistics.inputVertices, *inputPtr_,
                           uniform_ ? noLambda : opt_.lambda, so);
    res_.statistics.smoothingMoves += s.moved;
    res_.statistics.smoothingRefused += s.invalid + s.rejected;
    // The moves keep every star valid but not necessarily Delaunay: Lawson's flips over all edges, then the refinement
    // loop over every face and segment, so the output meets the bounds exactly as an unsmoothed one does (the loop
    // stops only when no triangle is bad; termination: the packing argument of §1 with the smoothed mesh as input).
    drainAll();
  }
  res_.statistics.insertionsAfterSmoothing = insertions_ - before;
}

// === a bad face

void Refiner::processFace(int f) {
  BadFace b = examineFace(f);
  if (!b.badShape && !b.mayBeBadSize) return;
  layOutFace(b);
  // Hyperbolic triangles whose vertices lie on a horocycle or hypercycle have no circumcircle; they are bad-sized for
  // every ε and are split at their (Klein-model) centroid, which lies inside them.
  Vec3 target = b.centroid ? model_.normalize(b.P[0] + b.P[1] + b.P[2]) : *b.cc;
  const bool offCenter = b.badShape && opt_.offCenters && !b.centroid && in_.background == Background::Euclidean &&
                         offCenterPoint(b, target);
  requireAboveSmallestSize(b);
  const HalfedgeMesh& m = tri_.mesh;
  if (b.centroid && opt_.segmentRule == SegmentRule::Chew && m.twin(3 * f + b.longestK) == kInvalid) {
    // A hyperbolic triangle without a circumcircle has its vertices on a hypercycle (or horocycle) whose axis lies
    // beyond its longest edge (the arc bulges away from the axis, so the middle vertex — the largest angle — is on the
    // near side): its "circumcentre" is beyond that edge. When the edge is a segment this is Chew's rejection;
    // splitting at the centroid instead would approach the segment forever (docs/refinement.md §5).
    rejectAtSegment(f, m.edge(3 * f + b.longestK));
    return;
  }
  // Frontal placement (size-driven triangles only): the point on the bisector of a front edge that makes a triangle of
  // the target size with it. With λ ≡ 0 the size test needs no location, so the frontal point is traced directly;
  // otherwise the circumcentre is located first, for λ(c) of the size test.
  const std::optional<Vec3> front =
      !b.badShape && opt_.frontal && !b.centroid ? frontalPoint(f, b.P, *b.cc) : std::nullopt;
  if (front && uniform_) target = *front;
  double theta = 0, r = 0;
  LocatedPoint x{traceToward(b, target, theta, r), {}, front && uniform_};
  if (x.frontal && !x.trace.reachedTarget()) {
    // The frontal point lies beyond a boundary edge (a non-convex domain): fall back to the circumcentre.
    target = *b.cc;
    x.frontal = false;
    x.trace = traceToward(b, target, theta, r);
  }
  if (!x.trace.reachedTarget()) {
    // The circumcentre lies outside the domain (or, in a non-convex domain, behind a segment): split the boundary edge
    // the geodesic to it crosses (Ruppert, Chew).
    rejectAtSegment(f, m.edge(x.trace.boundaryHalfedge));
    return;
  }
  x.arrival = followOnInput(b, theta, r);
  if (!b.badShape && !sizeBadAt(b, x.arrival)) return;
  if (front && !uniform_) moveToFrontalPoint(b, *front, x);
  if (hasBoundary_ && opt_.segmentRule == SegmentRule::Ruppert && splitSegmentsEncroachedBy(f, x.trace)) return;
  countInsertionKind(b, offCenter, x.frontal);
  insertAt(x.trace, x.arrival);
  // insertAt may move the point onto an edge (by up to 1e-3 of the containing face's height); should the bad face
  // survive that, it is examined again rather than left in the output.
  pushFace(f);
}

BadFace Refiner::examineFace(int f) const {
  const HalfedgeMesh& m = tri_.mesh;
  BadFace b;
  b.face = f;
  double shortest = INFINITY, longest = 0;
  int longestK = 0;
  for (int k = 0; k < 3; ++k) {
    const double l = tri_.length(3 * f + k);
    shortest = std::min(shortest, l);
    if (l > longest) longest = l, longestK = k;
  }
  b.shortest = shortest;
  b.longestK = longestK;
  const double R = circumradiusOf(tri_, f);  // +inf for a hyperbolic triangle without a circumcircle
  b.R = R;
  // Strict comparisons with a relative slack of 1e-12: a triangle exactly at a bound (circumradius equal to ε, or to
  // B times its shortest edge) is good, whatever the last bit of its computed circumradius.
  // Shewchuk's terminator, in its simplest form: a triangle with a corner at a sharp boundary corner (< 60°) may be
  // as skinny as that input angle forces, so only its size is enforced there; otherwise refinement would shrink the
  // corner's triangles forever.
  bool atSharpCorner = false;
  if (hasBoundary_)
    for (int k = 0; k < 3; ++k) atSharpCorner = atSharpCorner || sharpCorner_[m.faceVertex(f, k)];
  b.badShape = !atSharpCorner && R > opt_.ratioBound * shortest * (1 + 1e-12);
  b.mayBeBadSize = R > opt_.epsilon * std::exp(-lambdaMax_) * (1 + 1e-12);
  return b;
}

void Refiner::layOutFace(BadFace& b) const {
  // Trace from the vertex opposite the longest edge: for an obtuse triangle the circumcentre lies beyond that edge, so
  // this is the shortest way there.
  b.hs = 3 * b.face + (b.longestK + 2) % 3;
  b.v = tri_.mesh.tail(b.hs);
  b.P = layoutAtHalfedge(tri_, model_, b.hs);
  b.cc = model_.circumcenter(b.P[0], b.P[1], b.P[2]);
  b.centroid = !b.cc || !std::isfinite(b.R);
}

bool Refiner::offCenterPoint(const BadFace& b, Vec3& target) const {
  // Üngör's off-centre: on the bisector of the shortest edge pq, at the height h = ℓ(B + √(B² − 1/4)) where the
  // triangle it forms with pq has circumradius / shortest edge exactly B (apex angle arcsin(1/(2B))), unless the
  // circumcentre is nearer. It lies on the segment from pq's midpoint to the circumcentre, inside the circumcircle,
  // so the bad triangle is still destroyed.
  const int f = b.face;
  int ks = 0;
  for (int k = 1; k < 3; ++k)
    if (tri_.length(3 * f + k) < tri_.length(3 * f + ks)) ks = k;
  const Vec3 M = (b.P[ks] + b.P[(ks + 1) % 3]) / 2;
  const Vec3 toC = *b.cc - M;
  const double dist = std::hypot(toC.x(), toC.y());
  const double B = opt_.ratioBound, h = b.shortest * (B + std::sqrt(B * B - 0.25));
  if (!(h < dist)) return false;
  target = M + (h / dist) * toC;
  return true;
}

void Refiner::requireAboveSmallestSize(const BadFace& b) const {
  const HalfedgeMesh& m = tri_.mesh;
  const int f = b.face;
  if (std::isfinite(b.R) && b.R < minSize_)
    throw ConvergenceError("refine: face " + std::to_string(f) + " (vertices " + std::to_string(m.faceVertex(f, 0)) +
                           ", " + std::to_string(m.faceVertex(f, 1)) + ", " + std::to_string(m.faceVertex(f, 2)) +
                           ") still needs refining at circumradius " + num(b.R) + ", below the smallest size " +
                           num(minSize_) + ": the shape bound B = " + num(opt_.ratioBound) +
                           " cannot be met near this face (small input angle?)");
}

TraceResult Refiner::traceToward(const BadFace& b, const Vec3& x, double& theta, double& r) {
  r = model_.distance(BackgroundModel::origin(), x);
  theta = sp_.turned(tri_, b.hs, std::atan2(x.y(), x.x()));
  try {
    TraceResult t = traceFromVertex(tri_, sp_, model_, b.v, theta, r, b.hs);
    res_.statistics.traceSteps += t.steps;
    return t;
  } catch (const ConvergenceError& err) {
    // The trace names the vertex / face and the cap it hit; add which refinement step it served.
    throw ConvergenceError("refine (epsilon " + num(opt_.epsilon) + ", B " + num(opt_.ratioBound) + ", after " +
                           std::to_string(insertions_) + " insertions): locating the new point of face " +
                           std::to_string(b.face) + " (circumradius " + num(b.R) + ") from its vertex " +
                           std::to_string(b.v) + ": " + err.what());
  }
}

InputSurface::Arrival Refiner::followOnInput(const BadFace& b, double theta, double r) const {
  const int v = b.v;
  return inputPtr_->follow(v, v < res_.statistics.inputVertices, res_.locations[v], theta, r);
}

bool Refiner::sizeBadAt(const BadFace& b, const InputSurface::Arrival& arrival) const {
  const double lam = uniform_ ? 0.0 : inputPtr_->interpolate(opt_.lambda, arrival.location);
  return b.R > opt_.epsilon * std::exp(-lam) * (1 + 1e-12);
}

void Refiner::moveToFrontalPoint(const BadFace& b, const Vec3& front, LocatedPoint& x) {
  double thetaF = 0, rF = 0;
  const TraceResult trF = traceToward(b, front, thetaF, rF);
  if (!trF.reachedTarget()) return;  // beyond a boundary edge: keep the circumcentre
  x.trace = trF;
  x.arrival = followOnInput(b, thetaF, rF);
  x.frontal = true;
}

void Refiner::rejectAtSegment(int f, int e) {
  // Chew's rule first deletes the free vertices in the segment's diametral disk.
  ++res_.statistics.rejectedCircumcenters;
  if (opt_.segmentRule == SegmentRule::Chew) e = deleteFreeVertices(e);
  splitSegment(e);
  pushFace(f);
}

bool Refiner::splitSegmentsEncroachedBy(int f, const TraceResult& trace) {
  const std::vector<int> enc = encroachedByPoint(trace);
  if (enc.empty()) return false;
  ++res_.statistics.rejectedCircumcenters;
  for (int e : enc)
    if (tri_.mesh.isBoundaryEdge(e)) splitSegment(e);
  pushFace(f);
  return true;
}

void Refiner::countInsertionKind(const BadFace& b, bool offCenter, bool frontal) {
  if (b.centroid)
    ++res_.statistics.centroidInsertions;
  else if (offCenter)
    ++res_.statistics.offCenterInsertions;
  else if (frontal)
    ++res_.statistics.frontalInsertions;
  else
    ++res_.statistics.circumcenterInsertions;
}

std::optional<Vec3> Refiner::frontalPoint(int f, const std::array<Vec3, 3>& P, const Vec3& c) const {
  // Rebay's frontal Delaunay placement (J. Comput. Phys. 106, 1993), for a triangle that is bad by size only. A "front"
  // edge of f is one whose neighbour already meets its size target (key R·e^λ̄ ≤ ε, the queue's estimate). On the
  // longest front edge pq (length 2p, midpoint M, f's circumcentre c at distance q from M on f's side) the point X on
  // the geodesic M → c at distance d = ρ + √(ρ² − p²), ρ = max(ρ_target, p), ρ_target = ε·e^(−λ̄(pq)), is the apex of
  // the isosceles triangle on pq whose circumradius is the target: a near-equilateral triangle of the intended size
  // grows from the front. X is used only when d < q, i.e. strictly between M and c: it lies in f's empty circumdisk,
  // so inserting it destroys f, and every vertex is at least R − |cX| = R − q + d ≥ d ≥ ρ_target away from it (R ≥ q).
  // The insertion radius of a size-driven insertion thus stays above the smallest target size, and the packing
  // argument of docs/refinement.md §1 still bounds the vertex count. The formulas for ρ and d are Euclidean; in curved
  // backgrounds they only choose the point on the geodesic M → c, and both properties above still hold (they use the
  // triangle inequality and the empty circumdisk only).
  const HalfedgeMesh& m = tri_.mesh;
  int best = -1;
  double bestLength = 0;
  for (int k = 0; k < 3; ++k) {
    const int g = m.twin(3 * f + k);
    if (g == kInvalid) continue;
    const int f2 = HalfedgeMesh::face(g);
    const double R2 = circumradiusOf(tri_, f2);
    if (!(R2 * std::exp(meanLambda(f2)) <= opt_.epsilon)) continue;
    const double l = tri_.length(3 * f + k);
    if (l > bestLength) bestLength = l, best = k;
  }
  if (best < 0) return std::nullopt;
  const Vec3 &A = P[best], &B = P[(best + 1) % 3];
  if (orientationSign(A, B, c) <= 0) return std::nullopt;  // c not strictly on f's side of pq: obtuse apex
  const Vec3 M = model_.exp(A, model_.tangentToward(A, B), bestLength / 2);
  const double p = bestLength / 2, q = model_.distance(M, c);
  const double lamEdge = (res_.lambda[m.faceVertex(f, best)] + res_.lambda[m.faceVertex(f, (best + 1) % 3)]) / 2;
  const double target = opt_.epsilon * std::exp(-lamEdge);
  const double rho = std::max(target, p);
  const double d = rho + std::sqrt(std::max(0.0, rho * rho - p * p));
  if (!(d < q)) return std::nullopt;  // X would be at (or beyond) c: insert the circumcentre itself
  return model_.exp(M, model_.tangentToward(M, c), d);
}

}  // namespace detail

SegmentRule parseSegmentRule(const std::string& name) {
  if (name == "ruppert") return SegmentRule::Ruppert;
  if (name == "chew") return SegmentRule::Chew;
  throw InputError("segment rule '" + name + "' is not one of: ruppert, chew");
}

std::string RefineOptions::validate() const {
  using detail::num;
  if (!(epsilon > 0) || !std::isfinite(epsilon))
    return "refine: the size bound epsilon must be a finite positive number, got " + num(epsilon);
  if (!(ratioBound >= 1) || !std::isfinite(ratioBound))
    return "refine: the shape bound B (circumradius / shortest edge) must be at least 1, got " + num(ratioBound) +
           " (B = 1 is Chew's 30° bound; no triangle can do better than 1/√3)";
  for (int v = 0; v < static_cast<int>(lambda.size()); ++v)
    if (!std::isfinite(lambda[v]))
      return "refine: the conformal factor at vertex " + std::to_string(v) + " is not finite (" + num(lambda[v]) + ")";
  if (!(maxInsertions > 0)) return "refine: maxInsertions must be positive";
  if (smoothingPasses < 0) return "refine: smoothingPasses must be at least 0, got " + std::to_string(smoothingPasses);
  return "";
}

RefineResult refineDelaunay(const IntrinsicTriangulation& input, const RefineOptions& options) {
  detail::Refiner refiner(input, options);
  return refiner.run();
}

}  // namespace conformesh::refine
