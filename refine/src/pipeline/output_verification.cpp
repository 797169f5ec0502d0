// output_verification.cpp — the checks of output_verification.h.
#include "conformesh/refine/pipeline/output_verification.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/planar_layout.h"
#include "conformesh/intrinsic/mesh/triangle_geometry.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;

namespace {

std::string describeFace(const HalfedgeMesh& m, int f) {
  return "face " + std::to_string(f) + " (vertices " + std::to_string(m.faceVertex(f, 0)) + ", " +
         std::to_string(m.faceVertex(f, 1)) + ", " + std::to_string(m.faceVertex(f, 2)) + ")";
}

// Every face's lengths against the strict triangle inequality of the background; the first bad face is named.
void checkTriangles(const IntrinsicTriangulation& t, OutputVerification& v) {
  const HalfedgeMesh& m = t.mesh;
  int bad = 0, first = -1;
  for (int f = 0; f < m.nFaces(); ++f) {
    const double a = t.length(3 * f), b = t.length(3 * f + 1), c = t.length(3 * f + 2);
    const bool ok = std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && a > 0 && b > 0 && c > 0 &&
                    isValidTriangle(t.background, a, b, c);
    if (!ok && bad++ == 0) first = f;
  }
  v.facesChecked = m.nFaces();
  if (bad == 0) return;
  std::ostringstream s;
  s.precision(17);
  s << bad << " output faces violate the " << toString(t.background) << " triangle inequality, first "
    << describeFace(m, first) << " with lengths " << t.length(3 * first) << ", " << t.length(3 * first + 1) << ", "
    << t.length(3 * first + 2);
  v.failures.push_back(s.str());
}

void checkArea(double output, double input, double tolerance, OutputVerification& v) {
  v.areaRelativeError = (output - input) / input;
  if (std::abs(v.areaRelativeError) <= tolerance) return;
  std::ostringstream s;
  s.precision(12);
  s << "output area " << output << " differs from the input's " << input << " by " << v.areaRelativeError
    << " relative (tolerance " << tolerance << ": the output retriangulates the input)";
  v.failures.push_back(s.str());
}

}  // namespace

std::string OutputVerification::message() const {
  std::string s = "output failed verification: ";
  for (std::size_t i = 0; i < failures.size(); ++i) s += (i ? "; " : "") + failures[i];
  return s;
}

OutputVerification verifyMeshRemesh(const MeshRemeshResult& r, const IntrinsicTriangulation& input,
                                    const VerificationTolerances& tol) {
  OutputVerification v;
  checkTriangles(r.mesh, v);
  if (r.invertedTriangles > 0) {
    const auto [f, face] = r.firstInvertedTriangle;
    v.failures.push_back(std::to_string(r.invertedTriangles) + " of " + std::to_string(r.orientationChecked) +
                         " checked output triangles are inverted on the input, first " +
                         (f >= 0 ? describeFace(r.mesh.mesh, f) + " in input-side face " + std::to_string(face)
                                 : std::string("(not recorded)")));
  }
  if (!(r.maxSameFaceScaledError <= tol.sameFaceLength)) {
    const auto [e, face] = r.worstSameFaceEdge;
    std::ostringstream s;
    s.precision(3);
    s << "output edge " << e << " differs from the straight distance of its located ends in face " << face << " by "
      << r.maxSameFaceScaledError << " relative to max(edge, the face's longest side) (tolerance " << tol.sameFaceLength
      << ")";
    v.failures.push_back(s.str());
  }
  checkArea(totalArea(r.mesh), totalArea(input), tol.area, v);
  return v;
}

OutputVerification verifyMetricRemesh(const RemeshResult& r, const VerificationTolerances&) {
  OutputVerification v;
  checkTriangles(r.mesh, v);
  if (r.invertedTriangles > 0)
    v.failures.push_back(std::to_string(r.invertedTriangles) +
                         " output triangles are inverted in the map back to the chart's reference surface");
  return v;
}

OutputVerification verifyRefinement(const IntrinsicTriangulation& input, const RefineResult& r,
                                    const VerificationTolerances& tol) {
  OutputVerification v;
  checkTriangles(r.triangulation, v);
  const int nf = input.mesh.nFaces();
  for (std::size_t i = 0; i < r.locations.size(); ++i) {
    const InputLocation& l = r.locations[i];
    if (l.face >= 0 && l.face < nf && l.bary.allFinite()) continue;
    v.failures.push_back("output vertex " + std::to_string(i) + " is not located on a face of the input (face " +
                         std::to_string(l.face) + " of " + std::to_string(nf) + ")");
    break;
  }
  // Boundary loops split on their circle grow the domain from the chords towards the circle: no equality there.
  if (r.statistics.circleLoops == 0) checkArea(totalArea(r.triangulation), totalArea(input), tol.area, v);
  return v;
}

