// refine_test_surfaces.h — constant-curvature triangulations with known geometry for the refinement tests: a flat torus
// of any lattice (with the plane position of every vertex), a sphere with great-circle lengths (with unit-vector
// positions), a hyperbolic genus-2 surface glued from the regular octagon with angles π/4, and a planar unit disk; and
// the checks the refinement tests share (located points against closed-form distances, the signpost invariant).
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"
#include "conformesh/refine/trace/background_model.h"
#include "conformesh/refine/trace/geodesic_trace.h"
#include "conformesh/refine/trace/input_location.h"

namespace conformesh::refine::testing {

using intrinsic::IntrinsicTriangulation;

// === flat torus C/(ω1 Z + ω2 Z) on an n×n grid (the library's generator), with vertex (i, j) at (iω1 + jω2)/n.
struct FlatTorus {
  IntrinsicTriangulation tri;
  std::complex<double> w1, w2;
  int n;
  std::complex<double> position(int v) const { return (double(v / n) * w1 + double(v % n) * w2) / double(n); }
  // The lattice translate of z nearest to `near`.
  std::complex<double> nearest(std::complex<double> z, std::complex<double> near) const {
    // Solve z − near = a ω1 + b ω2, round a, b.
    const std::complex<double> d = z - near;
    const double det = w1.real() * w2.imag() - w1.imag() * w2.real();
    const double a = (d.real() * w2.imag() - d.imag() * w2.real()) / det;
    const double b = (w1.real() * d.imag() - w1.imag() * d.real()) / det;
    std::complex<double> best = z;
    double bestD = INFINITY;
    for (int da = -4; da <= 4; ++da)
      for (int db = -4; db <= 4; ++db) {
        const std::complex<double> c = z - (std::round(a) + da) * w1 - (std::round(b) + db) * w2;
        if (std::abs(c - near) < bestD) bestD = std::abs(c - near), best = c;
      }
    return best;
  }
  // The translate of tip(h)'s position whose offset from `from` has the length of h: input edges can be longer than
  // half the systole (skewed lattices), so "nearest translate" would pick the wrong copy.
  std::complex<double> unfoldTip(int h, std::complex<double> from) const {
    const auto& m = tri.mesh;
    const std::complex<double> z = position(m.tip(h));
    std::complex<double> best = z;
    double bestErr = INFINITY;
    for (int da = -n - 2; da <= n + 2; ++da)
      for (int db = -n - 2; db <= n + 2; ++db) {
        const std::complex<double> c = z + double(da) * w1 + double(db) * w2;
        const double err = std::abs(std::abs(c - from) - tri.length(h));
        if (err < bestErr) bestErr = err, best = c;
      }
    return best;
  }
  // Plane position (up to the lattice) of a point given by input face + barycentric coordinates.
  std::complex<double> locate(const InputLocation& loc) const {
    const auto& m = tri.mesh;
    const std::complex<double> p0 = position(m.faceVertex(loc.face, 0));
    const std::complex<double> p1 = unfoldTip(3 * loc.face, p0);
    const std::complex<double> p2 = unfoldTip(3 * loc.face + 1, p1);
    return loc.bary[0] * p0 + loc.bary[1] * p1 + loc.bary[2] * p2;
  }
  // Distance on the torus between two plane points.
  double torusDistance(std::complex<double> a, std::complex<double> b) const { return std::abs(nearest(b, a) - a); }
  double distance(const InputLocation& a, const InputLocation& b) const { return torusDistance(locate(a), locate(b)); }
};

inline FlatTorus flatTorus(std::complex<double> w1, std::complex<double> w2, int n) {
  intrinsic::FlatTorusOptions o;
  o.omega1 = w1;
  o.omega2 = w2;
  o.n = n;
  o.reduceBasis = false;  // keep the given basis: skewed lattices give long, thin input triangles (tiny angles)
  FlatTorus t{intrinsic::toTriangulation(intrinsic::makeFlatTorus(o)), w1, w2, n};
  return t;
}

// === icosphere with spherical (great-circle) lengths on the unit sphere.
struct SphereSurface {
  IntrinsicTriangulation tri;
  std::vector<Eigen::Vector3d> positions;
  // The point with gnomonic barycentric coordinates `bary` in its face: normalize(Σ β_k x_k), exact on the sphere.
  Eigen::Vector3d locate(const InputLocation& loc) const {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) p += loc.bary[k] * positions[tri.mesh.faceVertex(loc.face, k)];
    return p.normalized();
  }
  // Great-circle distance between two located points.
  double distance(const InputLocation& a, const InputLocation& b) const {
    return 2 * std::asin((locate(a) - locate(b)).norm() / 2);
  }
};

