// background_model.h — points and tangent vectors of the three constant-curvature backgrounds as vectors of R³, in the
// models where geodesics are straight: the plane as (x, y, 1), the unit sphere (gnomonic chart x/z, y/z) and the upper
// sheet of the hyperboloid x² + y² − z² = −1 (Beltrami–Klein chart x/z, y/z). Orientation is the sign of det[a b c] in
// all three (robust_predicates.h), and barycentric coordinates in these vectors do not depend on where a triangle was
// laid out (docs/refinement.md §2). A value type: no state beyond the background.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/triangle_geometry.h"

namespace conformesh::refine {

using Vec3 = Eigen::Vector3d;

class BackgroundModel {
 public:
  explicit BackgroundModel(intrinsic::Background g) : g_(g) {}
  intrinsic::Background background() const { return g_; }

  // The point (0, 0, 1): the origin of the plane, the north pole, the bottom of the hyperboloid. Its canonical frame is
  // (e1, e2).
  static Vec3 origin() { return Vec3(0, 0, 1); }

  // Inner product of tangent vectors: Euclidean dot of (x, y) for the plane, R³ dot for the sphere, Minkowski
  // x1x2 + y1y2 − z1z2 for the hyperboloid.
  double inner(const Vec3& a, const Vec3& b) const;
  double norm(const Vec3& t) const;

  // Geodesic distance, from the chord w = q − p by 2 asin(|w|/2) (sphere) and 2 asinh(|w|_M / 2) (hyperboloid), which
  // keep full relative accuracy for close points where acos / acosh of an inner product would lose half the digits.
  double distance(const Vec3& p, const Vec3& q) const;

  // Unit tangent vector at p pointing along the geodesic to q (q ≠ p). Written with the chord w = q − p as
  // w + (|w|²/2) p (sphere) and w − (|w|²_M/2) p (hyperboloid), exact projections onto T_p that do not cancel for
  // close points.
  Vec3 tangentToward(const Vec3& p, const Vec3& q) const;

  // The unit tangent at p obtained by turning t by +90° (counter-clockwise, the orientation of det > 0).
  Vec3 turnLeft(const Vec3& p, const Vec3& t) const;
  // t turned counter-clockwise by `angle` at p.
  Vec3 rotate(const Vec3& p, const Vec3& t, double angle) const;

  // The point at distance r from p along the unit tangent t (exponential map).
  Vec3 exp(const Vec3& p, const Vec3& t, double r) const;

  // The point at distance r from origin() in direction theta (polar coordinates around the origin).
  Vec3 polar(double r, double theta) const { return exp(origin(), Vec3(std::cos(theta), std::sin(theta), 0), r); }

  // Rescales a homogeneous vector onto the model (z = 1, |v| = 1, ⟨v,v⟩_M = −1 with z > 0).
  Vec3 normalize(const Vec3& v) const;

  // The canonical frame at p: e1 projected onto T_p and normalised, and its left turn. This frame depends only on the
  // layout's coordinates, so "angle θ at p in the canonical frame of a layout" is a well-defined tangent direction.
  Vec3 canonicalTangent(const Vec3& p) const;
  // Angle of tangent w at p in the canonical frame, in (−π, π].
  double angleOf(const Vec3& p, const Vec3& w) const;
  // Unit tangent at p at angle theta in the canonical frame.
  Vec3 direction(const Vec3& p, double theta) const;

  // Third vertex R of the counter-clockwise triangle (P, Q, R) with angle `angleAtP` at P and |PR| = lengthPR.
  Vec3 thirdVertex(const Vec3& P, const Vec3& Q, double angleAtP, double lengthPR) const;

  // Circumcentre of the counter-clockwise triangle (a, b, c). Sphere: the unit normal of the plane through a, b, c on
  // their side; hyperboloid: the Minkowski normal, which exists (is timelike) only when the three points lie on a
  // circle — on a horocycle or hypercycle there is no circumcentre and nullopt is returned.
  std::optional<Vec3> circumcenter(const Vec3& a, const Vec3& b, const Vec3& c) const;

  // Projective barycentric coordinates of x with respect to (a, b, c): x ∝ β0 a + β1 b + β2 c with Σβ = 1. Negative
  // coordinates mean x lies outside the triangle.
  Eigen::Vector3d barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) const;
  // The point with projective barycentric coordinates `bary` (the inverse of the above).
  Vec3 fromBarycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Eigen::Vector3d& bary) const;

 private:
  intrinsic::Background g_;
};

}  // namespace conformesh::refine
