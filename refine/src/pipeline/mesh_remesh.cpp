// mesh_remesh.cpp — uniformize → refine → pull back through the input faces, for a surface given by a triangle mesh
// (mesh_remesh.h), or the refinement of the input in its own metric. The pull-back traces each output edge across T0*,
// maps the pieces' ends to T0 through the flow's correspondence, follows each piece's image path across T0's faces
// (straight inside every input face, its crossings of input edges found exactly in the decorated-ideal (light-cone)
// model of flow_correspondence.h), and develops the path into the plane: the distance of its developed ends is the
// output length.
#include "conformesh/refine/pipeline/mesh_remesh.h"

#include "trace/corner_angle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <queue>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/refine/trace/geodesic_trace.h"
#include "conformesh/refine/trace/robust_predicates.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;
using detail::fastCornerAngle;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A point of T0* (face + projective barycentric coordinates) or of T0 (face + affine ones); `vertex` ≥ 0 when the
// point is that input vertex exactly (it can then be re-expressed in any face around it).
struct Point {
  int face = kInvalid;
  Eigen::Vector3d bary{0, 0, 0};
  int vertex = kInvalid;
};

// A straight piece of an output edge inside one T0* face, and its ends' images on T0.
struct Piece {
  int edge = 0;
  int starFace = 0;
  Eigen::Vector3d a, b;  // on T0*, coordinates of starFace
  Point imageA, imageB;  // on T0
  int depth = 0;         // bisections so far
  int order = 0;         // index of the traced piece it comes from (pieces of an edge are traced in path order)
  double t = 0;          // where it starts on that piece, as a fraction of it
};

// Drops the negative coordinate of a point of a boundary cap (beyond a boundary chord, input_location.h) and
// renormalises: the cap is mapped onto its chord at the same fraction, as remesh.cpp maps boundary arcs.
Eigen::Vector3d clampToFace(Eigen::Vector3d b) {
  for (int k = 0; k < 3; ++k) b[k] = std::max(b[k], 0.0);
  return b / b.sum();
}

// === tracing an output edge across T0*, recording the pieces (one per T0* face it crosses)

struct Tracer {
  const IntrinsicTriangulation& star;
  const Signposts& inputSignposts;  // initialSignposts(T0*): the frame of T1*'s signposts at input vertices
  BackgroundModel model;

  // Appends to `out` the pieces of the geodesic leaving from vertex `v` of T1* (located at `from` on T0*, an input
  // vertex iff isInput) in direction theta for `length`.
  void trace(int v, bool isInput, const InputLocation& from, double theta, double length, int edge,
             std::vector<Piece>& out) const {
    const HalfedgeMesh& m = star.mesh;
    int face;
    std::array<Vec3, 3> P;
    Vec3 s, t;
    unsigned exitMask = 7u;
    Eigen::Vector3d entry;
    if (isInput) {
      Wedge w = findWedge(star, inputSignposts, v, theta);
      if (w.halfedge == kInvalid) {
        // A direction along (round-off: just outside) the boundary at a boundary vertex: the nearer boundary edge.
        const int hOut = m.vertexHalfedge(v);
        int hIn = hOut;
        for (int h = hOut; h != kInvalid; h = m.nextOutgoing(h)) hIn = h;
        const double beforeFirst = inputSignposts.reduce(v, inputSignposts.angle[hOut] - theta);
        const double afterLast =
            inputSignposts.reduce(v, theta - inputSignposts.angle[hIn] - fastCornerAngle(star, hIn));
        w = beforeFirst <= afterLast ? Wedge{hOut, 0.0} : Wedge{hIn, fastCornerAngle(star, hIn)};
      }
      const int h = w.halfedge;
      face = HalfedgeMesh::face(h);
      P = layoutAtHalfedge(star, model, h);
      s = BackgroundModel::origin();
      t = model.polar(length, w.offset);
      exitMask = 1u << ((h % 3 + 1) % 3);
      entry = Eigen::Vector3d::Zero();
      entry[h % 3] = 1;
    } else {
      face = from.face;
      P = layoutFace(star, model, face);
      s = model.fromBarycentric(P[0], P[1], P[2], from.bary);
      t = model.exp(s, model.direction(s, theta), length);
      entry = clampToFace(from.bary);
    }
    // A geodesic of length ℓ crosses O(ℓ/h) faces; 20 visits per face is beyond any legitimate walk (as in
    // geodesic_trace.cpp) and turns a cycling walk on degenerate input into an error instead of a hang.
    const long long maxSteps = 20LL * m.nFaces() + 1000;
    for (long long step = 0;; ++step) {
      int o[3];
      bool inside = true;
      for (int k = 0; k < 3; ++k) {
        o[k] = orientationSign(P[k], P[(k + 1) % 3], t);
        if ((exitMask >> k & 1) && o[k] < 0) inside = false;
      }
      int exitK = -1;
      if (!inside)
        for (int k = 0; k < 3 && exitK < 0; ++k) {
          if (!(exitMask >> k & 1) || o[k] >= 0) continue;
          if (orientationSign(s, t, P[k]) <= 0 && orientationSign(s, t, P[(k + 1) % 3]) >= 0) exitK = k;
        }
      if (exitK < 0) {  // the end point is in this face (or within round-off of its edge)
        out.push_back({edge, face, entry, clampToFace(model.barycentric(P[0], P[1], P[2], t)), {}, {}, 0});
        return;
      }
      // The crossing with edge (P[k], P[k+1]): in all three models geodesics are planes through 0, so the crossing is
      // the intersection line of the two planes; projective barycentric coordinates ignore its scale and sign.
      const Vec3 X = (s.cross(t)).cross(P[exitK].cross(P[(exitK + 1) % 3]));
      Eigen::Vector3d beta = model.barycentric(P[0], P[1], P[2], X);
      beta[(exitK + 2) % 3] = 0;
      beta = clampToFace(beta);
      out.push_back({edge, face, entry, beta, {}, {}, 0});
      const int h = 3 * face + exitK, g = m.twin(h);
      if (g == kInvalid) {
        // Out through a boundary chord into its cap (an edge of T1* ending at a vertex on a boundary circle). The cap
        // maps onto its chord (clampToFace), and the end point to its foot there; the edge's image in this face is
        // taken as the straight segment from its entry to that foot (the piece just pushed is extended to it).
        out.back().b = clampToFace(model.barycentric(P[0], P[1], P[2], t));
        return;
      }
      if (step > maxSteps)
        throw ConvergenceError("mesh remesh: the trace of output edge " + std::to_string(edge) +
                               " did not reach its end after " + std::to_string(step) + " faces (last T0* face " +
                               std::to_string(face) + "): degenerate layout");
      const Vec3 Pp = P[exitK], Q = P[(exitK + 1) % 3];
      const int kg = g % 3;
      face = HalfedgeMesh::face(g);
      P[kg] = Q;
      P[(kg + 1) % 3] = Pp;
      P[(kg + 2) % 3] = model.thirdVertex(Q, Pp, fastCornerAngle(star, g), star.length(HalfedgeMesh::prev(g)));
      entry = Eigen::Vector3d::Zero();
      entry[kg] = beta[(exitK + 1) % 3];
      entry[(kg + 1) % 3] = beta[exitK];
      exitMask = 7u & ~(1u << kg);  // s → t is unchanged: the next face is unfolded in the same copy of the model
    }
  }
};

