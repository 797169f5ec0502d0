// image_path.cpp — points on T0, exact crossings of input edges and the development of image paths (image_path.h).
#include "pipeline/image_path.h"

#include <algorithm>
#include <cmath>

namespace conformesh::refine::detail {

using namespace conformesh::intrinsic;

namespace {

// The image path of a piece whose ends lie in faces f1 = (a, b, c) and f2 = (b, a, d) across halfedge h1 (a → b):
// both are rays of R^{2,1}, A = Σ A_i p_i, B = Σ B_i p_i, with <p_i, p_j> = −c_ij²/2 (Penner lengths: T0's lengths, the
// reference decoration). Writing p_d = α p_a + β p_b + γ p_c (γ < 0: d is beyond ab) puts both in one frame; the
// geodesic is the plane spanned by A and B, and it crosses edge ab at X = s A + t B with zero p_c component,
// s = −B_d γ ≥ 0, t = A_c ≥ 0. Returns the edge parameter τ of X (X = (1−τ) a + τ b), or NaN when the crossing
// is not on the edge (the path crosses other faces too).
double edgeCrossing(const IntrinsicTriangulation& t0, int h1, const Eigen::Vector3d& A1, const Eigen::Vector3d& B2) {
  const HalfedgeMesh& m = t0.mesh;
  const int f1 = HalfedgeMesh::face(h1), k = h1 % 3, g = m.twin(h1), f2 = HalfedgeMesh::face(g), j = g % 3;
  const double ab = t0.length(h1), bc = t0.length(3 * f1 + (k + 1) % 3), ca = t0.length(3 * f1 + (k + 2) % 3);
  const double bd = t0.length(3 * f2 + (j + 2) % 3), da = t0.length(3 * f2 + (j + 1) % 3);
  const double cd = (ca * bd + bc * da) / ab;  // Ptolemy: the other diagonal of the ideal quad
  // Gram matrix of (p_a, p_b, p_c): [[0,x,y],[x,0,z],[y,z,0]], inverse 1/(2xyz)·[[−z²,yz,xz],[yz,−y²,xy],[xz,xy,−x²]].
  const double x = -0.5 * ab * ab, y = -0.5 * ca * ca, z = -0.5 * bc * bc;
  const double ra = -0.5 * da * da, rb = -0.5 * bd * bd, rc = -0.5 * cd * cd;
  const double inv = 1.0 / (2 * x * y * z);
  const double alpha = inv * (-z * z * ra + y * z * rb + x * z * rc);
  const double beta = inv * (y * z * ra - y * y * rb + x * y * rc);
  const double gamma = inv * (x * z * ra + x * y * rb - x * x * rc);
  const double Aa = A1[k], Ab = A1[(k + 1) % 3], Ac = A1[(k + 2) % 3];
  const double Ba = B2[(j + 1) % 3], Bb = B2[j], Bd = B2[(j + 2) % 3];
  const double s = -Bd * gamma, t = Ac;
  if (!(gamma < 0) || s + t <= 0) return std::nan("");
  const double Xa = s * Aa + t * (Ba + Bd * alpha), Xb = s * Ab + t * (Bb + Bd * beta);
  const double tau = Xb / (Xa + Xb);
  // Round-off of the coordinates (≈1e-15) moves τ by as much; 1e-12 accepts crossings at a vertex of the edge.
  if (!(Xa + Xb > 0) || !(tau >= -1e-12 && tau <= 1 + 1e-12)) return std::nan("");
  return std::clamp(tau, 0.0, 1.0);
}

// The point R to the left of P → Q with |QR| = lengthQR and |RP| = lengthRP (law of cosines).
Eigen::Vector2d third(const Eigen::Vector2d& P, const Eigen::Vector2d& Q, double lengthQR, double lengthRP) {
  const Eigen::Vector2d u = Q - P;
  const double d = u.norm();
  const double x = (d * d + lengthRP * lengthRP - lengthQR * lengthQR) / (2 * d);
  const double y = std::sqrt(std::max(lengthRP * lengthRP - x * x, 0.0));
  const Eigen::Vector2d e = u / d;
  return P + x * e + y * Eigen::Vector2d(-e.y(), e.x());
}

}  // namespace

Eigen::Vector3d clampToFace(Eigen::Vector3d b) {
  for (int k = 0; k < 3; ++k) b[k] = std::max(b[k], 0.0);
  return b / b.sum();
}

Point toPoint(const FacePoint& p) {
  Point q;
  q.face = p.face;
  q.bary = {p.bary[0], p.bary[1], p.bary[2]};
  return q;
}

Point vertexPoint(const HalfedgeMesh& m, int v) {
  Point p;
  const int h = m.vertexHalfedge(v);
  p.face = HalfedgeMesh::face(h);
  p.bary[h % 3] = 1;
  p.vertex = v;
  return p;
}

// One midpoint (1-to-4) subdivision of a flat triangulation: the same flat metric, the same curvature atoms (a new
// vertex lies inside a flat face or on a straight edge between two, angle sum 2π), every face split into four similar

// Distance in face f of the Euclidean T0 between barycentric points x and y: |Σ d_i p_i|² = −Σ_{i<j} d_i d_j ℓ_ij²
// for a displacement d with Σ d_i = 0 (ℓ_ij the side between corners i and j).
double flatDistance(const IntrinsicTriangulation& t0, int f, const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  const Eigen::Vector3d d = x - y;
  double s = 0;
  for (int k = 0; k < 3; ++k) {
    const double l = t0.length(3 * f + k);  // corner k → k+1
    s -= d[k] * d[(k + 1) % 3] * l * l;
  }
  return std::sqrt(std::max(s, 0.0));
}

// Re-expresses p in face f when it is an input vertex that is a corner of f, or lies on an edge of its face whose
// twin is in f; returns false otherwise.
bool expressIn(const HalfedgeMesh& m, const Point& p, int f, Eigen::Vector3d& bary) {
  if (p.face == f) {
    bary = p.bary;
    return true;
  }
  if (p.vertex != kInvalid) {
    for (int k = 0; k < 3; ++k)
      if (m.faceVertex(f, k) == p.vertex) {
        bary = Eigen::Vector3d::Zero();
        bary[k] = 1;
        return true;
      }
    return false;
  }
  for (int k = 0; k < 3; ++k) {
    if (p.bary[(k + 2) % 3] != 0) continue;  // on edge (k, k+1) only if the opposite coordinate is exactly 0
    const int g = m.twin(3 * p.face + k);
    if (g == kInvalid || HalfedgeMesh::face(g) != f) continue;
    bary = Eigen::Vector3d::Zero();
    bary[g % 3] = p.bary[(k + 1) % 3];
    bary[(g % 3 + 1) % 3] = p.bary[k];
    return true;
  }
  return false;
}

// Resolves a piece whose ends lie in one input face or in two adjacent ones; false when it must be bisected.
bool resolvePiece(const IntrinsicTriangulation& t0, const Point& A, const Point& B, bool tiny, Resolved& r) {
  const HalfedgeMesh& m = t0.mesh;
  if (A.vertex != kInvalid && B.vertex != kInvalid) return false;  // two vertices: which path joins them is unknown
  r.crossing = kInvalid;
  r.viaCorner = -1;
  if (expressIn(m, A, B.face, r.a)) {
    r.faceA = r.faceB = B.face;
    r.b = B.bary;
    r.length = flatDistance(t0, B.face, r.a, r.b);
    return true;
  }
  if (expressIn(m, B, A.face, r.b)) {
    r.faceA = r.faceB = A.face;
    r.a = A.bary;
    r.length = flatDistance(t0, A.face, r.a, r.b);
    return true;
  }
  if (A.vertex != kInvalid || B.vertex != kInvalid) return false;
  r.faceA = A.face;
  r.faceB = B.face;
  r.a = A.bary;
  r.b = B.bary;
  for (int k = 0; k < 3; ++k) {
    const int h = 3 * A.face + k, g = m.twin(h);
    if (g == kInvalid || HalfedgeMesh::face(g) != B.face) continue;
    const double tau = edgeCrossing(t0, h, A.bary, B.bary);
    if (std::isnan(tau)) continue;
    Eigen::Vector3d x1 = Eigen::Vector3d::Zero(), x2 = Eigen::Vector3d::Zero();
    x1[k] = 1 - tau;
    x1[(k + 1) % 3] = tau;
    x2[g % 3] = tau;
    x2[(g % 3 + 1) % 3] = 1 - tau;
    r.crossing = h;
    r.length = flatDistance(t0, A.face, A.bary, x1) + flatDistance(t0, B.face, x2, B.bary);
    return true;
  }
  if (tiny)  // a path through (within round-off of) an input vertex w: the ends' faces share w but no edge
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (m.faceVertex(A.face, i) != m.faceVertex(B.face, j)) continue;
        r.viaCorner = i;
        r.length = flatDistance(t0, A.face, A.bary, Eigen::Vector3d::Unit(i)) +
                   flatDistance(t0, B.face, Eigen::Vector3d::Unit(j), B.bary);
        return true;
      }
  return false;
}

