// surface_projection.cpp — η, π by Gauss–Newton on the reference surface, and the mesh-to-surface deviations
// (see surface_projection.h).
#include "conformesh/embedding/extrinsic/surface_projection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Dense>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

namespace {

std::string sci3(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

std::string point(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return buf;
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // atan2 of |a × b| and a·b keeps full accuracy for small angles (acos of the dot product loses half the digits).
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

ProjectedPoint projectWithScale(const EmbeddedSurface& s, const Eigen::Vector3d& q, const Eigen::Vector3d& start,
                                const ProjectionOptions& o, double lengthScale) {
  ProjectedPoint r;
  Eigen::Vector3d y = s.retract(start);
  double lastStep = 0;
  for (int it = 0; it < o.maxIterations; ++it) {
    Eigen::Vector3d t1, t2;
    s.referenceFrame(y, t1, t2);
    const LocalSurfaceJet j = s.jet(y, t1, t2, false);
    // Gauss–Newton: the tangent-plane least-squares step (JᵀJ) δ = Jᵀ (q − X). Near the foot point the neglected
    // second-order term is (q − X)·X_ij, O(distance·κ) relative, so the iteration contracts by that factor per step
    // — about ε² for the points compared here.
    Eigen::Matrix<double, 3, 2> J;
    J.col(0) = j.xa;
    J.col(1) = j.xb;
    const Eigen::Vector2d delta = (J.transpose() * J).ldlt().solve(J.transpose() * (q - j.position));
    y = s.retract(y + delta.x() * t1 + delta.y() * t2);
    lastStep = (J * delta).norm();
    r.iterations = it + 1;
    if (!std::isfinite(lastStep)) break;
    if (lastStep <= o.stepTolerance * std::max((q - j.position).norm(), lengthScale)) {
      Eigen::Vector3d u1, u2;
      s.referenceFrame(y, u1, u2);
      const LocalSurfaceJet f = s.jet(y, u1, u2, false);
      r.reference = y;
      r.position = f.position;
      r.normal = f.normal;
      r.distance = (q - f.position).norm();
      return r;
    }
  }
  throw ConvergenceError("closest-point projection of " + point(q) + " did not converge in " +
                         std::to_string(r.iterations) + " Gauss–Newton steps (last step " + sci3(lastStep) +
                         "); the start " + point(start) + " is probably outside the projection's basin");
}

}  // namespace

ProjectedPoint closestPointProjection(const EmbeddedSurface& surface, const Eigen::Vector3d& q,
                                      const Eigen::Vector3d& startReference, const ProjectionOptions& options) {
  if (!q.allFinite() || !startReference.allFinite())
    throw InputError("closest-point projection: the point " + point(q) + " or the start " + point(startReference) +
                     " is not finite");
  return projectWithScale(surface, q, startReference, options, 1e-3 * std::max(1.0, q.norm()));
}

Eigen::Vector3d naturalProjection(const EmbeddedSurface& surface, const std::array<Eigen::Vector3d, 3>& corners,
                                  const Eigen::Vector3d& bary) {
  return surface.position(bary.x() * corners[0] + bary.y() * corners[1] + bary.z() * corners[2]);
}

std::string ProjectionOptions::validate() const {
  if (samplesPerEdge < 1) return "surface deviation: samplesPerEdge must be ≥ 1";
  return "";
}

SurfaceDeviation surfaceDeviation(const intrinsic::HalfedgeMesh& mesh, const std::vector<Eigen::Vector3d>& positions,
                                  const std::vector<Eigen::Vector3d>& referencePoints, const EmbeddedSurface& surface,
                                  const ProjectionOptions& options) {
  const int nV = mesh.nVertices();
  if (static_cast<int>(positions.size()) != nV || static_cast<int>(referencePoints.size()) != nV)
    throw InputError("surface deviation: " + std::to_string(positions.size()) + " positions and " +
                     std::to_string(referencePoints.size()) + " reference points for " + std::to_string(nV) +
                     " vertices");
  for (int v = 0; v < nV; ++v)
    if (!positions[v].allFinite() || !referencePoints[v].allFinite())
      throw InputError("surface deviation: vertex " + std::to_string(v) + " has a non-finite position or reference");
  const std::string problem = options.validate();
  if (!problem.empty()) throw InputError(problem);

  Eigen::Vector3d lo = positions[0], hi = positions[0];
  for (const auto& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double scale = 1e-3 * std::max((hi - lo).norm(), 1e-300);

  // Global orientation: the mesh's faces may be oriented either way relative to the reference frame; the majority
  // (by area) decides, so that a minority of flipped triangles shows up as normal deviations near π.
  const int nF = mesh.nFaces();
  std::vector<Eigen::Vector3d> faceNormal(nF);
  double orientation = 0;
  for (int f = 0; f < nF; ++f) {
    const auto& a = positions[mesh.faceVertex(f, 0)];
    const auto& b = positions[mesh.faceVertex(f, 1)];
    const auto& c = positions[mesh.faceVertex(f, 2)];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    faceNormal[f] = n.normalized();
    const Eigen::Vector3d y = (referencePoints[mesh.faceVertex(f, 0)] + referencePoints[mesh.faceVertex(f, 1)] +
                               referencePoints[mesh.faceVertex(f, 2)]) /
                              3;
    Eigen::Vector3d t1, t2;
    surface.referenceFrame(y, t1, t2);
    orientation += n.dot(surface.jet(y, t1, t2, false).normal);
  }
  const double sign = orientation >= 0 ? 1.0 : -1.0;

  SurfaceDeviation d;
  double sumDist = 0, sumAngle = 0;
  const int n = options.samplesPerEdge;
  for (int f = 0; f < nF; ++f) {
    std::array<Eigen::Vector3d, 3> ref, pos;
    for (int k = 0; k < 3; ++k) {
      ref[k] = referencePoints[mesh.faceVertex(f, k)];
      pos[k] = positions[mesh.faceVertex(f, k)];
    }
    bool flipped = false;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Eigen::Vector3d b(double(n - i - j) / n, double(i) / n, double(j) / n);
        const Eigen::Vector3d q = b.x() * pos[0] + b.y() * pos[1] + b.z() * pos[2];
        const Eigen::Vector3d yEta = b.x() * ref[0] + b.y() * ref[1] + b.z() * ref[2];
        Eigen::Vector3d t1, t2;
        surface.referenceFrame(yEta, t1, t2);
        const LocalSurfaceJet eta = surface.jet(yEta, t1, t2, false);
        const ProjectedPoint pi = projectWithScale(surface, q, yEta, options, scale);
        ++d.samples;
        sumDist += pi.distance;
        if (pi.distance > d.hausdorffClosest) {
          d.hausdorffClosest = pi.distance;
          d.worstFace = f;
        }
        d.hausdorffNatural = std::max(d.hausdorffNatural, (q - eta.position).norm());
        const double angle = angleBetween(faceNormal[f], sign * pi.normal);
        sumAngle += angle;
        d.normalDeviation = std::max(d.normalDeviation, angle);
        d.normalDeviationNatural = std::max(d.normalDeviationNatural, angleBetween(faceNormal[f], sign * eta.normal));
        if (angle > M_PI / 2) flipped = true;
      }
    if (flipped) ++d.flippedFaces;
  }
  d.meanClosest = sumDist / d.samples;
  d.meanNormalDeviation = sumAngle / d.samples;
  return d;
}

}  // namespace conformesh::embedding