// === pieces on T0: flat distances and exact crossings of input edges

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

// A resolved straight piece of an image path on T0: from `a` in face faceA to `b` in face faceB, which is faceA, or
// the face across halfedge `crossing` of faceA, or (a path through an input vertex, see below) a face sharing the
// corner `viaCorner` of faceA.
struct Resolved {
  int faceA = kInvalid, faceB = kInvalid;
  Eigen::Vector3d a, b;
  int crossing = kInvalid, viaCorner = -1;
  double length = 0;  // of the straight piece(s), each measured in its face
};

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
// The faces an image path crosses, unfolded one onto the next across the edges it crosses, lay the path out in the
// plane (the input is flat inside faces and across edges; only its vertices carry curvature, and a path meets
// vertices at most at its ends). The distance between its two developed ends is the output edge's length. Around
// an output triangle the three paths bound the image of the triangle, which contains no input vertex, so the three
// developments agree (no holonomy) and the three lengths are the sides of the flat triangle spanned by the developed
// vertices: T1 is a valid Euclidean triangulation whatever the distortion of the map, and where the image path is
// straight (a flat region mapped without bends) the length is the path's own.
class Development {
 public:
  explicit Development(const IntrinsicTriangulation& t) : t_(t) {}

  void start(int face) {
    face_ = face;
    c_[0] = {0, 0};
    c_[1] = {t_.length(3 * face), 0};
    c_[2] = third(c_[0], c_[1], t_.length(3 * face + 1), t_.length(3 * face + 2));
  }
  int face() const { return face_; }
  Eigen::Vector2d point(const Eigen::Vector3d& b) const { return b[0] * c_[0] + b[1] * c_[1] + b[2] * c_[2]; }