// === developing an image path into the plane
//
// The input is flat inside faces and across edges; only its vertices carry curvature, and a path meets vertices at
// most at its ends, so the unfolded faces lay the path out in the plane (docs/refinement.md, "Mesh pull-back").

void Development::start(int face) {
  face_ = face;
  c_[0] = {0, 0};
  c_[1] = {t_.length(3 * face), 0};
  c_[2] = third(c_[0], c_[1], t_.length(3 * face + 1), t_.length(3 * face + 2));
}

bool Development::across(int k) {
  const int g = t_.mesh.twin(3 * face_ + k);
  if (g == kInvalid) return false;
  const Eigen::Vector2d p = c_[(k + 1) % 3], q = c_[k];  // g runs tail = corner k+1 → tip = corner k
  const int j = g % 3;
  face_ = HalfedgeMesh::face(g);
  c_[j] = p;
  c_[(j + 1) % 3] = q;
  c_[(j + 2) % 3] = third(p, q, t_.length(3 * face_ + (j + 1) % 3), t_.length(3 * face_ + (j + 2) % 3));
  return true;
}

bool Development::moveTo(int target, const Eigen::Vector3d& b, int corner) {
  if (target == face_) return true;
  int best = -1;
  for (int k = 0; k < 3; ++k) {
    const int g = t_.mesh.twin(3 * face_ + k);
    if (g != kInvalid && HalfedgeMesh::face(g) == target && (best < 0 || b[(k + 2) % 3] < b[(best + 2) % 3])) best = k;
  }
  if (best >= 0) return across(best);
  if (corner < 0)
    for (int k = 0; k < 3; ++k)
      if (b[k] == 1) corner = k;
  if (corner < 0) return false;
  // Around the vertex at `corner`: counter-clockwise crosses side corner−1 (→ corner), clockwise side corner.
  const int w = t_.mesh.faceVertex(face_, corner);
  int bestSteps = 1 << 30;
  Eigen::Vector2d bestC[3];
  for (int direction = 0; direction < 2; ++direction) {
    Development d = *this;
    int steps = 0;
    for (; steps < 64 && d.face_ != target; ++steps) {
      int c = -1;
      for (int k = 0; k < 3; ++k)
        if (t_.mesh.faceVertex(d.face_, k) == w) c = k;
      if (c < 0 || !d.across(direction == 0 ? (c + 2) % 3 : c)) break;
    }
    if (d.face_ == target && steps < bestSteps) {
      bestSteps = steps;
      for (int k = 0; k < 3; ++k) bestC[k] = d.c_[k];
    }
  }
  if (bestSteps == 1 << 30) return false;
  face_ = target;
  for (int k = 0; k < 3; ++k) c_[k] = bestC[k];
  return true;
}

}  // namespace conformesh::refine::detail
