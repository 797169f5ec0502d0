// intrinsic_triangulation.cpp — per-element and whole-mesh geometry of an IntrinsicTriangulation from its edge lengths.
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

void validateLengths(const IntrinsicTriangulation& tri, const std::string& source) {
  const HalfedgeMesh& m = tri.mesh;
  if (static_cast<int>(tri.edgeLengths.size()) != m.nEdges())
    throw InputError(describeAt(source, "expected " + std::to_string(m.nEdges()) + " edge lengths, found " +
                                            std::to_string(tri.edgeLengths.size())));
  for (int e = 0; e < m.nEdges(); ++e) {
    const double l = tri.edgeLengths[e];
    if (!std::isfinite(l) || !(l > 0)) {
      const int h = m.edgeHalfedge(e);
      std::ostringstream msg;
      msg.precision(17);
      msg << "edge " << e << " (" << m.tail(h) << ", " << m.tip(h) << ") has length " << l
          << "; lengths must be finite and positive";
      throw InputError(describeAt(source, msg.str()));
    }
  }
  for (int f = 0; f < m.nFaces(); ++f) {
    const double a = tri.length(3 * f), b = tri.length(3 * f + 1), c = tri.length(3 * f + 2);
    if (!isValidTriangle(tri.background, a, b, c)) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "face " << f << " (" << m.faceVertex(f, 0) << ", " << m.faceVertex(f, 1) << ", " << m.faceVertex(f, 2)
          << ") violates the " << toString(tri.background) << " triangle inequality with lengths " << a << ", " << b
          << ", " << c;
      if (tri.background == Background::Spherical) msg << " (a spherical triangle also needs perimeter < 2π)";
      throw InputError(describeAt(source, msg.str()));
    }
  }
}

double cornerAngle(const IntrinsicTriangulation& tri, int h) {
  return angleOpposite(tri.background, tri.length(HalfedgeMesh::next(h)), tri.length(h),
                       tri.length(HalfedgeMesh::prev(h)));
}

double faceArea(const IntrinsicTriangulation& tri, int f) {
  return triangleArea(tri.background, tri.length(3 * f), tri.length(3 * f + 1), tri.length(3 * f + 2));
}

double faceCircumradius(const IntrinsicTriangulation& tri, int f) {
  return circumradius(tri.background, tri.length(3 * f), tri.length(3 * f + 1), tri.length(3 * f + 2));
}

double cotanOpposite(const IntrinsicTriangulation& tri, int h) {
  return cotOpposite(tri.background, tri.length(h), tri.length(HalfedgeMesh::next(h)),
                     tri.length(HalfedgeMesh::prev(h)));
}

double cotanWeight(const IntrinsicTriangulation& tri, int e) {
  const int h = tri.mesh.edgeHalfedge(e), t = tri.mesh.twin(h);
  double w = cotanOpposite(tri, h);
  if (t != kInvalid) w += cotanOpposite(tri, t);
  return 0.5 * w;
}

std::vector<double> allCornerAngles(const IntrinsicTriangulation& tri) {
  const int nF = tri.mesh.nFaces();
  std::vector<double> angles(3 * static_cast<size_t>(nF));
  for (int f = 0; f < nF; ++f) {
    const double l0 = tri.length(3 * f), l1 = tri.length(3 * f + 1), l2 = tri.length(3 * f + 2);
    // Corner k sits between halfedges k and k−1; its opposite side is halfedge k+1.
    angles[3 * f + 0] = angleOpposite(tri.background, l1, l0, l2);
    angles[3 * f + 1] = angleOpposite(tri.background, l2, l1, l0);
    angles[3 * f + 2] = angleOpposite(tri.background, l0, l2, l1);
  }
  return angles;
}

double totalArea(const IntrinsicTriangulation& tri) {
  // Neumaier summation: a million small areas would otherwise lose ~6 digits.
  double sum = 0, comp = 0;
  for (int f = 0; f < tri.mesh.nFaces(); ++f) {
    const double x = faceArea(tri, f), t = sum + x;
    comp += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  }
  return sum + comp;
}

double delaunayMargin(const IntrinsicTriangulation& tri, int e) {
  const int ha = tri.mesh.edgeHalfedge(e), hb = tri.mesh.twin(ha);
  if (hb == kInvalid) return std::numeric_limits<double>::infinity();
  // In face (a, b, c) of ha: angle at c is opposite e; the angles at a and b are adjacent to it. Same in face (b, a, d).
  const double alpha = cornerAngle(tri, HalfedgeMesh::prev(ha)), beta = cornerAngle(tri, HalfedgeMesh::prev(hb));
  if (tri.background == Background::Euclidean) return M_PI - alpha - beta;  // the four others sum to 2π − α − β
  const double rho = cornerAngle(tri, ha) + cornerAngle(tri, HalfedgeMesh::next(ha)) + cornerAngle(tri, hb) +
                     cornerAngle(tri, HalfedgeMesh::next(hb));
  return 0.5 * (rho - alpha - beta);
}

}  // namespace conformesh::intrinsic