inline SphereSurface sphere(int level) {
  intrinsic::IcosphereOptions o;
  o.level = level;
  const intrinsic::MeshData d = intrinsic::makeIcosphere(o);
  SphereSurface s{intrinsic::toTriangulation(d), {}};
  for (const auto& p : d.positions) s.positions.push_back(p.normalized());
  s.tri.background = intrinsic::Background::Spherical;
  for (int e = 0; e < s.tri.mesh.nEdges(); ++e) {
    const int h = s.tri.mesh.edgeHalfedge(e);
    const Eigen::Vector3d a = s.positions[s.tri.mesh.tail(h)], b = s.positions[s.tri.mesh.tip(h)];
    s.tri.edgeLengths[e] = 2 * std::asin((a - b).norm() / 2);
  }
  return s;
}

// === hyperbolic genus-2 surface: the regular octagon with interior angles π/4, sides glued a1 b1 a1⁻¹ b1⁻¹ a2 b2 a2⁻¹
// b2⁻¹, all corners one vertex. Triangulated by the centre (vertex 0), the corner vertex (1) and the midpoints of the
// four glued side pairs (2..5): 16 right triangles with angles π/8 at the centre and at the corner. Right-triangle
// trigonometry: cosh ρ = cot(π/8) (centre–midpoint = half side), cosh r = cot²(π/8) (centre–corner).
// V = 6, E = 24, F = 16: χ = −2; area 16 · (π − π/2 − π/4) = 4π.
struct OctagonSurface {
  IntrinsicTriangulation tri;
  double inradius, circumradius;
};

inline OctagonSurface genus2Octagon() {
  const double cot = 1 / std::tan(M_PI / 8);
  const double rho = std::acosh(cot), r = std::acosh(cot * cot);
  const int partner[8] = {2, 3, 0, 1, 6, 7, 4, 5};
  const int pairOf[8] = {0, 1, 0, 1, 2, 3, 2, 3};
  std::vector<std::array<int, 3>> faces, ids;
  auto halfA = [&](int i) { return 16 + 2 * pairOf[i] + (i < partner[i] ? 0 : 1); };  // corner_i -> mid_i
  auto halfB = [&](int i) { return 16 + 2 * pairOf[i] + (i < partner[i] ? 1 : 0); };  // mid_i -> corner_{i+1}
  for (int i = 0; i < 8; ++i) {
    const int mid = 2 + pairOf[i];
    faces.push_back({0, 1, mid});
    ids.push_back({i, halfA(i), 8 + i});
    faces.push_back({0, mid, 1});
    ids.push_back({8 + i, halfB(i), (i + 1) % 8});
  }
  OctagonSurface s;
  s.tri.mesh = intrinsic::HalfedgeMesh::fromFaces(faces, 6, "octagon", nullptr, ids);
  s.tri.background = intrinsic::Background::Hyperbolic;
  s.tri.edgeLengths.assign(24, 0);
  for (int e = 0; e < 8; ++e) s.tri.edgeLengths[e] = r;
  for (int e = 8; e < 16; ++e) s.tri.edgeLengths[e] = rho;
  for (int e = 16; e < 24; ++e) s.tri.edgeLengths[e] = rho;  // half sides: cosh(s/2) = cot(π/8) as well
  s.inradius = rho;
  s.circumradius = r;
  return s;
}