  // Unfolds the neighbour across side k (corner k → k+1) of the current face. False on the boundary.
  bool across(int k) {
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

  // Moves to face `target`: across a shared side when there is one (the side whose opposite coordinate of the current
  // point `b` is smallest, in case of multi-edges), else around the shared corner `corner` (if ≥ 0; else the corner
  // where b is 1) the way that crosses fewer faces.
  bool moveTo(int target, const Eigen::Vector3d& b, int corner) {
    if (target == face_) return true;
    int best = -1;
    for (int k = 0; k < 3; ++k) {
      const int g = t_.mesh.twin(3 * face_ + k);
      if (g != kInvalid && HalfedgeMesh::face(g) == target && (best < 0 || b[(k + 2) % 3] < b[(best + 2) % 3]))
        best = k;
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

 private:
  // The point R to the left of P → Q with |QR| = lengthQR and |RP| = lengthRP (law of cosines).
  static Eigen::Vector2d third(const Eigen::Vector2d& P, const Eigen::Vector2d& Q, double lengthQR, double lengthRP) {
    const Eigen::Vector2d u = Q - P;
    const double d = u.norm();
    const double x = (d * d + lengthRP * lengthRP - lengthQR * lengthQR) / (2 * d);
    const double y = std::sqrt(std::max(lengthRP * lengthRP - x * x, 0.0));
    const Eigen::Vector2d e = u / d;
    return P + x * e + y * Eigen::Vector2d(-e.y(), e.x());
  }

  const IntrinsicTriangulation& t_;
  int face_ = kInvalid;
  Eigen::Vector2d c_[3];
};

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
// ones. Old vertices keep their indices; the midpoint of edge e is vertex n + e. parentFace / parentBary carry each new
// face and its corners back to the face it came from.
struct Subdivision {
  IntrinsicTriangulation tri;
  std::vector<int> parentFace;                         // per new face
  std::vector<std::array<Eigen::Vector3d, 3>> corner;  // per new face: its corners in the parent's coordinates
};

Subdivision subdivide(const IntrinsicTriangulation& t) {
  const HalfedgeMesh& m = t.mesh;
  const int n = m.nVertices(), nf = m.nFaces();
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<double, 3>> sides;  // per new face corner k: length of its side k → k+1
  Subdivision out;
  for (int f = 0; f < nf; ++f) {
    int v[3], mid[3];
    double l[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = m.faceVertex(f, k);
      mid[k] = n + m.edge(3 * f + k);  // midpoint of side k → k+1
      l[k] = t.length(3 * f + k);
    }
    const Eigen::Vector3d e[3] = {Eigen::Vector3d::Unit(0), Eigen::Vector3d::Unit(1), Eigen::Vector3d::Unit(2)};
    for (int k = 0; k < 3; ++k) {  // corner triangle at corner k: (v_k, mid_k, mid_{k−1})
      const int km = (k + 2) % 3;
      faces.push_back({v[k], mid[k], mid[km]});
      sides.push_back({l[k] / 2, l[(k + 1) % 3] / 2, l[km] / 2});
      out.parentFace.push_back(f);
      out.corner.push_back({e[k], 0.5 * (e[k] + e[(k + 1) % 3]), 0.5 * (e[k] + e[km])});
    }
    faces.push_back({mid[0], mid[1], mid[2]});  // the middle triangle, sides parallel to the face's
    sides.push_back({l[2] / 2, l[0] / 2, l[1] / 2});
    out.parentFace.push_back(f);
    out.corner.push_back({0.5 * (e[0] + e[1]), 0.5 * (e[1] + e[2]), 0.5 * (e[2] + e[0])});
  }
  out.tri.mesh = HalfedgeMesh::fromFaces(faces, n + m.nEdges(), "subdivided input");
  out.tri.background = Background::Euclidean;
  out.tri.edgeLengths.assign(out.tri.mesh.nEdges(), 0.0);
  for (int f = 0; f < out.tri.mesh.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) out.tri.edgeLengths[out.tri.mesh.edge(3 * f + k)] = sides[f][k];
  return out;
}

// Affine interpolation of the input's positions at each output vertex's location (empty without positions).
std::vector<Eigen::Vector3d> interpolatePositions(const IntrinsicTriangulation& input,
                                                  const std::vector<Eigen::Vector3d>& inputPositions,
                                                  const std::vector<FacePoint>& location) {
  std::vector<Eigen::Vector3d> out;
  if (inputPositions.empty()) return out;
  out.reserve(location.size());
  for (const FacePoint& p : location) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) x += p.bary[k] * inputPositions[input.mesh.faceVertex(p.face, k)];
    out.push_back(x);
  }
  return out;
}

// Orientation of the output triangles on T0 where the three vertices can be written in one input face (directly, or
// a vertex or a point on a side re-expressed in a neighbouring face), and the same-face length check: an edge whose
// ends can be written in one face is compared with the straight distance of the ends there. A loop edge (both ends one
// vertex: a geodesic loop around a cone vertex of angle below π, which an intrinsic Delaunay triangulation may hold)
// and its triangles have no such picture in one face; they are counted, not checked.
void checkAgainstLocations(const IntrinsicTriangulation& t0, const IntrinsicTriangulation& t1,
                           const std::vector<Point>& vertexImage, MeshRemeshResult& out) {
  const HalfedgeMesh &m0 = t0.mesh, &m1 = t1.mesh;
  for (int f = 0; f < m1.nFaces(); ++f) {
    const int v0 = m1.faceVertex(f, 0), v1 = m1.faceVertex(f, 1), v2 = m1.faceVertex(f, 2);
    if (v0 == v1 || v1 == v2 || v2 == v0) continue;
    const Point* p[3] = {&vertexImage[v0], &vertexImage[v1], &vertexImage[v2]};
    for (int k = 0; k < 3; ++k) {
      const int face = p[k]->face;
      Eigen::Vector3d b[3];
      if (!expressIn(m0, *p[0], face, b[0]) || !expressIn(m0, *p[1], face, b[1]) || !expressIn(m0, *p[2], face, b[2]))
        continue;
      Eigen::Matrix3d B;
      B << b[0], b[1], b[2];
      ++out.orientationChecked;
      if (!(B.determinant() > 0)) ++out.invertedTriangles;
      break;
    }
  }
  for (int e = 0; e < m1.nEdges(); ++e) {
    const int h = m1.edgeHalfedge(e);
    if (m1.tail(h) == m1.tip(h)) {
      ++out.loopEdges;
      continue;
    }
    const Point &a = vertexImage[m1.tail(h)], &b = vertexImage[m1.tip(h)];
    Eigen::Vector3d x;
    double d;
    if (expressIn(m0, a, b.face, x))
      d = flatDistance(t0, b.face, x, b.bary);
    else if (expressIn(m0, b, a.face, x))
      d = flatDistance(t0, a.face, a.bary, x);
    else
      continue;
    ++out.sameFaceEdges;
    out.maxSameFaceLengthError =
        std::max(out.maxSameFaceLengthError, std::abs(t1.edgeLengths[e] - d) / t1.edgeLengths[e]);
  }
}

// The input route (mesh_remesh.h, top): Delaunay refinement of the input in its own metric. The refiner flips the
// input to its intrinsic Delaunay triangulation first and records every inserted vertex on the input's own faces, so
// the output needs no map: its lengths are the refinement's, its locations the refinement's.
MeshRemeshResult remeshInInputMetric(const IntrinsicTriangulation& input,
                                     const std::vector<Eigen::Vector3d>& inputPositions,
                                     const MeshRemeshOptions& options) {
  auto say = [&](const std::string& s) {
    if (options.progress) options.progress(s);
  };
  MeshRemeshResult out;
  out.refinedIn = RefineMetric::Input;
  out.inputVertices = out.t0Vertices = input.mesh.nVertices();
  out.inputFaces = input.mesh.nFaces();

  auto t = std::chrono::steady_clock::now();
  RefineOptions ref = options.refinement;
  ref.epsilon = options.epsilon;
  ref.ratioBound = options.ratioBound;
  ref.lambda.clear();
  // The input's boundary is a polygon of straight input edges: split it where it lies, never on a fitted circle
  // (which would put vertices off the input's faces).
  ref.boundarySplit = BoundarySplit::Geodesic;
  if (!ref.progress && options.progress)
    ref.progress = [&](const RefineProgress& p) {
      say("refining: " + std::to_string(p.vertices) + " vertices, " + std::to_string(p.queuedTriangles) +
          " bad triangles queued");
    };
  say("refining the input in its own metric, eps = " + std::to_string(options.epsilon));
  RefineResult refined = refineDelaunay(input, ref);
  out.refinement = refined.statistics;
  out.seconds.refine = secondsSince(t);

  t = std::chrono::steady_clock::now();
  const HalfedgeMesh& m0 = input.mesh;
  const int n0 = m0.nVertices(), n1 = refined.triangulation.mesh.nVertices();
  out.lambda = refined.lambda;  // λ ≡ 0: the refinement's metric is the input's
  out.location.resize(n1);
  std::vector<Point> vertexImage(n1);
  for (int v = 0; v < n1; ++v) {
    // Round-off may leave a coordinate of an inserted vertex at −1e-17; the output claims a point of its face.
    vertexImage[v] =
        v < n0 ? vertexPoint(m0, v) : Point{refined.locations[v].face, clampToFace(refined.locations[v].bary)};
    const Eigen::Vector3d& b = vertexImage[v].bary;
    out.location[v] = {vertexImage[v].face, {b[0], b[1], b[2]}};
  }
  out.positions = interpolatePositions(input, inputPositions, out.location);
  out.mesh = std::move(refined.triangulation);
  out.pathLength = out.mesh.edgeLengths;  // each edge is a geodesic of the input: its own path
  checkAgainstLocations(input, out.mesh, vertexImage, out);
  out.quality = measureQuality(out.mesh);
  out.uniformQuality = out.quality;
  out.seconds.pullBack = secondsSince(t);
  return out;
}

}  // namespace

