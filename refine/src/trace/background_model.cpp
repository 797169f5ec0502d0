// background_model.cpp — the plane, sphere and hyperboloid models of background_model.h: distances, tangents,
// exponential maps, circumcentres and projective barycentric coordinates.
#include "conformesh/refine/trace/background_model.h"

#include <cmath>

#include <Eigen/Geometry>

namespace conformesh::refine {

using intrinsic::Background;

namespace {

// The chord w = q − p of two model points, with its dominant component recomputed from the other two. A point of the
// sphere or hyperboloid near the origin (0, 0, 1) has z = 1 − O(r²): at r ≲ 10⁻⁸ the stored z carries no information
// beyond x and y, and a plain difference q.z − p.z has absolute error ~u = 2⁻⁵³ where its true value is O(r·|w|).
// Anything that uses the tilt of the chord then fails: the circumcentre of a triangle of size s, the normal of the
// plane through its corners, is off by ~u/s — for s ≈ 10⁻⁸ at the size of the triangle itself (measured on the
// uniformized cow, whose smallest edges are 2·10⁻¹³: a circumcentre landing on a corner, a zero-length edge, NaN
// signposts, and a trace that never ended). The constraint of the model fixes that component instead:
//   sphere      |p|² = |q|² = 1   ⇒  w_i (p_i + q_i) = −Σ_{j≠i} w_j (p_j + q_j),
//   hyperboloid ⟨p,p⟩_M = ⟨q,q⟩_M ⇒  w_z (p_z + q_z) = w_x (p_x + q_x) + w_y (p_y + q_y)   (p_z + q_z ≥ 2),
// so the chord is as accurate, relative to |w|, as the coordinates transverse to the axis i of the largest |p_i + q_i|
// (near the origin: x and y, which keep full relative precision). On the sphere the division is by
// |p_i + q_i| ≥ |p + q|/√3; below 1/2 (points more than ~2.6 rad apart, chords ≥ 1.9) the plain difference is already
// accurate to round-off relative to |w| and is kept, since the points' own norm error u would be amplified there.
Vec3 chord(Background g, const Vec3& p, const Vec3& q) {
  Vec3 w = q - p;
  if (g == Background::Hyperbolic) {
    w.z() = (w.x() * (p.x() + q.x()) + w.y() * (p.y() + q.y())) / (p.z() + q.z());
  } else if (g == Background::Spherical) {
    const Vec3 s = p + q;
    int i = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(s[k]) > std::abs(s[i])) i = k;
    if (std::abs(s[i]) >= 0.5) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      w[i] = -(w[j] * s[j] + w[k] * s[k]) / s[i];
    }
  }
  return w;
}

}  // namespace

double BackgroundModel::inner(const Vec3& a, const Vec3& b) const {
  switch (g_) {
    case Background::Euclidean:
      return a.x() * b.x() + a.y() * b.y();
    case Background::Spherical:
      return a.dot(b);
    case Background::Hyperbolic:
      return a.x() * b.x() + a.y() * b.y() - a.z() * b.z();
  }
  return 0;
}

double BackgroundModel::norm(const Vec3& t) const {
  return std::sqrt(std::max(0.0, inner(t, t)));
}

double BackgroundModel::distance(const Vec3& p, const Vec3& q) const {
  const Vec3 w = chord(g_, p, q);
  switch (g_) {
    case Background::Euclidean:
      return std::hypot(w.x(), w.y());
    case Background::Spherical:
      return 2 * std::asin(std::min(1.0, w.norm() / 2));
    case Background::Hyperbolic:
      // ⟨w,w⟩_M = 4 sinh²(d/2) ≥ 0 for two points of the upper sheet.
      return 2 * std::asinh(norm(w) / 2);
  }
  return 0;
}

Vec3 BackgroundModel::tangentToward(const Vec3& p, const Vec3& q) const {
  Vec3 w = chord(g_, p, q);
  switch (g_) {
    case Background::Euclidean:
      w.z() = 0;
      break;
    case Background::Spherical:
      w += (w.squaredNorm() / 2) * p;
      break;
    case Background::Hyperbolic:
      w -= (inner(w, w) / 2) * p;
      break;
  }
  return w / norm(w);
}

Vec3 BackgroundModel::turnLeft(const Vec3& p, const Vec3& t) const {
  switch (g_) {
    case Background::Euclidean:
      return Vec3(-t.y(), t.x(), 0);
    case Background::Spherical:
      return p.cross(t);
    case Background::Hyperbolic: {
      // The Lorentz cross product J(p × t), J = diag(1, 1, −1): Minkowski-orthogonal to p and t, and equal to e2 for
      // p = e3, t = e1, so it turns left like the other two models; proper Lorentz maps preserve it.
      const Vec3 c = p.cross(t);
      return Vec3(c.x(), c.y(), -c.z());
    }
  }
  return t;
}

