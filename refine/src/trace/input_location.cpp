// input_location.cpp — locating points on the input triangulation by geodesic tracing (input_location.h).
#include "conformesh/refine/trace/input_location.h"

#include <Eigen/LU>

#include "conformesh/refine/trace/geodesic_trace.h"

namespace conformesh::refine {

using intrinsic::HalfedgeMesh;

InputSurface::InputSurface(const intrinsic::IntrinsicTriangulation& input)
    : tri_(input), sp_(initialSignposts(input)), model_(input.background) {}

InputLocation InputSurface::vertexLocation(int v) const {
  const int h = tri_.mesh.vertexHalfedge(v);
  InputLocation loc;
  loc.face = HalfedgeMesh::face(h);
  loc.bary = Eigen::Vector3d::Zero();
  loc.bary[h % 3] = 1.0;
  return loc;
}

InputSurface::Arrival InputSurface::follow(int vertex, bool isInputVertex, const InputLocation& from, double theta,
                                           double length) const {
  TraceResult r;
  if (isInputVertex) {
    r = traceFromVertex(tri_, sp_, model_, vertex, theta, length);
  } else {
    const std::array<Vec3, 3> C = layoutFace(tri_, model_, from.face);
    const Vec3 s = model_.fromBarycentric(C[0], C[1], C[2], from.bary);
    const Vec3 t = model_.exp(s, model_.direction(s, theta), length);
    r = traceFromPoint(tri_, model_, from.face, C, s, t);
  }
  // Carry the arrival direction into the canonical layout of the end face: isometries of every model are linear, so the
  // map is M = [canonical corners]·[trace corners]⁻¹.
  const std::array<Vec3, 3> C = layoutFace(tri_, model_, r.face);
  Eigen::Matrix3d A, B;
  A << C[0], C[1], C[2];
  B << r.corners[0], r.corners[1], r.corners[2];
  const Eigen::Matrix3d M = A * B.inverse();
  const Vec3 endC = model_.fromBarycentric(C[0], C[1], C[2], r.bary);
  Vec3 arrival = M * r.arrivalTangent(model_);
  if (model_.background() == intrinsic::Background::Euclidean) arrival.z() = 0;
  Arrival a;
  a.location.face = r.face;
  a.location.bary = r.bary;
  a.angle = model_.angleOf(endC, arrival);
  a.leftSurface = !r.reachedTarget();
  return a;
}

double InputSurface::interpolate(const std::vector<double>& values, const InputLocation& at) const {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += at.bary[k] * values[tri_.mesh.faceVertex(at.face, k)];
  return s;
}

std::vector<Eigen::Vector3d> interpolatePositions(const intrinsic::HalfedgeMesh& input,
                                                  const std::vector<Eigen::Vector3d>& positions,
                                                  const std::vector<InputLocation>& locations) {
  std::vector<Eigen::Vector3d> out;
  if (positions.empty()) return out;
  out.reserve(locations.size());
  for (const InputLocation& p : locations) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) x += p.bary[k] * positions[input.faceVertex(p.face, k)];
    out.push_back(x);
  }
  return out;
}

}  // namespace conformesh::refine