std::string toString(RefineMetric metric) {
  return metric == RefineMetric::Input ? "input" : "uniformized";
}

RefineMetric parseRefineMetric(const std::string& name) {
  for (RefineMetric m : {RefineMetric::Uniformized, RefineMetric::Input})
    if (toString(m) == name) return m;
  throw InputError("refine metric '" + name + "' is not one of uniformized, input");
}

// === pipeline

MeshInput meshInputFromData(const MeshData& data) {
  if (data.background != Background::Euclidean)
    throw InputError(data.source + ": mesh remeshing needs a Euclidean input (flat faces); found a " +
                     std::string(data.background == Background::Spherical ? "spherical" : "hyperbolic") +
                     " background");
  MeshInput in;
  in.source = data.source;
  ConversionReport report;
  in.triangulation = toTriangulation(data, &report);
  if (!data.positions.empty()) {
    in.positions.resize(in.triangulation.mesh.nVertices());
    for (int v = 0; v < data.nVertices; ++v)
      if (report.vertexMap[v] != kInvalid) in.positions[report.vertexMap[v]] = data.positions[v];
  }
  return in;
}

MeshRemeshResult remeshMesh(const IntrinsicTriangulation& input, const std::vector<Eigen::Vector3d>& inputPositions,
                            const MeshRemeshOptions& options) {
  if (!(options.epsilon > 0) || !std::isfinite(options.epsilon))
    throw InputError("remesh: --eps must be a positive size in the input mesh's units, found " +
                     std::to_string(options.epsilon));
  if (input.background != Background::Euclidean)
    throw InputError("remesh: the input mesh must have a Euclidean background (flat faces)");
  if (options.inputSubdivisions < 0 || options.inputSubdivisions > 6)
    throw InputError("remesh: input subdivisions must be 0..6, found " + std::to_string(options.inputSubdivisions));
  validateLengths(input, "remesh input");
  if (!inputPositions.empty() && inputPositions.size() != static_cast<std::size_t>(input.mesh.nVertices()))
    throw InputError("remesh: " + std::to_string(inputPositions.size()) + " positions for " +
                     std::to_string(input.mesh.nVertices()) + " input vertices");
  if (options.refineIn == RefineMetric::Input) {
    if (options.inputSubdivisions != 0)
      throw InputError(
          "remesh: input subdivisions apply when refining in the uniformized metric, not in the input's "
          "(found " +
          std::to_string(options.inputSubdivisions) + ")");
    if (options.uniform)
      throw InputError(
          "remesh: --uniform (lambda = 0 in the uniformized domain) does not apply when refining in the "
          "input metric, where the size bound is uniform on the input already");
    if (options.refinement.boundarySplit == BoundarySplit::Circle)
      throw InputError(
          "remesh: boundary splits on circles need the uniformized metric; the input's boundary is "
          "split at edge midpoints");
    return remeshInInputMetric(input, inputPositions, options);
  }
  // T0: the input, midpoint-subdivided `inputSubdivisions` times (the same flat surface), with each face's place in
  // the input (face + affine map of its corners).
  IntrinsicTriangulation t0 = input;
  std::vector<int> parentFace(input.mesh.nFaces());
  std::vector<std::array<Eigen::Vector3d, 3>> parentCorner(input.mesh.nFaces());
  for (int f = 0; f < input.mesh.nFaces(); ++f) {
    parentFace[f] = f;
    parentCorner[f] = {Eigen::Vector3d::Unit(0), Eigen::Vector3d::Unit(1), Eigen::Vector3d::Unit(2)};
  }
  for (int level = 0; level < options.inputSubdivisions; ++level) {
    Subdivision sub = subdivide(t0);
    std::vector<int> face(sub.parentFace.size());
    std::vector<std::array<Eigen::Vector3d, 3>> corner(sub.parentFace.size());
    for (std::size_t f = 0; f < face.size(); ++f) {
      const int p = sub.parentFace[f];
      face[f] = parentFace[p];
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d& b = sub.corner[f][k];
        corner[f][k] = b[0] * parentCorner[p][0] + b[1] * parentCorner[p][1] + b[2] * parentCorner[p][2];
      }
    }
    t0 = std::move(sub.tri);
    parentFace = std::move(face);
    parentCorner = std::move(corner);
  }
  const HalfedgeMesh& m0 = t0.mesh;
  const int n0 = m0.nVertices();
  auto say = [&](const std::string& s) {
    if (options.progress) options.progress(s);
  };
  MeshRemeshResult out;
  out.inputVertices = input.mesh.nVertices();
  out.inputFaces = input.mesh.nFaces();
  out.t0Vertices = n0;

  // === 1. uniformize T0 → T0*, λ and the correspondence
  auto t = std::chrono::steady_clock::now();
  UniformizationOptions uni = options.uniformization;
  if (!uni.progress) uni.progress = options.progress;
  say("uniformizing the input (" + std::to_string(n0) + " vertices) by discrete Ricci flow");
  const Uniformization u = uniformize(t0, uni);
  out.uniformization = u.report;
  out.seconds.uniformize = secondsSince(t);

  // === 2. refine T0*, graded by e^(−λ)
  t = std::chrono::steady_clock::now();
  RefineOptions ref = options.refinement;
  ref.epsilon = options.epsilon;
  ref.ratioBound = options.ratioBound;
  if (!options.uniform) ref.lambda = u.lambda;
  if (!ref.progress && options.progress)
    ref.progress = [&](const RefineProgress& p) {
      say("refining: " + std::to_string(p.vertices) + " vertices, " + std::to_string(p.queuedTriangles) +
          " bad triangles queued");
    };
  say("refining the uniformized surface, eps = " + std::to_string(options.epsilon));
  const RefineResult refined = refineDelaunay(u.uniform, ref);
  out.refinement = refined.statistics;
  out.uniformQuality = measureQuality(refined.triangulation);
  out.seconds.refine = secondsSince(t);

  // === 3. pull back
  t = std::chrono::steady_clock::now();
  const IntrinsicTriangulation& star = u.uniform;
  const HalfedgeMesh& m1 = refined.triangulation.mesh;
  const int n1 = m1.nVertices();
  say("pulling back " + std::to_string(n1) + " vertices and " + std::to_string(m1.nEdges()) +
      " edges through the input faces");
  out.lambda = refined.lambda;

  // Vertices: input vertices are themselves; inserted ones go through the correspondence (boundary caps clamped).
  out.location.resize(n1);
  std::vector<Point> vertexImage(n1);
  {
    std::vector<FacePoint> onStar;
    for (int v = n0; v < n1; ++v) {
      const Eigen::Vector3d b = clampToFace(refined.locations[v].bary);
      onStar.push_back({refined.locations[v].face, {b[0], b[1], b[2]}});
    }
    const std::vector<FacePoint> onInput = u.correspondence.mapToInput(star.mesh, onStar);
    for (int v = 0; v < n1; ++v) {
      vertexImage[v] = v < n0 ? vertexPoint(m0, v) : toPoint(onInput[v - n0]);
      const Point& p = vertexImage[v];
      const Eigen::Vector3d b = p.bary[0] * parentCorner[p.face][0] + p.bary[1] * parentCorner[p.face][1] +
                                p.bary[2] * parentCorner[p.face][2];
      out.location[v] = {parentFace[p.face], {b[0], b[1], b[2]}};
    }
  }
  out.positions = interpolatePositions(input, inputPositions, out.location);

  // Edges: trace each across T0*, one piece per T0* face.
  const Signposts inputSignposts = initialSignposts(star);
  const Tracer tracer{star, inputSignposts, BackgroundModel(star.background)};
  std::vector<Piece> pieces;
  pieces.reserve(2 * m1.nEdges());
  std::vector<int> firstPiece(m1.nEdges() + 1);
  for (int e = 0; e < m1.nEdges(); ++e) {
    firstPiece[e] = static_cast<int>(pieces.size());
    const int h = m1.edgeHalfedge(e), a = m1.tail(h), b = m1.tip(h);
    tracer.trace(a, a < n0, refined.locations[a], refined.signposts.angle[h], refined.triangulation.length(h), e,
                 pieces);
    // The ends are the vertices' own images (an input vertex exactly).
    Piece& last = pieces.back();
    if (b < n0)
      for (int k = 0; k < 3; ++k)
        if (star.mesh.faceVertex(last.starFace, k) == b) last.b = Eigen::Vector3d::Unit(k);
  }
  firstPiece[m1.nEdges()] = static_cast<int>(pieces.size());
  {
    std::vector<FacePoint> ends;
    ends.reserve(2 * pieces.size());
    for (const Piece& p : pieces)
      for (const Eigen::Vector3d* b : {&p.a, &p.b}) ends.push_back({p.starFace, {(*b)[0], (*b)[1], (*b)[2]}});
    const std::vector<FacePoint> images = u.correspondence.mapToInput(star.mesh, ends);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      pieces[i].imageA = toPoint(images[2 * i]);
      pieces[i].imageB = toPoint(images[2 * i + 1]);
    }
    for (int e = 0; e < m1.nEdges(); ++e) {
      const int h = m1.edgeHalfedge(e);
      // The ends are the vertices' own images: exact for input vertices, and for a vertex on a boundary circle its
      // foot on its own chord (the trace may reach its cap across a neighbouring chord).
      pieces[firstPiece[e]].imageA = vertexImage[m1.tail(h)];
      pieces[firstPiece[e + 1] - 1].imageB = vertexImage[m1.tip(h)];
    }
  }

  // Bisect pieces whose image ends are neither in one input face nor in two adjacent ones, all together per round
  // (one pass of the correspondence per round). Each halving shortens the image by about half; a piece still
  // unresolved after 60 (below 1e-18 of its edge) means a degenerate input.
  // After 50 halvings a piece is 2⁻⁵⁰ ≈ 1e-15 of its edge: ends whose faces share only a vertex are then taken to
  // pass through it (the path cannot be told from one through the vertex in double precision).
  constexpr int kTinyRound = 50;
  std::vector<double> pathLength(m1.nEdges(), 0.0);
  out.edgePieces.assign(m1.nEdges(), 0);
  struct Record {
    int edge, order;
    double t;
    Resolved r;
  };
  std::vector<Record> records;
  records.reserve(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) pieces[i].order = static_cast<int>(i);
  std::vector<Piece> pending = std::move(pieces);
  for (int round = 0; !pending.empty(); ++round) {
    std::vector<Piece> split;
    for (const Piece& p : pending) {
      Resolved r;
      if (p.depth >= options.extraBisections && resolvePiece(t0, p.imageA, p.imageB, round >= kTinyRound, r)) {
        pathLength[p.edge] += r.length;
        out.edgePieces[p.edge] += r.crossing != kInvalid || r.viaCorner >= 0 ? 2 : 1;
        if (r.crossing != kInvalid || r.viaCorner >= 0) ++out.inputEdgeCrossings;
        records.push_back({p.edge, p.order, p.t, r});
        continue;
      }
      if (round >= 60)
        throw ConvergenceError("mesh remesh: the image of output edge " + std::to_string(p.edge) +
                               " could not be followed across the input faces (input faces " +
                               std::to_string(p.imageA.face) + " and " + std::to_string(p.imageB.face) +
                               " after 60 halvings): degenerate input");
      const Eigen::Vector3d mid = 0.5 * (p.a + p.b);  // on the T0* segment: projective coordinates are affine on it
      const double half = std::ldexp(1.0, -(p.depth + 1));
      split.push_back({p.edge, p.starFace, p.a, mid, p.imageA, {}, p.depth + 1, p.order, p.t});
      split.push_back({p.edge, p.starFace, mid, p.b, {}, p.imageB, p.depth + 1, p.order, p.t + half});
    }
    if (split.empty()) break;
    std::vector<FacePoint> mids(split.size() / 2);
    for (std::size_t i = 0; i < mids.size(); ++i) {
      const Eigen::Vector3d& b = split[2 * i].b;
      mids[i] = {split[2 * i].starFace, {b[0], b[1], b[2]}};
    }
    const std::vector<FacePoint> images = u.correspondence.mapToInput(star.mesh, mids);
    for (std::size_t i = 0; i < mids.size(); ++i) split[2 * i].imageB = split[2 * i + 1].imageA = toPoint(images[i]);
    pending = std::move(split);
  }
  for (int n : out.edgePieces) out.pathPieces += n;

  // Develop each edge's path (records in path order) and measure its ends' distance in the plane.
  std::sort(records.begin(), records.end(),
            [](const Record& x, const Record& y) { return x.order != y.order ? x.order < y.order : x.t < y.t; });
  std::vector<double> lengths(m1.nEdges(), 0.0);
  Development dev(t0);
  for (std::size_t i = 0; i < records.size();) {
    const int e = records[i].edge;
    dev.start(records[i].r.faceA);
    const Eigen::Vector2d from = dev.point(records[i].r.a);
    Eigen::Vector3d at = records[i].r.a;  // the current point, in the current face
    for (; i < records.size() && records[i].edge == e; ++i) {
      const Resolved& r = records[i].r;
      if (!dev.moveTo(r.faceA, at, -1))
        throw ConvergenceError("mesh remesh: the image path of output edge " + std::to_string(e) +
                               " jumps from input face " + std::to_string(dev.face()) + " to face " +
                               std::to_string(r.faceA) + ", which shares no side or corner with it");
      if (r.crossing != kInvalid) dev.across(r.crossing % 3);
      if (r.viaCorner >= 0 && !dev.moveTo(r.faceB, Eigen::Vector3d::Unit(r.viaCorner), r.viaCorner))
        throw ConvergenceError("mesh remesh: the image path of output edge " + std::to_string(e) +
                               " passes input vertex " + std::to_string(m0.faceVertex(r.faceA, r.viaCorner)) +
                               " between faces that its fan does not join");
      at = r.b;
    }
    lengths[e] = (dev.point(at) - from).norm();
    if (lengths[e] > 0) out.maxBendExcess = std::max(out.maxBendExcess, pathLength[e] / lengths[e] - 1);
  }

  out.pathLength = pathLength;
  out.mesh.mesh = m1;
  out.mesh.background = Background::Euclidean;
  out.mesh.edgeLengths = lengths;
  validateLengths(out.mesh, "remeshed surface (developed image-path lengths)");

  // Orientation of the map back, and the edges within one input face (on T0: with subdivisions, its faces).
  checkAgainstLocations(t0, out.mesh, vertexImage, out);
  out.quality = measureQuality(out.mesh);
  out.seconds.pullBack = secondsSince(t);
  return out;
}

