// embedded_surface.cpp — position, frame, normal and κ₁ + κ₂ of a metric's embedding by central differences on the
// reference surface (see embedded_surface.h for the steps and their errors).
#include "conformesh/embedding/extrinsic/embedded_surface.h"

#include <algorithm>
#include <cmath>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

using intrinsic::ChartShape;

EmbeddedSurface::EmbeddedSurface(const intrinsic::SmoothMetric& metric) : metric_(metric), domain_(metric.domain()) {
  if (!metric.hasEmbedding())
    throw InputError("metric '" + metric.family() + "' (" + metric.description() +
                     ") has no embedding in R³ of its own: extrinsic checks (mean curvature, projections) need one");
  sphere_ = domain_.shape() == ChartShape::Sphere;
  width_ = sphere_ ? 1.0 : std::min(domain_.u1 - domain_.u0, domain_.v1 - domain_.v0) / M_PI;
}

Eigen::Vector3d EmbeddedSurface::position(const Eigen::Vector3d& y) const {
  const Eigen::Vector2d uv = intrinsic::chartPoint(domain_, y);
  return metric_.position(uv.x(), uv.y());
}

Eigen::Vector3d EmbeddedSurface::retract(const Eigen::Vector3d& y) const {
  if (sphere_) return y.normalized();
  return {y.x(), y.y(), 0.0};
}

void EmbeddedSurface::referenceFrame(const Eigen::Vector3d& y, Eigen::Vector3d& t1, Eigen::Vector3d& t2) const {
  if (!sphere_) {
    t1 = Eigen::Vector3d::UnitX();
    t2 = Eigen::Vector3d::UnitY();
    return;
  }
  const Eigen::Vector3d n = y.normalized();
  // Any unit vector ⊥ n; start from the coordinate axis least aligned with n so that the cross product is well scaled.
  Eigen::Index k;
  n.cwiseAbs().minCoeff(&k);
  t1 = n.cross(Eigen::Vector3d::Unit(k)).normalized();
  t2 = n.cross(t1);
}

LocalSurfaceJet EmbeddedSurface::jet(const Eigen::Vector3d& y, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                                     bool curvature) const {
  const double h = (curvature ? 2e-4 : 1e-5) * width_;
  const double ha = h / e1.norm(), hb = h / e2.norm();
  const Eigen::Vector3d da = ha * e1, db = hb * e2;
  LocalSurfaceJet j;
  const Eigen::Vector3d pa = position(y + da), ma = position(y - da), pb = position(y + db), mb = position(y - db);
  j.xa = (pa - ma) / (2 * ha);
  j.xb = (pb - mb) / (2 * hb);
  const Eigen::Vector3d c = j.xa.cross(j.xb);
  j.areaFactor = c.norm();
  j.normal = c / j.areaFactor;
  if (!curvature) {
    j.position = position(y);
    return j;
  }
  j.position = position(y);
  const Eigen::Vector3d xaa = (pa - 2 * j.position + ma) / (ha * ha);
  const Eigen::Vector3d xbb = (pb - 2 * j.position + mb) / (hb * hb);
  const Eigen::Vector3d xab =
      (position(y + da + db) - position(y + da - db) - position(y - da + db) + position(y - da - db)) / (4 * ha * hb);
  const double E = j.xa.squaredNorm(), F = j.xa.dot(j.xb), G = j.xb.squaredNorm();
  const double L = j.normal.dot(xaa), M = j.normal.dot(xab), N = j.normal.dot(xbb);
  j.meanCurvature = -(E * N - 2 * F * M + G * L) / (E * G - F * F);
  return j;
}

}  // namespace conformesh::embedding
