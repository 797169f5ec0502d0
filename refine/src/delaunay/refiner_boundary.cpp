// refiner_boundary.cpp — the Refiner's boundary work (refiner.h): which loops are circles (laid out by their lengths
// and turning angles, Kåsa's fit), Ruppert's encroachment tests (of a segment by its apex, of segments by a new point's
// Delaunay cavity) and, for SegmentRule::Chew, the deletion of free vertices from a segment's diametral disk.
#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/QR>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/refine/delaunay/vertex_removal.h"
#include "delaunay/refiner.h"
#include "trace/corner_angle.h"

namespace conformesh::refine::detail {

using detail::fastCornerAngle;
using intrinsic::Background;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;
using intrinsic::kInvalid;

namespace {

// The loop laid out in the plane by its edge lengths and turning angles π − Σθ (the discrete geodesic curvature):
// position i is the tail of loop[i].
std::vector<Eigen::Vector2d> layOutLoop(const IntrinsicTriangulation& tri, const std::vector<int>& loop,
                                        const std::vector<double>& angleSums) {
  const int n = static_cast<int>(loop.size());
  std::vector<Eigen::Vector2d> pos(n);
  Eigen::Vector2d p(0, 0);
  double heading = 0;
  for (int i = 0; i < n; ++i) {
    pos[i] = p;
    const int h = loop[i];
    p += tri.length(h) * Eigen::Vector2d(std::cos(heading), std::sin(heading));
    heading += M_PI - angleSums[tri.mesh.tip(h)];
  }
  return pos;
}

// Kåsa's algebraic least-squares circle through the points: its centre and radius.
void kasaCircle(const std::vector<Eigen::Vector2d>& pos, Eigen::Vector2d& center, double& radius) {
  const int n = static_cast<int>(pos.size());
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    A(i, 0) = pos[i].x();
    A(i, 1) = pos[i].y();
    A(i, 2) = 1;
    b(i) = -pos[i].squaredNorm();
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
  center = Eigen::Vector2d(-s(0) / 2, -s(1) / 2);
  radius = std::sqrt(std::max(0.0, center.squaredNorm() - s(2)));
}

}  // namespace

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
    if (in_.background == Background::Euclidean && opt_.boundarySplit != BoundarySplit::Geodesic)
      lc = fitLoopCircle(li, loop, sums);
    loops_.push_back(lc);
  }
}

LoopCircle Refiner::fitLoopCircle(int li, const std::vector<int>& loop, const std::vector<double>& sums) {
  // Lay the loop out, fit a circle and measure how far the vertices are from it.
  const HalfedgeMesh& m = tri_.mesh;
  const int n = static_cast<int>(loop.size());
  const std::vector<Eigen::Vector2d> pos = layOutLoop(tri_, loop, sums);
  Eigen::Vector2d center;
  double radius = 0;
  kasaCircle(pos, center, radius);
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
  LoopCircle lc;
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
  return lc;
}

bool Refiner::segmentEncroached(int e) const {
  // In a Delaunay triangulation a vertex lies strictly inside the diametral circle of boundary edge e only if the apex
  // of e's triangle does, i.e. the angle opposite e exceeds 90°. 1e-10 rad keeps a right angle (the apex ON the
  // circle, not encroaching) from being split because of round-off in the angle.
  const int h = tri_.mesh.edgeHalfedge(e);
  return fastCornerAngle(tri_, HalfedgeMesh::prev(h)) > M_PI / 2 + 1e-10;
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
    followCompaction(r.moves, r.mergedFace);
    for (const auto& [from, to] : r.moves.vertices)
      for (size_t j = i + 1; j < victims.size(); ++j)
        if (victims[j] == from) victims[j] = to;
    for (const auto& [from, to] : r.moves.edges)
      if (e == from) e = to;
    // Removing a vertex leaves the rest of the triangulation Delaunay; only the edges of the region its star covered
    // can fail the test, and Lawson's flips from them restore it everywhere.
    restoreDelaunay(r.regionEdges);
  }
  return e;
}

void Refiner::followCompaction(const intrinsic::ElementMoves& mv, int mergedFace) {
  // Every per-element array of the refinement follows the compaction (swap-with-last, halfedge_mesh.h).
  const HalfedgeMesh& m = tri_.mesh;
  intrinsic::applyMoves(res_.locations, mv.vertices, m.nVertices());
  intrinsic::applyMoves(res_.lambda, mv.vertices, m.nVertices());
  intrinsic::applyMoves(sharpCorner_, mv.vertices, m.nVertices());
  intrinsic::applyMoves(edgeLoop_, mv.edges, m.nEdges());
  // Queued faces and segments are named by index: a face that moved (and the merged face) is queued again under its
  // new index; heap entries under old indices are stale and re-tested or skipped (drain, pushFace).
  faceQueued_.resize(m.nFaces(), 0);
  if (frontQueued_.size() > static_cast<size_t>(m.nFaces())) frontQueued_.resize(m.nFaces());
  std::vector<int> moved{mergedFace};
  for (const auto& mvf : mv.faces) moved.push_back(mvf.second);
  for (int f : moved) {
    faceQueued_[f] = 0;
    if (f < static_cast<int>(frontQueued_.size())) frontQueued_[f] = 0;
    pushFace(f);
  }
  for (const auto& [from, to] : mv.edges)
    if (m.isBoundaryEdge(to)) segmentQueue_.push_back(to);
}

}  // namespace conformesh::refine::detail