// === the curvature-measure check

CurvatureMeasureResult meshCurvatureMeasure(const MeshRemeshResult& r, const IntrinsicTriangulation& input,
                                            const CurvatureMeasureOptions& options) {
  const HalfedgeMesh& m = r.mesh.mesh;
  const int n = m.nVertices(), n0 = input.mesh.nVertices();
  if (r.inputVertices != n0) throw InputError("curvature measure: the result is not a remeshing of this input");
  const std::vector<double> k1 = vertexCurvatures(r.mesh), k0 = vertexCurvatures(input);
  CurvatureMeasureResult c;
  c.radius = options.radiusFraction * std::sqrt(totalArea(r.mesh));
  c.discrete.assign(n, 0.0);
  c.smooth.assign(n, 0.0);
  c.absoluteScale.assign(n, 0.0);
  c.relativeError.assign(n, 0.0);
  c.histogram.assign(options.histogramBins, 0);
  for (double x : k0) c.smoothTotalCurvature += x;
  // Truncated Dijkstra from each vertex along the output's edges.
  std::vector<double> dist(n, INFINITY);
  std::vector<int> touched;
  using Item = std::pair<double, int>;
  int within = 0;
  for (int v = 0; v < n; ++v) {
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
    dist[v] = 0;
    touched.push_back(v);
    q.push({0.0, v});
    while (!q.empty()) {
      const auto [d, w] = q.top();
      q.pop();
      if (d > dist[w]) continue;
      c.discrete[v] += k1[w];
      if (w < n0) {
        c.smooth[v] += k0[w];
        c.absoluteScale[v] += std::abs(k0[w]);
      }
      const int h0 = m.vertexHalfedge(w);
      // Every outgoing halfedge of w, and for a boundary vertex the incoming boundary edge too.
      for (int h = h0;;) {
        for (int g : {h, HalfedgeMesh::prev(h)}) {
          const int x = g == h ? m.tip(h) : m.tail(g);
          const double nd = d + r.mesh.length(g);
          if (nd < c.radius && nd < dist[x]) {
            if (dist[x] == INFINITY) touched.push_back(x);
            dist[x] = nd;
            q.push({nd, x});
          }
        }
        h = m.nextOutgoing(h);
        if (h == kInvalid || h == h0) break;
      }
    }
    for (int w : touched) dist[w] = INFINITY;
    touched.clear();
    const double err = c.discrete[v] - c.smooth[v];
    c.meanAbsoluteError += std::abs(err) / n;
    c.maxAbsoluteError = std::max(c.maxAbsoluteError, std::abs(err));
    c.relativeError[v] = c.absoluteScale[v] > 0 ? err / c.absoluteScale[v] : 0.0;
    if (std::abs(c.relativeError[v]) < options.withinBand) ++within;
    const double x = (c.relativeError[v] + options.histogramRange) / (2 * options.histogramRange);
    const int bin = std::clamp(static_cast<int>(std::floor(x * options.histogramBins)), 0, options.histogramBins - 1);
    ++c.histogram[bin];
    if (options.progress && ((v + 1) % ((n + 99) / 100) == 0 || v + 1 == n)) options.progress(v + 1, n);
  }
  c.fractionWithinBand = n > 0 ? static_cast<double>(within) / n : 0.0;
  return c;
}