namespace {

// A half of the double with geodesic boundary (hyperbolic, flat cylinder; docs/ricci_flow.md §3.4): the angle sums
// recomputed from the written lengths, 2π inside and π on the boundary, within the flow's tolerance.
void checkGeodesicBoundary(const Uniformization& u, OutputVerification& v) {
  int at = -1;
  const double worst = maxGeodesicBoundaryResidual(u.uniform, &at);
  if (worst <= u.report.effectiveTolerance) return;
  std::ostringstream s;
  s.precision(3);
  s << "the half of the double's angle sums are off by " << worst << " rad at vertex " << at << " (2pi inside, pi on "
    << "the geodesic boundary; tolerance " << u.report.effectiveTolerance << ")";
  v.failures.push_back(s.str());
}

// The circle domain's loops against their circles (uniformization.h: the longest loop the unit circle centred at 0,
// the others circles), each to 1e-8 of its radius — the accuracy uniformize guarantees; "" when they are.
std::string circleDomainLoopsOff(const Uniformization& u) {
  constexpr double kCircle = 1e-8;
  const HalfedgeMesh& m = u.uniform.mesh;
  std::vector<Eigen::Vector2d> z(u.positions.size());
  for (std::size_t v = 0; v < z.size(); ++v) z[v] = u.positions[v].head<2>();
  LoopCircle outer;
  std::ostringstream s;
  s.precision(3);
  int index = 0;
  for (const std::vector<int>& halfedges : m.boundaryLoops()) {
    std::vector<int> loop;
    for (int h : halfedges) loop.push_back(m.tail(h));
    const LoopCircle fit = fitLoopCircle(z, loop);
    if (!(fit.deviation <= kCircle)) {
      s << "the circle domain's boundary loop " << index << " is off its circle by " << fit.deviation
        << " of its radius (tolerance 1e-08)";
      return s.str();
    }
    if (fit.radius > outer.radius) outer = fit;
    ++index;
  }
  if (!(std::abs(outer.radius - 1) <= kCircle && outer.centre.norm() <= kCircle))
    s << "the circle domain's outer loop is the circle of radius " << outer.radius << " about (" << outer.centre.x()
      << ", " << outer.centre.y() << "), not the unit circle (tolerance 1e-08)";
  return s.str();
}

// Inserted boundary vertices (uniformization.h, insertedVertices: the half of the double, or boundary edges split):
// appended and on the boundary; a circle domain's loops on their circles, the outer the unit circle; the residual
// within the tolerance.
void checkInsertedVertices(const Uniformization& u, OutputVerification& v) {
  const HalfedgeMesh& m = u.uniform.mesh;
  const int inserted = static_cast<int>(u.insertedVertices.size()), first = m.nVertices() - inserted;
  for (int i = 0; i < inserted; ++i) {
    const int q = u.insertedVertices[i].vertex;
    if (q == first + i && m.isBoundaryVertex(q)) continue;
    v.failures.push_back("inserted vertex " + std::to_string(i) + " is vertex " + std::to_string(q) + ", expected " +
                         std::to_string(first + i) + " on the boundary");
    return;
  }
  if (u.report.target != UniformizationTarget::CircleDomain) {
    checkGeodesicBoundary(u, v);
    return;
  }
  std::ostringstream s;
  s.precision(3);
  if (u.positions.size() != static_cast<std::size_t>(m.nVertices()))
    s << "the circle domain has " << u.positions.size() << " positions for " << m.nVertices() << " vertices";
  else if (const std::string off = circleDomainLoopsOff(u); !off.empty())
    s << off;
  else if (!(u.report.maxResidual <= u.report.effectiveTolerance))
    s << "the circle domain's max |K - K^| " << u.report.maxResidual << " exceeds the tolerance "
      << u.report.effectiveTolerance;
  if (!s.str().empty()) v.failures.push_back(s.str());
}

}  // namespace

OutputVerification verifyUniformization(const Uniformization& u) {
  OutputVerification v;
  checkTriangles(u.uniform, v);
  if (!u.insertedVertices.empty()) checkInsertedVertices(u, v);
  for (std::size_t i = 0; i < u.lambda.size(); ++i)
    if (!std::isfinite(u.lambda[i])) {
      v.failures.push_back("lambda of vertex " + std::to_string(i) + " is not finite");
      break;
    }
  return v;
}

std::string failedOutputName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/'), dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + ".failed";
  return path.substr(0, dot) + ".failed" + path.substr(dot);
}

}  // namespace conformesh::refine