Vec3 BackgroundModel::rotate(const Vec3& p, const Vec3& t, double angle) const {
  return std::cos(angle) * t + std::sin(angle) * turnLeft(p, t);
}

Vec3 BackgroundModel::exp(const Vec3& p, const Vec3& t, double r) const {
  switch (g_) {
    case Background::Euclidean:
      return Vec3(p.x() / p.z() + r * t.x(), p.y() / p.z() + r * t.y(), 1.0);
    case Background::Spherical:
      return std::cos(r) * p + std::sin(r) * t;
    case Background::Hyperbolic:
      return std::cosh(r) * p + std::sinh(r) * t;
  }
  return p;
}

Vec3 BackgroundModel::normalize(const Vec3& v) const {
  switch (g_) {
    case Background::Euclidean:
      return v / v.z();
    case Background::Spherical:
      return v / v.norm();
    case Background::Hyperbolic: {
      const double s = std::sqrt(std::max(0.0, -inner(v, v)));
      return (v.z() < 0 ? -v : v) / s;
    }
  }
  return v;
}

Vec3 BackgroundModel::canonicalTangent(const Vec3& p) const {
  const Vec3 e1(1, 0, 0);
  switch (g_) {
    case Background::Euclidean:
      return e1;
    case Background::Spherical: {
      const Vec3 t = e1 - p.x() * p;
      return t / t.norm();
    }
    case Background::Hyperbolic: {
      const Vec3 t = e1 + p.x() * p;  // ⟨e1, p⟩_M = p.x, and the projection onto T_p adds ⟨e1,p⟩ p since ⟨p,p⟩ = −1
      return t / norm(t);
    }
  }
  return e1;
}

double BackgroundModel::angleOf(const Vec3& p, const Vec3& w) const {
  const Vec3 t = canonicalTangent(p);
  return std::atan2(inner(w, turnLeft(p, t)), inner(w, t));
}

Vec3 BackgroundModel::direction(const Vec3& p, double theta) const {
  return rotate(p, canonicalTangent(p), theta);
}

Vec3 BackgroundModel::thirdVertex(const Vec3& P, const Vec3& Q, double angleAtP, double lengthPR) const {
  return exp(P, rotate(P, tangentToward(P, Q), angleAtP), lengthPR);
}

std::optional<Vec3> BackgroundModel::circumcenter(const Vec3& a, const Vec3& b, const Vec3& c) const {
  // Curved models: the normal of the plane through a, b, c is u × v, and its tilt is all in the chords' transverse
  // components — hence the constrained chords (see chord()).
  const Vec3 u = chord(g_, a, b), v = chord(g_, a, c);
  switch (g_) {
    case Background::Euclidean: {
      // Relative to a: the standard formula |u|²(v⊥) − |v|²(u⊥) over 2 u×v.
      const double d = 2 * (u.x() * v.y() - u.y() * v.x());
      if (d == 0) return std::nullopt;
      const double uu = u.x() * u.x() + u.y() * u.y(), vv = v.x() * v.x() + v.y() * v.y();
      return Vec3(a.x() / a.z() + (v.y() * uu - u.y() * vv) / d, a.y() / a.z() + (u.x() * vv - v.x() * uu) / d, 1.0);
    }
    case Background::Spherical: {
      const Vec3 n = u.cross(v);
      const double len = n.norm();
      if (len == 0) return std::nullopt;
      return n / len;
    }
    case Background::Hyperbolic: {
      const Vec3 c0 = u.cross(v);
      const Vec3 n(c0.x(), c0.y(), -c0.z());
      if (!(inner(n, n) < 0)) return std::nullopt;  // spacelike or null: hypercycle or horocycle, no circle
      return normalize(n);
    }
  }
  return std::nullopt;
}

Eigen::Vector3d BackgroundModel::barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) const {
  // Cramer's rule for [a b c]·β = x, up to the common factor det[a b c] that the normalization removes: β_k is the
  // triple product of x with the opposite pair, so its sign is exactly the (floating-point) orientation of x against
  // that side — consistent with the walk's decisions — and no 3×3 factorization is needed.
  const Eigen::Vector3d beta(x.dot(b.cross(c)), x.dot(c.cross(a)), x.dot(a.cross(b)));
  return beta / beta.sum();
}

Vec3 BackgroundModel::fromBarycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Eigen::Vector3d& bary) const {
  return normalize(bary[0] * a + bary[1] * b + bary[2] * c);
}

}  // namespace conformesh::refine
