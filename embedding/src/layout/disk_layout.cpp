// disk_layout.cpp — Möbius normalization of a circle-domain layout and the circle fit of its boundary loops. See
// disk_layout.h and docs/layout.md §6.
#include "conformesh/embedding/layout/disk_layout.h"

#include <cmath>
#include <complex>

#include <Eigen/Dense>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

DiskLayout layoutDisk(const intrinsic::Uniformization& u, const DiskLayoutOptions& options) {
  if (u.report.target != intrinsic::UniformizationTarget::CircleDomain)
    throw InputError("layoutDisk: expected a circle-domain uniformization (genus 0 with boundary), found target " +
                     intrinsic::toString(u.report.target));
  const intrinsic::HalfedgeMesh& m = u.uniform.mesh;
  const int n = m.nVertices();
  for (int v : {options.centreVertex, options.directionVertex})
    if (v < -1 || v >= n)
      throw InputError("layoutDisk: vertex " + std::to_string(v) + " out of range [0, " + std::to_string(n) + ")");
  if (options.centreVertex >= 0 && m.isBoundaryVertex(options.centreVertex))
    throw InputError("layoutDisk: centre vertex " + std::to_string(options.centreVertex) +
                     " is on the boundary; expected an interior vertex");
  using C = std::complex<double>;
  std::vector<C> z(n);
  for (int v = 0; v < n; ++v) z[v] = C(u.positions[v].x(), u.positions[v].y());
  if (options.centreVertex >= 0) {
    const C a = z[options.centreVertex];
    for (C& p : z) p = (p - a) / (1.0 - std::conj(a) * p);
  }
  if (options.directionVertex >= 0) {
    const C r = std::polar(1.0, -std::arg(z[options.directionVertex]));
    for (C& p : z) p *= r;
  }
  DiskLayout d;
  for (const C& p : z) d.points.emplace_back(p.real(), p.imag());
  // Circle fit (Kåsa): minimize Σ (|p|² − 2c·p − k)², linear in (c, k), ρ² = k + |c|².
  for (const auto& loop : m.boundaryLoops()) {
    Eigen::MatrixXd A(loop.size(), 3);
    Eigen::VectorXd b(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d& p = d.points[m.tail(loop[i])];
      A.row(i) << 2 * p.x(), 2 * p.y(), 1;
      b(i) = p.squaredNorm();
    }
    const Eigen::Vector3d sol = A.colPivHouseholderQr().solve(b);
    DiskLayout::Circle c;
    c.centre = sol.head<2>();
    c.radius = std::sqrt(sol(2) + c.centre.squaredNorm());
    for (int h : loop)
      c.deviation = std::max(c.deviation, std::abs((d.points[m.tail(h)] - c.centre).norm() - c.radius) / c.radius);
    d.circles.push_back(c);
  }
  d.minSignedArea = std::numeric_limits<double>::infinity();
  for (int f = 0; f < m.nFaces(); ++f) {
    const Eigen::Vector2d a = d.points[m.faceVertex(f, 1)] - d.points[m.faceVertex(f, 0)];
    const Eigen::Vector2d b = d.points[m.faceVertex(f, 2)] - d.points[m.faceVertex(f, 0)];
    d.minSignedArea = std::min(d.minSignedArea, 0.5 * (a.x() * b.y() - a.y() * b.x()));
  }
  return d;
}

}  // namespace conformesh::embedding