// === planar disk: the library's ring disk (boundary: regular 6N-gon inscribed in the unit circle).
struct DiskSurface {
  IntrinsicTriangulation tri;
  std::vector<Eigen::Vector2d> positions;
  Eigen::Vector2d locate(const InputLocation& loc) const {
    Eigen::Vector2d p = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) p += loc.bary[k] * positions[tri.mesh.faceVertex(loc.face, k)];
    return p;
  }
  double distance(const InputLocation& a, const InputLocation& b) const { return (locate(a) - locate(b)).norm(); }
};

inline DiskSurface disk(int rings) {
  intrinsic::DiskOptions o;
  o.rings = rings;
  const intrinsic::MeshData d = intrinsic::makeDisk(o);
  DiskSurface s{intrinsic::toTriangulation(d), {}};
  for (const auto& p : d.positions) s.positions.emplace_back(p.x(), p.y());
  return s;
}

// === a planar point set's Delaunay triangulation, by brute force (the empty-circumcircle test over all triples; for
// the handful of points of a test domain). `points` must be in general position except for the convex hull's vertices;
// the hull is the domain's boundary, so collinear hull points must not occur either.
inline DiskSurface planarDelaunay(const std::vector<Eigen::Vector2d>& points) {
  intrinsic::MeshData d;
  const int n = static_cast<int>(points.size());
  d.nVertices = n;
  for (const auto& p : points) d.positions.emplace_back(p.x(), p.y(), 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const Eigen::Vector2d a = points[i], u = points[j] - a, v = points[k] - a;
        const double cross = u.x() * v.y() - u.y() * v.x();
        if (std::abs(cross) < 1e-14) continue;
        const Eigen::Vector2d c = a + Eigen::Vector2d(v.y() * u.squaredNorm() - u.y() * v.squaredNorm(),
                                                      u.x() * v.squaredNorm() - v.x() * u.squaredNorm()) /
                                          (2 * cross);
        const double R = (a - c).norm();
        bool empty = true;
        for (int m = 0; m < n && empty; ++m)
          if (m != i && m != j && m != k && (points[m] - c).norm() < R * (1 - 1e-12)) empty = false;
        if (!empty) continue;
        if (cross > 0)
          d.faces.push_back({i, j, k});
        else
          d.faces.push_back({i, k, j});
      }
  return {intrinsic::toTriangulation(d), points};
}

// === planar annulus 0.5 < |z| < 1 (the library's log-polar grid): a circle domain with one hole.
inline DiskSurface annulus(int rings) {
  intrinsic::AnnulusOptions o;
  o.innerRadius = 0.5;
  o.outerRadius = 1.0;
  o.rings = rings;
  const intrinsic::MeshData d = intrinsic::makeAnnulus(o);
  DiskSurface s{intrinsic::toTriangulation(d), {}};
  for (const auto& p : d.positions) s.positions.emplace_back(p.x(), p.y());
  return s;
}

// === checks shared by the refinement tests

// The largest |closed-form distance between an edge's located ends − the edge's length| over a refined triangulation
// of `surface` (FlatTorus, SphereSurface or DiskSurface): every recorded input location must lie where the intrinsic
// lengths say it does.
template <class Surface>
double worstLocatedLengthError(const Surface& surface, const IntrinsicTriangulation& t,
                               const std::vector<InputLocation>& locations) {
  double worst = 0;
  for (int e = 0; e < t.mesh.nEdges(); ++e) {
    const int h = t.mesh.edgeHalfedge(e);
    const double d = surface.distance(locations[t.mesh.tail(h)], locations[t.mesh.tip(h)]);
    worst = std::max(worst, std::abs(d - t.edgeLengths[e]));
  }
  return worst;
}

// Largest violation of the signpost invariant: consecutive outgoing halfedges differ by the corner angle between them.
inline double signpostDefect(const IntrinsicTriangulation& t, const Signposts& sp) {
  double worst = 0;
  for (int h = 0; h < t.mesh.nHalfedges(); ++h) {
    const int g = t.mesh.nextOutgoing(h);
    if (g == intrinsic::kInvalid) continue;
    const double d =
        std::remainder(sp.angle[g] - sp.angle[h] - intrinsic::cornerAngle(t, h), sp.period[t.mesh.tail(h)]);
    worst = std::max(worst, std::abs(d));
  }
  return worst;
}

}  // namespace conformesh::refine::testing
