// delaunay_refinement.cpp — the refinement loop of delaunay_refinement.h: queues of encroached boundary edges and bad
// triangles, circumcentre location by geodesic tracing, insertion with signposts and input locations, Lawson flips.
#include "conformesh/refine/delaunay/delaunay_refinement.h"

#include "trace/corner_angle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <optional>
#include <queue>
#include <sstream>
#include <string>

#include <Eigen/QR>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/refine/trace/geodesic_trace.h"
#include "conformesh/refine/trace/robust_predicates.h"
#include "conformesh/refine/delaunay/vertex_removal.h"

namespace conformesh::refine {

using detail::fastCornerAngle;
using intrinsic::Background;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

namespace {

std::string num(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// Circumradius of face f: in the Euclidean background abc / (4·area) with Kahan's area (+∞ for a degenerate face), the
// same value as intrinsic::faceCircumradius up to round-off but without its half-perimeter products; it is evaluated
// for every face a flip or an insertion touches. Curved backgrounds use the core's formula.
double circumradiusOf(const IntrinsicTriangulation& tri, int f) {
  if (tri.background != Background::Euclidean) return intrinsic::faceCircumradius(tri, f);
  const double a = tri.length(3 * f), b = tri.length(3 * f + 1), c = tri.length(3 * f + 2);
  const double area4 = detail::fourAreaEuclidean(a, b, c);
  return area4 > 0 ? a * b * c / area4 : INFINITY;
}

// Angle difference reduced to (−π, π].
double wrapPi(double a) {
  a = std::remainder(a, 2 * M_PI);
  return a;
}

// One boundary loop: whether it is split on its circle, the circle's radius, and on which side of the loop's halfedges
// (interior on their left) the centre lies: left for an outer loop, right for a hole of a circle domain.
struct LoopCircle {
  bool circle = false;
  double radius = 0;
  bool centerOnLeft = true;
};

class Refiner {
 public:
  Refiner(const IntrinsicTriangulation& input, const RefineOptions& options)
      : in_(input), opt_(options), model_(input.background) {}

  RefineResult run();

 private:
  // === setup
  void validate();
  void setupBoundary();
  // === queues and tests
  void pushFace(int f);
  void pushFacesAround(int v);
  bool meetsSizeTarget(int f) const;
  void pushFront(int f);
  bool segmentEncroached(int e) const;
  void processSegment(int e);
  void processFace(int f);
  // === mutation
  void flip(int e);
  void restoreDelaunay(std::vector<int>& stack, int center = kInvalid);  // consumes `stack`
  int delaunaySign(int e) const;
  void afterInsertion(int p);
  void splitSegment(int e);
  void insertAt(const TraceResult& trace, const InputSurface::Arrival& arrival);
  void insertOnEdge(const TraceResult& trace, int cornerOpposite, const InputSurface::Arrival& arrival);
  std::vector<int> encroachedByPoint(const TraceResult& trace) const;
  // SegmentRule::Chew: the free vertices strictly inside the diametral disk of boundary edge e, and their deletion
  // before e is split; returns e's index afterwards (removal compacts the edge array).
  std::vector<int> freeVerticesInDiametralDisk(int e) const;
  int deleteFreeVertices(int e);
  std::optional<Vec3> frontalPoint(int f, const std::array<Vec3, 3>& P, const Vec3& c) const;
  void countInsertion();
  // === the loop. drain() serves the queues until they are empty; drainAll() first Lawson-flips every edge and queues
  // every face and boundary segment (the start, and the restart after a smoothing pass).
  void drain();
  void drainAll();
  void smoothAndRefine();

  const IntrinsicTriangulation& in_;
  RefineOptions opt_;
  BackgroundModel model_;
  std::optional<InputSurface> inputStore_;  // built after validation
  const InputSurface* inputPtr_ = nullptr;
  RefineResult res_;
  IntrinsicTriangulation& tri_ = res_.triangulation;
  Signposts& sp_ = res_.signposts;
  std::vector<int> edgeLoop_;  // per edge: boundary loop index, −1 for interior edges
  std::vector<LoopCircle> loops_;
  std::vector<char> sharpCorner_;  // per vertex: an input boundary vertex whose angle is below 60°
  bool hasBoundary_ = false, uniform_ = true;
  double lambdaMax_ = 0, minSize_ = 0;
  // Bad-triangle candidates, largest relative size R·e^λ first (λ averaged over the corners): refining from the
  // coarse end, as Triangle does, spreads insertions evenly and gives better-shaped meshes than first-in-first-out
  // (measured: mean smallest angle 46–48° → see docs/refinement.md). Keys may go stale when flips change a queued face;
  // they only order the work, processFace re-tests every face.
  std::priority_queue<std::pair<double, int>> faceQueue_;
  // With RefineOptions::frontal: the bad faces next to a face that meets its size target (the front), served before
  // faceQueue_ so that the mesh grows from good regions as in Rebay's algorithm. Entries may go stale; processFace
  // re-tests every face, and every bad face is also in faceQueue_.
  std::priority_queue<std::pair<double, int>> frontQueue_;
  std::vector<char> frontQueued_;
  std::deque<int> segmentQueue_;
  std::vector<char> faceQueued_;
  // Reused work buffers (no allocation per insertion): the cavity search of encroachedByPoint, Lawson's edge stack.
  mutable std::vector<std::pair<int, std::array<Vec3, 3>>> cavityStack_;
  mutable std::vector<int> cavityVisited_;
  std::vector<int> flipStack_;
  std::int64_t insertions_ = 0;
  std::chrono::steady_clock::time_point lastProgress_ = std::chrono::steady_clock::now();
};

void Refiner::validate() {
  intrinsic::validateLengths(in_, "refine input");
  if (!(opt_.epsilon > 0) || !std::isfinite(opt_.epsilon))
    throw InputError("refine: the size bound epsilon must be a finite positive number, got " + num(opt_.epsilon));
  if (!(opt_.ratioBound >= 1) || !std::isfinite(opt_.ratioBound))
    throw InputError("refine: the shape bound B (circumradius / shortest edge) must be at least 1, got " +
                     num(opt_.ratioBound) + " (B = 1 is Chew's 30° bound; no triangle can do better than 1/√3)");
  const int nV = in_.mesh.nVertices();
  if (!opt_.lambda.empty() && static_cast<int>(opt_.lambda.size()) != nV)
    throw InputError("refine: the conformal factor has " + std::to_string(opt_.lambda.size()) +
                     " values, expected one per input vertex (" + std::to_string(nV) + ")");
  for (int v = 0; v < static_cast<int>(opt_.lambda.size()); ++v)
    if (!std::isfinite(opt_.lambda[v]))
      throw InputError("refine: the conformal factor at vertex " + std::to_string(v) + " is not finite (" +
                       num(opt_.lambda[v]) + ")");
  if (!(opt_.maxInsertions > 0)) throw InputError("refine: maxInsertions must be positive");
  if (opt_.smoothingPasses < 0)
    throw InputError("refine: smoothingPasses must be at least 0, got " + std::to_string(opt_.smoothingPasses));
}

void Refiner::setupBoundary() {
  const HalfedgeMesh& m = tri_.mesh;
  edgeLoop_.assign(m.nEdges(), -1);
  const std::vector<std::vector<int>> loops = m.boundaryLoops();
  hasBoundary_ = !loops.empty();
  res_.statistics.boundaryLoops = static_cast<int>(loops.size());
  if (hasBoundary_ && in_.background != Background::Euclidean && opt_.boundarySplit == BoundarySplit::Circle)
    throw InputError("refine: boundary circles are supported in the Euclidean background only (input is " +
                     intrinsic::toString(in_.background) + "); use geodesic boundary splitting");
  const std::vector<double> sums = intrinsic::angleSums(tri_);
  // 60° is the smallest boundary angle for which Ruppert's analysis holds; 1e-9 rad keeps an exact 60° corner regular.
  sharpCorner_.assign(m.nVertices(), 0);
  for (int v = 0; v < m.nVertices(); ++v) sharpCorner_[v] = m.isBoundaryVertex(v) && sums[v] < M_PI / 3 - 1e-9;
  for (int li = 0; li < static_cast<int>(loops.size()); ++li) {
    const std::vector<int>& loop = loops[li];
    for (int h : loop) edgeLoop_[m.edge(h)] = li;
    LoopCircle lc;
    if (in_.background == Background::Euclidean && opt_.boundarySplit != BoundarySplit::Geodesic) {
      // Lay the loop out by its edge lengths and turning angles π − Σθ (the discrete geodesic curvature), then fit a
      // circle (Kåsa's algebraic least squares) and measure how far the vertices are from it.
      const int n = static_cast<int>(loop.size());
      std::vector<Eigen::Vector2d> pos(n);
      Eigen::Vector2d p(0, 0);
      double heading = 0;
      for (int i = 0; i < n; ++i) {
        pos[i] = p;
        const int h = loop[i];
        p += tri_.length(h) * Eigen::Vector2d(std::cos(heading), std::sin(heading));
        heading += M_PI - sums[m.tip(h)];
      }
      Eigen::MatrixXd A(n, 3);
      Eigen::VectorXd b(n);
      for (int i = 0; i < n; ++i) {
        A(i, 0) = pos[i].x();
        A(i, 1) = pos[i].y();
        A(i, 2) = 1;
        b(i) = -pos[i].squaredNorm();
      }
      const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
      const Eigen::Vector2d center(-s(0) / 2, -s(1) / 2);
      const double radius = std::sqrt(std::max(0.0, center.squaredNorm() - s(2)));
      double worst = 0;
      int worstVertex = m.tail(loop[0]);
      for (int i = 0; i < n; ++i) {
        const double dev = std::abs((pos[i] - center).norm() - radius);
        if (dev > worst) {
          worst = dev;
          worstVertex = m.tail(loop[i]);
        }
      }
      double area2 = 0;
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d &u = pos[i], &w = pos[(i + 1) % n];
        area2 += u.x() * w.y() - u.y() * w.x();
      }
      // Every triangle and every rectangle is cocircular; a loop is read as a discretized circle only if it also has
      // at least 6 vertices and turns by at most 60° at each (so a regular hexagon is the coarsest circle).
      double maxTurn = 0;
      for (int h : loop) maxTurn = std::max(maxTurn, std::abs(M_PI - sums[m.tip(h)]));
      const bool cocircular =
          n >= 6 && maxTurn <= M_PI / 3 + 1e-9 && std::isfinite(radius) && worst <= opt_.circleTolerance * radius;
      if (cocircular) {
        lc.circle = true;
        lc.radius = radius;
        lc.centerOnLeft = area2 > 0;
        ++res_.statistics.circleLoops;
      } else if (opt_.boundarySplit == BoundarySplit::Circle && maxTurn > 1e-9) {
        // (A loop that turns nowhere is a closed geodesic — an end of a flat cylinder, uniformization.h — the circle of
        // infinite radius: it is split at geodesic midpoints, which keep it geodesic.)
        throw InputError("refine: boundary loop " + std::to_string(li) + " (" + std::to_string(n) +
                         " edges) is not inscribed in a circle: vertex " + std::to_string(worstVertex) + " lies " +
                         num(worst) + " from the fitted circle of radius " + num(radius) + " (tolerance " +
                         num(opt_.circleTolerance) + " relative), largest turning angle " + num(maxTurn * 180 / M_PI) +
                         "° (a discretized circle needs ≥ 6 vertices and turns ≤ 60°)");
      }
    }
    loops_.push_back(lc);
  }
}

void Refiner::pushFace(int f) {
  if (f >= tri_.mesh.nFaces()) return;  // deleted by a vertex removal since it was named
  if (faceQueued_.size() < static_cast<size_t>(tri_.mesh.nFaces())) faceQueued_.resize(tri_.mesh.nFaces(), 0);
  if (faceQueued_[f]) return;
  faceQueued_[f] = 1;
  const HalfedgeMesh& m = tri_.mesh;
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
  const double meanLambda =
      (res_.lambda[m.faceVertex(f, 0)] + res_.lambda[m.faceVertex(f, 1)] + res_.lambda[m.faceVertex(f, 2)]) / 3;
  faceQueue_.push({std::isfinite(R) ? R * std::exp(meanLambda) : INFINITY, f});
}

bool Refiner::meetsSizeTarget(int f) const {
  // The queue's estimate of the size test (λ averaged over the corners instead of interpolated at the circumcentre):
  // it only chooses where the front is, never whether a face is refined.
  const HalfedgeMesh& m = tri_.mesh;
  const double lam =
      (res_.lambda[m.faceVertex(f, 0)] + res_.lambda[m.faceVertex(f, 1)] + res_.lambda[m.faceVertex(f, 2)]) / 3;
  return circumradiusOf(tri_, f) * std::exp(lam) <= opt_.epsilon;
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
  const double lam =
      (res_.lambda[m.faceVertex(f, 0)] + res_.lambda[m.faceVertex(f, 1)] + res_.lambda[m.faceVertex(f, 2)]) / 3;
  frontQueue_.push({circumradiusOf(tri_, f) * std::exp(lam), f});
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

bool Refiner::segmentEncroached(int e) const {
  // In a Delaunay triangulation a vertex lies strictly inside the diametral circle of boundary edge e only if the apex
  // of e's triangle does, i.e. the angle opposite e exceeds 90°. 1e-10 rad keeps a right angle (the apex ON the
  // circle, not encroaching) from being split because of round-off in the angle.
  const int h = tri_.mesh.edgeHalfedge(e);
  return fastCornerAngle(tri_, HalfedgeMesh::prev(h)) > M_PI / 2 + 1e-10;
}

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
  res_.locations.push_back(arr.location);
  res_.lambda.push_back(uniform_ ? 0.0 : inputPtr_->interpolate(opt_.lambda, arr.location));
  ++res_.statistics.boundarySplits;
  afterInsertion(p);
}

std::vector<int> Refiner::encroachedByPoint(const TraceResult& trace) const {
  // The faces whose circumcircle contains the point (its Delaunay cavity), grown from the face containing it. A point
  // encroaching boundary edge s lies in the circumcircle of s's triangle whenever s itself is not encroached (that
  // circumcircle then contains the half of s's diametral disk on the domain side), so only the cavity's boundary edges
  // need testing. The in-circle test decides only whether a boundary edge is split early, never the triangulation, so
  // it does not need to be exact. This runs once per insertion: the buffers are reused and the Euclidean background
  // uses the polynomial in-circle determinant instead of constructing circumcentres.
  const HalfedgeMesh& m = tri_.mesh;
  const Vec3& t = trace.end;
  const bool flat = tri_.background == Background::Euclidean;
  std::vector<int> result;
  cavityStack_.clear();
  cavityVisited_.clear();
  cavityStack_.push_back({trace.face, trace.corners});
  cavityVisited_.push_back(trace.face);
  auto encroaches = [&](const Vec3& a, const Vec3& b) {
    if (flat) return (a.x() - t.x()) * (b.x() - t.x()) + (a.y() - t.y()) * (b.y() - t.y()) < 0;
    return model_.inner(model_.tangentToward(t, a), model_.tangentToward(t, b)) < 0;
  };
  auto inCircle = [&](const std::array<Vec3, 3>& R) {
    if (flat) {
      // Sign of the classical 3×3 in-circle determinant (R counter-clockwise): positive when t is inside.
      const double ax = R[0].x() - t.x(), ay = R[0].y() - t.y(), bx = R[1].x() - t.x(), by = R[1].y() - t.y();
      const double cx = R[2].x() - t.x(), cy = R[2].y() - t.y();
      const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
      return ax * (by * c2 - b2 * cy) - ay * (bx * c2 - b2 * cx) + a2 * (bx * cy - by * cx) > 0;
    }
    const std::optional<Vec3> cc = model_.circumcenter(R[0], R[1], R[2]);
    return cc && model_.distance(*cc, t) < model_.distance(*cc, R[0]);
  };
  while (!cavityStack_.empty()) {
    const auto [f, P] = cavityStack_.back();
    cavityStack_.pop_back();
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * f + k, g = m.twin(h);
      const Vec3 &Pp = P[k], &Q = P[(k + 1) % 3];
      if (g == kInvalid) {
        if (encroaches(Pp, Q)) result.push_back(m.edge(h));
        continue;
      }
      const int f2 = HalfedgeMesh::face(g);
      if (std::find(cavityVisited_.begin(), cavityVisited_.end(), f2) != cavityVisited_.end()) continue;
      std::array<Vec3, 3> R;
      const int kg = g % 3;
      R[kg] = Q;
      R[(kg + 1) % 3] = Pp;
      R[(kg + 2) % 3] = unfoldThirdVertex(tri_, model_, g, Q, Pp);
      if (inCircle(R)) {
        cavityVisited_.push_back(f2);
        cavityStack_.push_back({f2, R});
      }
    }
  }
  return result;
}

std::vector<int> Refiner::freeVerticesInDiametralDisk(int e) const {
  // The diametral disk of e: centred at e's geodesic midpoint, radius half its length (a geodesic disk in the curved
  // backgrounds). Faces are unfolded from e's own face across interior edges that may meet the disk — an edge PQ of
  // length ℓ meets it only if min(d(M, P), d(M, Q)) < ρ + ℓ/2, a conservative test valid in every background — so the
  // search never crosses the boundary: it finds the free vertices inside the disk that are reachable from e within the
  // faces meeting it (in a convex domain: all of them).
  const HalfedgeMesh& m = tri_.mesh;
  const int ha = m.edgeHalfedge(e), k = ha % 3;
  const std::array<Vec3, 3> P = layoutAtHalfedge(tri_, model_, ha);
  const double L = tri_.edgeLengths[e], rho = L / 2;
  const Vec3 M = model_.exp(P[k], model_.tangentToward(P[k], P[(k + 1) % 3]), rho);
  const int nInput = res_.statistics.inputVertices;
  std::vector<int> result;
  cavityStack_.clear();
  cavityVisited_.clear();
  cavityStack_.push_back({HalfedgeMesh::face(ha), P});
  cavityVisited_.push_back(HalfedgeMesh::face(ha));
  while (!cavityStack_.empty()) {
    const auto [f, Q] = cavityStack_.back();
    cavityStack_.pop_back();
    std::array<double, 3> d;
    for (int j = 0; j < 3; ++j) {
      d[j] = model_.distance(M, Q[j]);
      const int w = m.faceVertex(f, j);
      // Strictly inside, with a relative slack of 1e-12: a vertex on the circle (a triangle inscribed in it) stays.
      if (w >= nInput && !m.isBoundaryVertex(w) && d[j] < rho * (1 - 1e-12) &&
          std::find(result.begin(), result.end(), w) == result.end())
        result.push_back(w);
    }
    for (int j = 0; j < 3; ++j) {
      const int h = 3 * f + j, g = m.twin(h);
      if (g == kInvalid) continue;
      const int f2 = HalfedgeMesh::face(g);
      if (std::find(cavityVisited_.begin(), cavityVisited_.end(), f2) != cavityVisited_.end()) continue;
      if (!(std::min(d[j], d[(j + 1) % 3]) < rho + tri_.length(h) / 2)) continue;
      std::array<Vec3, 3> R;
      const int kg = g % 3;
      R[kg] = Q[(j + 1) % 3];
      R[(kg + 1) % 3] = Q[j];
      R[(kg + 2) % 3] = unfoldThirdVertex(tri_, model_, g, Q[(j + 1) % 3], Q[j]);
      cavityVisited_.push_back(f2);
      cavityStack_.push_back({f2, R});
    }
  }
  return result;
}

int Refiner::deleteFreeVertices(int e) {
  std::vector<int> victims = freeVerticesInDiametralDisk(e);
  const HalfedgeMesh& m = tri_.mesh;
  auto onFlip = [&](int fe) {
    ++res_.statistics.flips;
    const int h = m.edgeHalfedge(fe);
    pushFace(HalfedgeMesh::face(h));
    pushFace(HalfedgeMesh::face(m.twin(h)));
  };
  for (size_t i = 0; i < victims.size(); ++i) {
    VertexRemovalResult r = removeInsertedVertex(tri_, sp_, victims[i], res_.statistics.inputVertices, onFlip);
    if (!r.removed) {
      ++res_.statistics.refusedDeletions;
      restoreDelaunay(r.regionEdges);
      continue;
    }
    ++res_.statistics.deletedVertices;
    // Every per-element array of the refinement follows the compaction (swap-with-last, halfedge_mesh.h).
    const intrinsic::ElementMoves& mv = r.moves;
    intrinsic::applyMoves(res_.locations, mv.vertices, m.nVertices());
    intrinsic::applyMoves(res_.lambda, mv.vertices, m.nVertices());
    intrinsic::applyMoves(sharpCorner_, mv.vertices, m.nVertices());
    intrinsic::applyMoves(edgeLoop_, mv.edges, m.nEdges());
    for (const auto& [from, to] : mv.vertices)
      for (size_t j = i + 1; j < victims.size(); ++j)
        if (victims[j] == from) victims[j] = to;
    for (const auto& [from, to] : mv.edges)
      if (e == from) e = to;
    // Queued faces and segments are named by index: a face that moved (and the merged face) is queued again under its
    // new index; heap entries under old indices are stale and re-tested or skipped (drain, pushFace).
    faceQueued_.resize(m.nFaces(), 0);
    if (frontQueued_.size() > static_cast<size_t>(m.nFaces())) frontQueued_.resize(m.nFaces());
    std::vector<int> moved{r.mergedFace};
    for (const auto& mvf : mv.faces) moved.push_back(mvf.second);
    for (int f : moved) {
      faceQueued_[f] = 0;
      if (f < static_cast<int>(frontQueued_.size())) frontQueued_[f] = 0;
      pushFace(f);
    }
    for (const auto& [from, to] : mv.edges)
      if (m.isBoundaryEdge(to)) segmentQueue_.push_back(to);
    // Removing a vertex leaves the rest of the triangulation Delaunay; only the edges of the region its star covered
    // can fail the test, and Lawson's flips from them restore it everywhere.
    restoreDelaunay(r.regionEdges);
  }
  return e;
}

void Refiner::insertOnEdge(const TraceResult& trace, int j, const InputSurface::Arrival& arr) {
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
  const double arrivalHere = model_.angleOf(t, trace.arrivalTangent(model_));
  const double angleToB = model_.angleOf(t, model_.tangentToward(t, bb)) - arrivalHere + arr.angle;
  const int p = splitEdgeWithSignposts(tri_, sp_, e, model_.distance(a, t), model_.distance(t, bb),
                                       model_.distance(t, c), model_.distance(t, d), angleToB, 0.0);
  res_.locations.push_back(arr.location);
  res_.lambda.push_back(uniform_ ? 0.0 : inputPtr_->interpolate(opt_.lambda, arr.location));
  afterInsertion(p);
}

void Refiner::insertAt(const TraceResult& trace, const InputSurface::Arrival& arr) {
  const std::array<Vec3, 3>& P = trace.corners;
  const Vec3& t = trace.end;
  // A point within 1e-9 (relative, in barycentric terms) of an edge would give a sliver whose lengths may violate the
  // triangle inequality after rounding; it is inserted on the edge instead, moving it by at most ~1e-9 of the face's
  // size.
  int j = 0;
  for (int k = 1; k < 3; ++k)
    if (trace.bary[k] < trace.bary[j]) j = k;
  std::array<double, 3> d{model_.distance(t, P[0]), model_.distance(t, P[1]), model_.distance(t, P[2])};
  const IntrinsicTriangulation& T = tri_;
  const int f = trace.face;
  bool valid = trace.bary[j] > 1e-9;
  for (int k = 0; k < 3 && valid; ++k)
    valid = intrinsic::isValidTriangle(T.background, T.length(3 * f + k), d[k], d[(k + 1) % 3]);
  if (!valid) {
    insertOnEdge(trace, j, arr);
    return;
  }
  countInsertion();
  const double arrivalHere = model_.angleOf(t, trace.arrivalTangent(model_));
  const double angleTo0 = model_.angleOf(t, model_.tangentToward(t, P[0])) - arrivalHere + arr.angle;
  const int p = splitFaceWithSignposts(tri_, sp_, f, d, angleTo0);
  res_.locations.push_back(arr.location);
  res_.lambda.push_back(uniform_ ? 0.0 : inputPtr_->interpolate(opt_.lambda, arr.location));
  afterInsertion(p);
}

void Refiner::processSegment(int e) {
  // Chew's rule keeps the triangulation constrained Delaunay: a vertex inside a diametral circle is allowed, segments
  // are split only for rejected circumcentres.
  if (opt_.segmentRule == SegmentRule::Chew) return;
  if (e >= tri_.mesh.nEdges() || !tri_.mesh.isBoundaryEdge(e)) return;
  if (segmentEncroached(e)) splitSegment(e);
}

void Refiner::processFace(int f) {
  const HalfedgeMesh& m = tri_.mesh;
  double shortest = INFINITY, longest = 0;
  int longestK = 0;
  for (int k = 0; k < 3; ++k) {
    const double l = tri_.length(3 * f + k);
    shortest = std::min(shortest, l);
    if (l > longest) longest = l, longestK = k;
  }
  const double R = circumradiusOf(tri_, f);  // +inf for a hyperbolic triangle without a circumcircle
  // Strict comparisons with a relative slack of 1e-12: a triangle exactly at a bound (circumradius equal to ε, or to
  // B times its shortest edge) is good, whatever the last bit of its computed circumradius.
  // Shewchuk's terminator, in its simplest form: a triangle with a corner at a sharp boundary corner (< 60°) may be
  // as skinny as that input angle forces, so only its size is enforced there; otherwise refinement would shrink the
  // corner's triangles forever.
  bool atSharpCorner = false;
  if (hasBoundary_)
    for (int k = 0; k < 3; ++k) atSharpCorner = atSharpCorner || sharpCorner_[m.faceVertex(f, k)];
  const bool badShape = !atSharpCorner && R > opt_.ratioBound * shortest * (1 + 1e-12);
  bool mayBeBadSize = R > opt_.epsilon * std::exp(-lambdaMax_) * (1 + 1e-12);
  if (!badShape && !mayBeBadSize) return;
  // Trace from the vertex opposite the longest edge: for an obtuse triangle the circumcentre lies beyond that edge, so
  // this is the shortest way there.
  const int hs = 3 * f + (longestK + 2) % 3;
  const int v = m.tail(hs);
  const std::array<Vec3, 3> P = layoutAtHalfedge(tri_, model_, hs);
  const std::optional<Vec3> cc = model_.circumcenter(P[0], P[1], P[2]);
  const bool centroid = !cc || !std::isfinite(R);
  // Hyperbolic triangles whose vertices lie on a horocycle or hypercycle have no circumcircle; they are bad-sized for
  // every ε and are split at their (Klein-model) centroid, which lies inside them.
  Vec3 target = centroid ? model_.normalize(P[0] + P[1] + P[2]) : *cc;
  bool offCenter = false;
  if (badShape && opt_.offCenters && !centroid && in_.background == Background::Euclidean) {
    // Üngör's off-centre: on the bisector of the shortest edge pq, at the height h = ℓ(B + √(B² − 1/4)) where the
    // triangle it forms with pq has circumradius / shortest edge exactly B (apex angle arcsin(1/(2B))), unless the
    // circumcentre is nearer. It lies on the segment from pq's midpoint to the circumcentre, inside the circumcircle,
    // so the bad triangle is still destroyed.
    int ks = 0;
    for (int k = 1; k < 3; ++k)
      if (tri_.length(3 * f + k) < tri_.length(3 * f + ks)) ks = k;
    const Vec3 M = (P[ks] + P[(ks + 1) % 3]) / 2;
    const Vec3 toC = *cc - M;
    const double dist = std::hypot(toC.x(), toC.y());
    const double B = opt_.ratioBound, h = shortest * (B + std::sqrt(B * B - 0.25));
    if (h < dist) {
      target = M + (h / dist) * toC;
      offCenter = true;
    }
  }
  if (std::isfinite(R) && R < minSize_)
    throw ConvergenceError("refine: face " + std::to_string(f) + " (vertices " + std::to_string(m.faceVertex(f, 0)) +
                           ", " + std::to_string(m.faceVertex(f, 1)) + ", " + std::to_string(m.faceVertex(f, 2)) +
                           ") still needs refining at circumradius " + num(R) + ", below the smallest size " +
                           num(minSize_) + ": the shape bound B = " + num(opt_.ratioBound) +
                           " cannot be met near this face (small input angle?)");
  if (centroid && opt_.segmentRule == SegmentRule::Chew && m.twin(3 * f + longestK) == kInvalid) {
    // A hyperbolic triangle without a circumcircle has its vertices on a hypercycle (or horocycle) whose axis lies
    // beyond its longest edge (the arc bulges away from the axis, so the middle vertex — the largest angle — is on the
    // near side): its "circumcentre" is beyond that edge. When the edge is a segment this is Chew's rejection;
    // splitting at the centroid instead would approach the segment forever (measured: a vertex 0.003 from a segment's
    // midpoint, centroids 10⁻³, 3·10⁻⁴, … from it).
    ++res_.statistics.rejectedCircumcenters;
    splitSegment(deleteFreeVertices(m.edge(3 * f + longestK)));
    pushFace(f);
    return;
  }
  // Frontal placement (size-driven triangles only): the point on the bisector of a front edge that makes a triangle of
  // the target size with it. With λ ≡ 0 the size test needs no location, so the frontal point is traced directly;
  // otherwise the circumcentre is located first, for λ(c) of the size test.
  const std::optional<Vec3> front = !badShape && opt_.frontal && !centroid ? frontalPoint(f, P, *cc) : std::nullopt;
  if (front && uniform_) target = *front;
  auto traceTo = [&](const Vec3& x, double& theta, double& r) {
    r = model_.distance(BackgroundModel::origin(), x);
    theta = sp_.turned(tri_, hs, std::atan2(x.y(), x.x()));
    try {
      TraceResult t = traceFromVertex(tri_, sp_, model_, v, theta, r, hs);
      res_.statistics.traceSteps += t.steps;
      return t;
    } catch (const ConvergenceError& err) {
      // The trace names the vertex / face and the cap it hit; add which refinement step it served.
      throw ConvergenceError("refine (epsilon " + num(opt_.epsilon) + ", B " + num(opt_.ratioBound) + ", after " +
                             std::to_string(insertions_) + " insertions): locating the new point of face " +
                             std::to_string(f) + " (circumradius " + num(R) + ") from its vertex " + std::to_string(v) +
                             ": " + err.what());
    }
  };
  double theta = 0, r = 0;
  TraceResult tr = traceTo(target, theta, r);
  bool frontal = front && uniform_;
  if (frontal && !tr.reachedTarget()) {
    // The frontal point lies beyond a boundary edge (a non-convex domain): fall back to the circumcentre.
    target = *cc;
    frontal = false;
    tr = traceTo(target, theta, r);
  }
  if (!tr.reachedTarget()) {
    // The circumcentre lies outside the domain (or, in a non-convex domain, behind a segment): split the boundary edge
    // the geodesic to it crosses (Ruppert, Chew), Chew's rule first deleting the free vertices in its diametral disk.
    ++res_.statistics.rejectedCircumcenters;
    int s = m.edge(tr.boundaryHalfedge);
    if (opt_.segmentRule == SegmentRule::Chew) s = deleteFreeVertices(s);
    splitSegment(s);
    pushFace(f);
    return;
  }
  InputSurface::Arrival arr = inputPtr_->follow(v, v < res_.statistics.inputVertices, res_.locations[v], theta, r);
  if (!badShape) {
    const double lam = uniform_ ? 0.0 : inputPtr_->interpolate(opt_.lambda, arr.location);
    if (!(R > opt_.epsilon * std::exp(-lam) * (1 + 1e-12))) return;
  }
  if (front && !uniform_) {
    double thetaF = 0, rF = 0;
    const TraceResult trF = traceTo(*front, thetaF, rF);
    if (trF.reachedTarget()) {
      tr = trF;
      arr = inputPtr_->follow(v, v < res_.statistics.inputVertices, res_.locations[v], thetaF, rF);
      frontal = true;
    }
  }
  if (hasBoundary_ && opt_.segmentRule == SegmentRule::Ruppert) {
    const std::vector<int> enc = encroachedByPoint(tr);
    if (!enc.empty()) {
      ++res_.statistics.rejectedCircumcenters;
      for (int e : enc)
        if (m.isBoundaryEdge(e)) splitSegment(e);
      pushFace(f);
      return;
    }
  }
  if (centroid)
    ++res_.statistics.centroidInsertions;
  else if (offCenter)
    ++res_.statistics.offCenterInsertions;
  else if (frontal)
    ++res_.statistics.frontalInsertions;
  else
    ++res_.statistics.circumcenterInsertions;
  insertAt(tr, arr);
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
    const double lam2 =
        (res_.lambda[m.faceVertex(f2, 0)] + res_.lambda[m.faceVertex(f2, 1)] + res_.lambda[m.faceVertex(f2, 2)]) / 3;
    if (!(R2 * std::exp(lam2) <= opt_.epsilon)) continue;
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

RefineResult Refiner::run() {
  validate();
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
  setupBoundary();
  drainAll();
  smoothAndRefine();
  return std::move(res_);
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

}  // namespace

SegmentRule parseSegmentRule(const std::string& name) {
  if (name == "ruppert") return SegmentRule::Ruppert;
  if (name == "chew") return SegmentRule::Chew;
  throw InputError("segment rule '" + name + "' is not one of: ruppert, chew");
}

RefineResult refineDelaunay(const IntrinsicTriangulation& input, const RefineOptions& options) {
  Refiner refiner(input, options);
  return refiner.run();
}

}  // namespace conformesh::refine