// === output

MeshData toMeshData(const MeshRemeshResult& r, const std::string& source, double epsilon) {
  MeshData d = fromTriangulation(r.mesh);
  d.source = source;
  if (!r.positions.empty()) d.positions = r.positions;
  const int n = r.mesh.mesh.nVertices();
  auto& p = d.vertexProperties;
  p["input_face"].resize(n);
  for (const char* b : {"input_b0", "input_b1", "input_b2"}) p[b].resize(n);
  for (int v = 0; v < n; ++v) {
    p["input_face"][v] = r.location[v].face;
    p["input_b0"][v] = r.location[v].bary[0];
    p["input_b1"][v] = r.location[v].bary[1];
    p["input_b2"][v] = r.location[v].bary[2];
  }
  p["lambda"] = r.lambda;
  p["curvature"] = vertexCurvatures(r.mesh);
  char eps[64];
  std::snprintf(eps, sizeof eps, "%.17g", epsilon);
  d.comments.push_back("conformesh remesh: mesh " + source);
  d.comments.push_back("eps " + std::string(eps) + " (circumradius bound in the input mesh's metric)");
  d.comments.push_back(r.refinedIn == RefineMetric::Input
                           ? "lengths: refined in the input's own metric; the refined triangulation's lengths"
                           : "lengths: lengths of the edges' image paths across the input faces");
  d.comments.push_back("input: " + std::to_string(r.inputVertices) + " vertices, " + std::to_string(r.inputFaces) +
                       " faces (input_face, input_b0..2)");
  return d;
}

VtkMesh toVtkMesh(const MeshData& data, const MeshRemeshResult& r) {
  if (r.positions.empty())
    throw InputError(data.source + ": a metric-only input has no positions to draw; VTK output needs positions");
  VtkMesh vtk;
  vtk.title = "conformesh remesh: " + data.source;
  vtk.points = r.positions;
  vtk.triangles = data.faces;
  for (const auto& [name, values] : data.vertexProperties)
    if (name.rfind("input_", 0) != 0) vtk.pointFields[name] = values;
  return vtk;
}

}  // namespace conformesh::refine
