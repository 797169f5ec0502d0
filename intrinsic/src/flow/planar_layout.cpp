// planar_layout.cpp — layoutFlat: breadth-first unfolding of a flat triangulation, each halfedge's direction obtained
// by rotating the direction of the edge its face was reached across by the face's corner angles. See planar_layout.h;
// docs/ricci_flow.md ("Uniformization targets and the genus-0 puncture") says why directions are never recomputed from
// coordinates.
#include "conformesh/intrinsic/flow/planar_layout.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "flow/linalg/two_threads.h"

namespace conformesh::intrinsic {

namespace {

// One unfolding of `tri`: the points, the direction of every laid-out halfedge and the (cos, sin) of every corner.
class PlanarUnfolding {
 public:
  PlanarUnfolding(const IntrinsicTriangulation& tri, double mismatch, const std::vector<char>& skipFaces)
      : tri_(tri), m_(tri.mesh), mismatch_(mismatch), skipFaces_(skipFaces) {}

  std::vector<Eigen::Vector2d> run() {
    p_.assign(m_.nVertices(), Eigen::Vector2d::Zero());
    placed_.assign(m_.nVertices(), 0);
    done_.assign(m_.nFaces(), 0);
    meanLength_ = 0;
    for (double l : tri_.edgeLengths) meanLength_ += l;
    meanLength_ /= std::max<std::size_t>(1, tri_.edgeLengths.size());
    dir_.assign(m_.nHalfedges(), Eigen::Vector2d::Zero());
    computeTurns();
    for (int seed = 0; seed < m_.nFaces(); ++seed)
      if (!done_[seed] && !skip(seed)) unfoldFrom(seed);
    return std::move(p_);
  }

 private:
  bool skip(int f) const { return !skipFaces_.empty() && skipFaces_[f]; }

  // Places v at q, or checks that a vertex placed before is within mismatch × (mean edge length) of q.
  void place(int v, const Eigen::Vector2d& q) {
    if (placed_[v]) {
      if ((p_[v] - q).norm() > mismatch_ * meanLength_) {
        std::ostringstream msg;
        msg.precision(3);
        msg << "layoutFlat: vertex " << v << " is reached at two places " << (p_[v] - q).norm()
            << " apart; the metric is not flat or not simply developable";
        throw ConvergenceError(msg.str());
      }
      return;
    }
    p_[v] = q;
    placed_[v] = 1;
  }

  // (cos, sin) of every corner angle of the unskipped faces, up front on two cores: the arctangents, cosines and sines
  // are most of the work, and only the breadth-first unfolding is sequential.
  void computeTurns() {
    turn_.resize(m_.nHalfedges());
    onTwoCores(m_.nFaces(), kParallelMin, [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
      for (auto f = static_cast<int>(begin); f < end; ++f)
        if (!skip(f))
          for (int h = 3 * f; h < 3 * f + 3; ++h) {
            const double angle = cornerAngle(tri_, h);
            turn_[h] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
          }
    });
  }

  // d rotated counter-clockwise (sign +1) or clockwise (−1) by the corner angle at the tail of h.
  Eigen::Vector2d rotate(const Eigen::Vector2d& d, int h, double sign) const {
    const double c = turn_[h].x(), s = sign * turn_[h].y();
    return Eigen::Vector2d(c * d.x() - s * d.y(), s * d.x() + c * d.y());
  }

  // Face of halfedge h (a → b, direction known), third vertex c to the left of a → b: places c from a and sets the
  // directions of the other two halfedges (c → a and b → c), rotating a → b by the angle at a (counter-clockwise) and
  // b → a by the angle at b (clockwise).
  void layFace(int h) {
    const int pv = HalfedgeMesh::prev(h), nx = HalfedgeMesh::next(h);
    const Eigen::Vector2d ac = rotate(dir_[h], h, 1);
    place(m_.tail(pv), p_[m_.tail(h)] + tri_.length(pv) * ac);
    dir_[pv] = -ac;
    dir_[nx] = rotate(-dir_[h], nx, -1);
  }

  // Lays out the seed face (its first edge on the x-axis when neither end is placed yet), then every unskipped face
  // reachable from it, breadth first.
  void unfoldFrom(int seed) {
    const int h = 3 * seed;
    const int a = m_.tail(h), b = m_.tip(h);
    if (!placed_[a] && !placed_[b]) {
      place(a, Eigen::Vector2d(0, 0));
      place(b, Eigen::Vector2d(tri_.length(h), 0));
    }
    dir_[h] = (p_[b] - p_[a]).normalized();
    layFace(h);
    done_[seed] = 1;
    queue_.assign(1, seed);
    for (std::size_t qi = 0; qi < queue_.size(); ++qi) {
      const int f = queue_[qi];
      for (int k = 0; k < 3; ++k) {
        const int t = m_.twin(3 * f + k);
        if (t == kInvalid) continue;
        const int g = HalfedgeMesh::face(t);
        if (done_[g] || skip(g)) continue;
        // In g, t runs from a to b (both placed: they are f's vertices), opposite to f's halfedge.
        dir_[t] = -dir_[3 * f + k];
        layFace(t);
        done_[g] = 1;
        queue_.push_back(g);
      }
    }
  }

  const IntrinsicTriangulation& tri_;
  const HalfedgeMesh& m_;
  const double mismatch_;
  const std::vector<char>& skipFaces_;
  double meanLength_ = 0;
  std::vector<Eigen::Vector2d> p_;
  std::vector<char> placed_, done_;
  std::vector<Eigen::Vector2d> dir_;   // per halfedge: unit direction tail → tip, once its face is laid out
  std::vector<Eigen::Vector2d> turn_;  // per halfedge: (cos, sin) of the corner angle at its tail
  std::vector<int> queue_;
};

}  // namespace

std::vector<Eigen::Vector2d> layoutFlat(const IntrinsicTriangulation& tri, double mismatch,
                                        const std::vector<char>& skipFaces) {
  if (tri.background != Background::Euclidean)
    throw InputError("layoutFlat: the triangulation is " + toString(tri.background) +
                     ", a flat layout needs Euclidean");
  return PlanarUnfolding(tri, mismatch, skipFaces).run();
}

LoopCircle fitLoopCircle(const std::vector<Eigen::Vector2d>& z, const std::vector<int>& loop) {
  const int k = static_cast<int>(loop.size());
  const Eigen::Vector2d &A = z[loop[0]], &B = z[loop[k / 3]], &C = z[loop[(2 * k) / 3]];
  // The circumcentre of A, B, C.
  const double d = 2 * (A.x() * (B.y() - C.y()) + B.x() * (C.y() - A.y()) + C.x() * (A.y() - B.y()));
  LoopCircle c;
  c.centre = {
      (A.squaredNorm() * (B.y() - C.y()) + B.squaredNorm() * (C.y() - A.y()) + C.squaredNorm() * (A.y() - B.y())) / d,
      (A.squaredNorm() * (C.x() - B.x()) + B.squaredNorm() * (A.x() - C.x()) + C.squaredNorm() * (B.x() - A.x())) / d};
  c.radius = (A - c.centre).norm();
  for (int v : loop) c.deviation = std::max(c.deviation, std::abs((z[v] - c.centre).norm() - c.radius) / c.radius);
  return c;
}

}  // namespace conformesh::intrinsic
