// reference_surface.cpp — seams, interpolation and orientation on a chart's reference surface (reference_surface.h).
#include "conformesh/intrinsic/metric/reference_surface.h"

#include <cmath>

#include <Eigen/Geometry>

namespace conformesh::intrinsic {

namespace {
bool isPolar(const ChartDomain& d) {
  const ChartShape s = d.shape();
  return s == ChartShape::Sphere || s == ChartShape::Disk;
}
}  // namespace

Eigen::Vector3d unwrapNear(const ChartDomain& d, const Eigen::Vector3d& ref, Eigen::Vector3d x) {
  if (isPolar(d)) return x;
  auto shift = [](double& a, double r, double period) { a -= period * std::round((a - r) / period); };
  if (d.periodicU) shift(x.x(), ref.x(), d.u1 - d.u0);
  if (d.periodicV) shift(x.y(), ref.y(), d.v1 - d.v0);
  return x;
}

Eigen::Vector2d chartCoordinates(const ChartDomain& d, const Eigen::Vector3d& x) {
  Eigen::Vector2d uv = chartPoint(d, x, Eigen::Vector3d::Zero());
  auto wrap = [](double& a, double lo, double hi) { a -= (hi - lo) * std::floor((a - lo) / (hi - lo)); };
  if (!isPolar(d)) {
    if (d.periodicU) wrap(uv.x(), d.u0, d.u1);
    if (d.periodicV) wrap(uv.y(), d.v0, d.v1);
  }
  return uv;
}

Eigen::Vector3d interpolateOnReference(const ChartDomain& d, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                                       const Eigen::Vector3d& x2, const Eigen::Vector3d& bary) {
  Eigen::Vector3d x = bary[0] * x0 + bary[1] * unwrapNear(d, x0, x1) + bary[2] * unwrapNear(d, x0, x2);
  if (d.shape() == ChartShape::Sphere) x.normalize();
  return x;
}

double referenceOrientation(const ChartDomain& d, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                            const Eigen::Vector3d& x2) {
  if (d.shape() == ChartShape::Sphere) return x0.dot(x1.cross(x2));
  const Eigen::Vector3d a = unwrapNear(d, x0, x1) - x0, b = unwrapNear(d, x0, x2) - x0;
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace conformesh::intrinsic
