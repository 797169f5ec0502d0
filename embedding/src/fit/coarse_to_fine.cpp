// coarse_to_fine.cpp — point location in a chart triangulation (hash grid of face boxes, barycentric tests in the plane
// or in the cones of spherical triangles) and barycentric interpolation of coarse positions (see coarse_to_fine.h).
#include "conformesh/embedding/fit/coarse_to_fine.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

namespace {

// A point counts as inside a face when its smallest barycentric coordinate is at least −kInsideTolerance: chart
// points computed through trigonometric functions (referencePoint of (u, v)) sit on coarse edges and vertices only
// up to ~1e-16, while a point that misses every face by a real amount has a coordinate of order 1 below 0 in every
// candidate face.
constexpr double kInsideTolerance = 1e-9;

std::string pointText(const Eigen::Vector3d& x) {
  return "(" + formatNumber(x.x()) + ", " + formatNumber(x.y()) + ", " + formatNumber(x.z()) + ")";
}

// The point as the location sees it: in the plane its (x, y), on the sphere its direction.
Eigen::Vector3d normalizedPoint(ChartSurface surface, const Eigen::Vector3d& x) {
  if (surface == ChartSurface::Plane) return {x.x(), x.y(), 0};
  return x.normalized();
}

struct CellKey {
  std::int64_t i, j, k;
  bool operator==(const CellKey& o) const { return i == o.i && j == o.j && k == o.k; }
};
struct CellHash {
  std::size_t operator()(const CellKey& c) const {
    std::uint64_t h = static_cast<std::uint64_t>(c.i) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(c.j) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(c.k) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

class FaceGrid {
 public:
  explicit FaceGrid(const ChartTriangulation& t) : t_(t) {
    const int nv = static_cast<int>(t.points.size());
    for (const auto& x : t.points)
      if (!x.allFinite()) throw InputError("coarse-to-fine: a coarse chart point is not finite: " + pointText(x));
    points_.reserve(nv);
    for (const auto& x : t.points) {
      if (t.surface == ChartSurface::UnitSphere && x.norm() == 0)
        throw InputError("coarse-to-fine: a coarse chart point of a sphere chart is the centre (0, 0, 0)");
      points_.push_back(normalizedPoint(t.surface, x));
    }
    std::vector<Eigen::AlignedBox3d> boxes;
    boxes.reserve(t.faces.size());
    double extentSum = 0;
    for (size_t f = 0; f < t.faces.size(); ++f) {
      for (int c : t.faces[f])
        if (c < 0 || c >= nv)
          throw InputError("coarse-to-fine: coarse face " + std::to_string(f) + " refers to vertex " +
                           std::to_string(c) + ", but there are " + std::to_string(nv) + " chart points");
      const Eigen::Vector3d &a = points_[t.faces[f][0]], &b = points_[t.faces[f][1]], &c = points_[t.faces[f][2]];
      const Eigen::Vector3d n = (b - a).cross(c - a);
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      // Relative to the longest side, a face whose area is at round-off level has no reliable coordinates.
      if (!(n.norm() > 1e-12 * longest * longest))
        throw InputError("coarse-to-fine: coarse face " + std::to_string(f) + " (vertices " +
                         std::to_string(t.faces[f][0]) + ", " + std::to_string(t.faces[f][1]) + ", " +
                         std::to_string(t.faces[f][2]) + ") is degenerate: its chart triangle has zero area");
      Eigen::AlignedBox3d box(a);
      box.extend(b), box.extend(c);
      double grow = 0;
      if (t.surface == ChartSurface::UnitSphere) {
        // Every point of the spherical triangle is p/|p| for p in the flat triangle, |p| ≥ d (the plane's distance
        // from the centre), so it lies within 1 − d of the flat triangle.
        const double d = std::abs(a.dot(n)) / n.norm();
        if (!(d > 1e-6))
          throw InputError("coarse-to-fine: coarse face " + std::to_string(f) +
                           " spans a great circle of the sphere chart (its plane passes through the centre)");
        grow = 1 - d;
      }
      const double extent = box.sizes().maxCoeff();
      grow += 1e-6 * extent;  // far above kInsideTolerance·extent: round-off-outside points stay candidates
      box.min().array() -= grow, box.max().array() += grow;
      if (t.surface == ChartSurface::Plane) box.min().z() = box.max().z() = 0;
      boxes.push_back(box);
      extentSum += box.sizes().maxCoeff();
    }
    if (t.faces.empty()) throw InputError("coarse-to-fine: the coarse chart triangulation has no faces");
    cell_ = extentSum / static_cast<double>(t.faces.size());
    for (size_t f = 0; f < boxes.size(); ++f) {
      const CellKey lo = key(boxes[f].min()), hi = key(boxes[f].max());
      for (std::int64_t i = lo.i; i <= hi.i; ++i)
        for (std::int64_t j = lo.j; j <= hi.j; ++j)
          for (std::int64_t k = lo.k; k <= hi.k; ++k) cells_[{i, j, k}].push_back(static_cast<int>(f));
    }
  }

  // Barycentric coordinates of x (already normalizedPoint) in face f; false when x is on the far side of the sphere.
  bool barycentric(int f, const Eigen::Vector3d& x, Eigen::Vector3d& lambda) const {
    const Eigen::Vector3d &a = points_[t_.faces[f][0]], &b = points_[t_.faces[f][1]], &c = points_[t_.faces[f][2]];
    if (t_.surface == ChartSurface::Plane) {
      auto cross2 = [](const Eigen::Vector3d& p, const Eigen::Vector3d& q) { return p.x() * q.y() - p.y() * q.x(); };
      const double whole = cross2(b - a, c - a);
      lambda = Eigen::Vector3d(cross2(b - x, c - x), cross2(c - x, a - x), cross2(a - x, b - x)) / whole;
      return true;
    }
    // x = α a + β b + γ c by Cramer's rule; the orientation of (a, b, c) cancels in the ratios.
    const double whole = a.dot(b.cross(c));
    lambda = Eigen::Vector3d(x.dot(b.cross(c)), a.dot(x.cross(c)), a.dot(b.cross(x))) / whole;
    const double sum = lambda.sum();
    if (!(sum > 0)) return false;
    lambda /= sum;
    return true;
  }

  ChartLocation locate(int index, const Eigen::Vector3d& raw) const {
    if (!raw.allFinite() || (t_.surface == ChartSurface::UnitSphere && raw.norm() == 0))
      throw InputError("coarse-to-fine: fine chart point " + std::to_string(index) + " " + pointText(raw) +
                       (raw.allFinite() ? " is the centre of the sphere chart" : " is not finite"));
    const Eigen::Vector3d x = normalizedPoint(t_.surface, raw);
    ChartLocation best;
    double bestMin = -std::numeric_limits<double>::infinity();
    const auto it = cells_.find(key(x));
    if (it != cells_.end())
      for (int f : it->second) {
        Eigen::Vector3d lambda;
        if (!barycentric(f, x, lambda)) continue;
        const double m = lambda.minCoeff();
        if (m > bestMin) bestMin = m, best.face = f, best.barycentric = lambda;
      }
    if (best.face < 0 || bestMin < -kInsideTolerance)
      throw InputError("coarse-to-fine: fine chart point " + std::to_string(index) + " " + pointText(raw) +
                       " lies in no coarse face" +
                       (best.face < 0 ? std::string(" (no face near it)")
                                      : " (nearest: face " + std::to_string(best.face) +
                                            ", smallest barycentric coordinate " + formatNumber(bestMin) + ")"));
    best.barycentric = best.barycentric.cwiseMax(0.0);
    best.barycentric /= best.barycentric.sum();
    return best;
  }

 private:
  CellKey key(const Eigen::Vector3d& x) const {
    return {static_cast<std::int64_t>(std::floor(x.x() / cell_)), static_cast<std::int64_t>(std::floor(x.y() / cell_)),
            static_cast<std::int64_t>(std::floor(x.z() / cell_))};
  }

  const ChartTriangulation& t_;
  std::vector<Eigen::Vector3d> points_;
  double cell_ = 1;
  std::unordered_map<CellKey, std::vector<int>, CellHash> cells_;
};

}  // namespace

ChartTriangulation chartTriangulation(const intrinsic::MeshData& mesh, const intrinsic::ChartDomain& domain) {
  const intrinsic::ChartShape shape = domain.shape();
  if (shape == intrinsic::ChartShape::Cylinder || shape == intrinsic::ChartShape::Torus)
    throw InputError(describeAt(mesh.source, "coarse-to-fine: the chart is a " + intrinsic::toString(shape) +
                                                 " (periodic); its seam triangles have no single chart triangle, "
                                                 "only sphere, disk and rectangle charts are handled"));
  const auto u = mesh.vertexProperties.find("u"), v = mesh.vertexProperties.find("v");
  if (u == mesh.vertexProperties.end() || v == mesh.vertexProperties.end())
    throw InputError(describeAt(mesh.source,
                                "coarse-to-fine: the mesh has no vertex properties u and v (chart "
                                "coordinates, as discretizeMetric writes them)"));
  if (static_cast<int>(u->second.size()) != mesh.nVertices || static_cast<int>(v->second.size()) != mesh.nVertices)
    throw InputError(describeAt(mesh.source, "coarse-to-fine: vertex properties u, v have " +
                                                 std::to_string(u->second.size()) + ", " +
                                                 std::to_string(v->second.size()) + " values for " +
                                                 std::to_string(mesh.nVertices) + " vertices"));
  ChartTriangulation t;
  t.surface = shape == intrinsic::ChartShape::Sphere ? ChartSurface::UnitSphere : ChartSurface::Plane;
  t.faces = mesh.faces;
  t.points.reserve(mesh.nVertices);
  for (int i = 0; i < mesh.nVertices; ++i)
    t.points.push_back(intrinsic::referencePoint(domain, u->second[i], v->second[i]));
  return t;
}

std::vector<ChartLocation> locateInChart(const ChartTriangulation& coarse, const std::vector<Eigen::Vector3d>& points) {
  const FaceGrid grid(coarse);
  std::vector<ChartLocation> out;
  out.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) out.push_back(grid.locate(static_cast<int>(i), points[i]));
  return out;
}

std::vector<Eigen::Vector3d> carryPositions(const ChartTriangulation& coarse,
                                            const std::vector<Eigen::Vector3d>& coarsePositions,
                                            const std::vector<Eigen::Vector3d>& finePoints) {
  if (coarsePositions.size() != coarse.points.size())
    throw InputError("coarse-to-fine: " + std::to_string(coarsePositions.size()) + " coarse positions for " +
                     std::to_string(coarse.points.size()) + " coarse chart points");
  for (size_t i = 0; i < coarsePositions.size(); ++i)
    if (!coarsePositions[i].allFinite())
      throw InputError("coarse-to-fine: coarse position " + std::to_string(i) + " " + pointText(coarsePositions[i]) +
                       " is not finite");
  const auto located = locateInChart(coarse, finePoints);
  std::vector<Eigen::Vector3d> out;
  out.reserve(located.size());
  for (const ChartLocation& l : located) {
    const auto& f = coarse.faces[l.face];
    out.push_back(l.barycentric[0] * coarsePositions[f[0]] + l.barycentric[1] * coarsePositions[f[1]] +
                  l.barycentric[2] * coarsePositions[f[2]]);
  }
  return out;
}

}  // namespace conformesh::embedding
