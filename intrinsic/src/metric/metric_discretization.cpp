// metric_discretization.cpp — building T0 from a SmoothMetric: icosahedral spheres, hexagonal disks, periodic grids,
// and edge lengths by adaptive composite Gauss–Legendre along chart curves (see metric_discretization.h).
#include "conformesh/intrinsic/metric/metric_discretization.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

namespace conformesh::intrinsic {

namespace {

// A triangulation in reference space before lengths: vertices with their reference points, faces with the reference
// points of their corners (for periodic grids these are unwrapped, so that each face's chart curves are the short
// ones).
struct Skeleton {
  std::vector<Eigen::Vector3d> vertexRef;
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<Eigen::Vector3d, 3>> cornerRef;
};

// Subdivides the base triangles at frequency N; a new vertex is identified by its integer barycentric weights on the
// base vertices (exact, so points on shared base edges coincide without any tolerance).
template <class PointOf>
Skeleton subdivide(const std::vector<std::array<int, 3>>& base, int N, PointOf pointOf) {
  using Key = std::vector<std::pair<int, int>>;
  std::map<Key, int> ids;
  Skeleton s;
  auto vertex = [&](const std::array<int, 3>& f, int i, int j) {
    const int w[3] = {N - i - j, i, j};
    Key key;
    for (int k = 0; k < 3; ++k)
      if (w[k] > 0) key.emplace_back(f[k], w[k]);
    std::sort(key.begin(), key.end());
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    const int id = static_cast<int>(s.vertexRef.size());
    ids.emplace(key, id);
    s.vertexRef.push_back(pointOf(key));
    return id;
  };
  for (const auto& f : base)
    for (int i = 0; i < N; ++i)
      for (int j = 0; i + j < N; ++j) {
        const int a = vertex(f, i, j), b = vertex(f, i + 1, j), c = vertex(f, i, j + 1);
        s.faces.push_back({a, b, c});
        if (i + j + 1 < N) {
          const int d = vertex(f, i + 1, j + 1);
          s.faces.push_back({b, d, c});
        }
      }
  for (const auto& f : s.faces) s.cornerRef.push_back({s.vertexRef[f[0]], s.vertexRef[f[1]], s.vertexRef[f[2]]});
  return s;
}

// Icosahedron with vertices at both poles (so no edge passes through a pole and every chart curve meets a pole only at
// an endpoint): north, an upper ring of 5 at z = 1/√5, a lower ring rotated by π/5, south. Faces oriented outward.
Skeleton icosphere(int N) {
  std::vector<Eigen::Vector3d> p(12);
  p[0] = {0, 0, 1};
  p[11] = {0, 0, -1};
  const double z = 1 / std::sqrt(5.0), r = 2 / std::sqrt(5.0);
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * M_PI * k / 5, b = a + M_PI / 5;
    p[1 + k] = {r * std::cos(a), r * std::sin(a), z};
    p[6 + k] = {r * std::cos(b), r * std::sin(b), -z};
  }
  std::vector<std::array<int, 3>> base;
  for (int k = 0; k < 5; ++k) {
    const int u0 = 1 + k, u1 = 1 + (k + 1) % 5, l0 = 6 + k, l1 = 6 + (k + 1) % 5;
    base.push_back({0, u0, u1});
    base.push_back({u0, l0, u1});
    base.push_back({u1, l0, l1});
    base.push_back({11, l1, l0});
  }
  return subdivide(base, N, [&](const std::vector<std::pair<int, int>>& key) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (auto [v, w] : key) x += w * p[v];
    return Eigen::Vector3d(x.normalized());
  });
}

// Hexagonal disk of radius `radius`: the hexagon's 6 triangles subdivided at frequency N, then each hexagonal ring k
// mapped to the circle of radius k/N·radius with its 6k points equally spaced in angle (triangles stay near
// equilateral; the centre is an ordinary degree-6 vertex, not a pole fan).
Skeleton hexDisk(int N, double radius) {
  std::vector<std::array<int, 3>> base;
  for (int s = 1; s <= 6; ++s) base.push_back({0, s, s % 6 + 1});
  return subdivide(base, N, [&](const std::vector<std::pair<int, int>>& key) {
    int ring = 0;
    int corner = -1, wCorner = 0, next = -1, wNext = 0;
    for (auto [v, w] : key) {
      if (v == 0) continue;
      ring += w;
      if (corner < 0)
        corner = v, wCorner = w;
      else
        next = v, wNext = w;
    }
    if (ring == 0) return Eigen::Vector3d(0, 0, 0);
    // Two corners on one side: the side runs from corner s to s+1 (with 6 → 1 wrapping, where the sorted key lists 1
    // first).
    double side = corner - 1, t = 0;
    if (next > 0) {
      if (corner == 1 && next == 6)
        side = 5, t = double(wCorner) / ring;
      else
        t = double(wNext) / ring;
    }
    const double angle = 2 * M_PI * (side + t) / 6, rr = radius * ring / N;
    return Eigen::Vector3d(rr * std::cos(angle), rr * std::sin(angle), 0);
  });
}

// Mean metric length of the u- and v-coordinate lines (for choosing a grid whose cells are near square).
std::pair<double, double> meanCoordinateLengths(const SmoothMetric& m) {
  const ChartDomain d = m.domain();
  const int n = 16;
  double lu = 0, lv = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const double u = d.u0 + (a + 0.5) / n * (d.u1 - d.u0), v = d.v0 + (b + 0.5) / n * (d.v1 - d.v0);
      const Eigen::Matrix2d g = m.g(u, v);
      lu += std::sqrt(g(0, 0)) * (d.u1 - d.u0);
      lv += std::sqrt(g(1, 1)) * (d.v1 - d.v0);
    }
  return {lu / (n * n), lv / (n * n)};
}

double edgeLength(const SmoothMetric& m, const ChartDomain& d, const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                  const DiscretizationOptions& o, bool& exact) {
  exact = false;
  if (o.exactGeodesics) {
    const std::optional<double> s = m.geodesicDistance(chartPoint(d, xa), chartPoint(d, xb));
    if (s) {
      exact = true;
      return *s;
    }
  }
  return chartCurveLength(m, xa, xb, o);
}

Skeleton grid(const SmoothMetric& m, const DiscretizationOptions& o) {
  const ChartDomain d = m.domain();
  const int nv = o.resolution;
  const auto [lu, lv] = meanCoordinateLengths(m);
  const int nu = std::max(d.periodicU ? 3 : 1, static_cast<int>(std::lround(nv * lu / lv)));
  const int cu = d.periodicU ? nu : nu + 1, cv = d.periodicV ? nv : nv + 1;  // vertex counts
  const double du = (d.u1 - d.u0) / nu, dv = (d.v1 - d.v0) / nv;
  Skeleton s;
  for (int j = 0; j < cv; ++j)
    for (int i = 0; i < cu; ++i) s.vertexRef.emplace_back(d.u0 + i * du, d.v0 + j * dv, 0);
  auto id = [&](int i, int j) { return (j % cv) * cu + (i % cu); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const Eigen::Vector3d p00(d.u0 + i * du, d.v0 + j * dv, 0), p10 = p00 + Eigen::Vector3d(du, 0, 0),
                                                                  p01 = p00 + Eigen::Vector3d(0, dv, 0),
                                                                  p11 = p00 + Eigen::Vector3d(du, dv, 0);
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), e = id(i, j + 1);
      // The shorter metric diagonal (the Delaunay choice for a near-parallelogram cell).
      bool ex;
      const double l1 = edgeLength(m, d, p00, p11, o, ex), l2 = edgeLength(m, d, p10, p01, o, ex);
      if (l1 <= l2) {
        s.faces.push_back({a, b, c}), s.cornerRef.push_back({p00, p10, p11});
        s.faces.push_back({a, c, e}), s.cornerRef.push_back({p00, p11, p01});
      } else {
        s.faces.push_back({a, b, e}), s.cornerRef.push_back({p00, p10, p01});
        s.faces.push_back({b, c, e}), s.cornerRef.push_back({p10, p11, p01});
      }
    }
  return s;
}

// Interior angle opposite a (law of cosines; only for the quality report).
double angleFrom(double a, double b, double c) {
  return std::acos(std::clamp((b * b + c * c - a * a) / (2 * b * c), -1.0, 1.0));
}

// Speed |dc/dt|_g of the chart curve traced by the reference segment xa + t(xb − xa), t ∈ [0, 1].
class ChartCurveSpeed {
 public:
  ChartCurveSpeed(const SmoothMetric& m, const Eigen::Vector3d& xa, const Eigen::Vector3d& xb)
      : m_(m), d_(m.domain()), xa_(xa), dx_(xb - xa) {}
  double operator()(double t) const {
    Eigen::Vector2d duv;
    const Eigen::Vector2d c = chartPoint(d_, xa_ + t * dx_, dx_, &duv);
    return std::sqrt(std::max(0.0, duv.dot(m_.g(c.x(), c.y()) * duv)));
  }

 private:
  const SmoothMetric& m_;
  const ChartDomain d_;
  const Eigen::Vector3d xa_, dx_;
};

// Recursive halving of one Gauss–Legendre rule; 30 levels (pieces of 1e-9 of the curve) is the hard stop.
double lengthByHalving(const ChartCurveSpeed& speed, const DiscretizationOptions& o) {
  const GaussLegendreRule& rule = gaussLegendreRule(o.gaussPoints);
  auto piece = [&](double t0, double t1) {
    double s = 0;
    for (size_t k = 0; k < rule.nodes.size(); ++k)
      s += rule.weights[k] * speed(0.5 * (t0 + t1) + 0.5 * (t1 - t0) * rule.nodes[k]);
    return 0.5 * (t1 - t0) * s;
  };
  std::function<double(double, double, double, int)> rec = [&](double t0, double t1, double whole, int depth) {
    const double tm = 0.5 * (t0 + t1), left = piece(t0, tm), right = piece(tm, t1);
    if (std::abs(left + right - whole) <= o.lengthTolerance * std::abs(left + right) || depth >= 30)
      return left + right;
    return rec(t0, tm, left, depth + 1) + rec(tm, t1, right, depth + 1);
  };
  return rec(0, 1, piece(0, 1), 0);
}

// G7–K15 on [t0, t1], halving where |K15 − G7| > tolerance·K15; 30 levels is the hard stop.
double lengthByKronrod(const ChartCurveSpeed& speed, double t0, double t1, double tolerance, int depth) {
  using GK = GaussKronrod15;
  const double c = 0.5 * (t0 + t1), h = 0.5 * (t1 - t0);
  const double f0 = speed(c);
  double k15 = GK::kronrodWeights[GK::kNodes - 1] * f0, g7 = GK::gaussWeights[3] * f0;
  for (int k = 0; k + 1 < GK::kNodes; ++k) {
    const double pair = speed(c - h * GK::nodes[k]) + speed(c + h * GK::nodes[k]);
    k15 += GK::kronrodWeights[k] * pair;
    if (k % 2 == 1) g7 += GK::gaussWeights[k / 2] * pair;
  }
  k15 *= h, g7 *= h;
  if (std::abs(k15 - g7) <= tolerance * std::abs(k15) || depth >= 30) return k15;
  return lengthByKronrod(speed, t0, c, tolerance, depth + 1) + lengthByKronrod(speed, c, t1, tolerance, depth + 1);
}

}  // namespace

double chartCurveLength(const SmoothMetric& m, const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                        const DiscretizationOptions& o) {
  const ChartCurveSpeed speed(m, xa, xb);
  const double len = o.curveRule == DiscretizationOptions::CurveRule::GaussKronrod15
                         ? lengthByKronrod(speed, 0, 1, o.lengthTolerance, 0)
                         : lengthByHalving(speed, o);
  if (!std::isfinite(len)) throw InputError(m.description() + ": the metric length of a chart curve is not finite");
  return len;
}

MeshData discretizeMetric(const SmoothMetric& m, const DiscretizationOptions& o, DiscretizationReport* report) {
  const ChartDomain d = m.domain();
  const ChartShape shape = d.shape();
  const int minN = (shape == ChartShape::Torus) ? 3 : 1;
  if (o.resolution < minN || o.resolution > 4096)
    throw InputError(m.description() + ": resolution must lie in " + std::to_string(minN) + "..4096, found " +
                     std::to_string(o.resolution));
  if ((shape == ChartShape::Sphere && !(d.v0 == 0 && d.v1 == M_PI && d.u0 == 0 && d.u1 == 2 * M_PI)) ||
      (shape == ChartShape::Disk && !(d.v0 == 0 && d.u0 == 0 && d.u1 == 2 * M_PI)))
    throw InputError(m.description() +
                     ": a polar chart must be u in [0, 2pi) with v in [0, pi] (sphere) or "
                     "[0, v1] (disk)");
  Skeleton s = shape == ChartShape::Sphere ? icosphere(o.resolution)
               : shape == ChartShape::Disk ? hexDisk(o.resolution, d.v1)
                                           : grid(m, o);

  MeshData out;
  out.source = m.description();
  out.nVertices = static_cast<int>(s.vertexRef.size());
  out.faces = s.faces;
  out.background = Background::Euclidean;
  std::vector<double> us, vs;
  for (const Eigen::Vector3d& x : s.vertexRef) {
    Eigen::Vector2d c = chartPoint(d, x);
    us.push_back(c.x());
    vs.push_back(c.y());
    if (m.hasEmbedding()) out.positions.push_back(m.position(c.x(), c.y()));
  }
  out.vertexProperties["u"] = us;
  out.vertexProperties["v"] = vs;

  std::map<std::pair<int, int>, int> edgeOf;
  int exactCount = 0;
  out.cornerEdges.resize(s.faces.size());
  for (size_t f = 0; f < s.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = s.faces[f][k], b = s.faces[f][(k + 1) % 3];
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      auto it = edgeOf.find(key);
      if (it == edgeOf.end()) {
        bool exact = false;
        const double len = edgeLength(m, d, s.cornerRef[f][k], s.cornerRef[f][(k + 1) % 3], o, exact);
        exactCount += exact;
        it = edgeOf.emplace(key, static_cast<int>(out.edges.size())).first;
        out.edges.push_back({a, b, len});
      }
      out.cornerEdges[f][k] = it->second;
    }

  std::ostringstream lengths;
  lengths << "lengths: " << exactCount << " of " << out.edges.size() << " edges are exact geodesic distances, the rest "
          << "metric lengths of chart curves (Gauss-Legendre, relative tolerance " << o.lengthTolerance << ")";
  out.comments = {"conformesh discretize: metric " + m.description(),
                  "chart: " + toString(shape) + ", resolution " + std::to_string(o.resolution) +
                      "; vertex properties u, v are chart coordinates" +
                      (shape == ChartShape::Sphere || shape == ChartShape::Disk ? " (u = 0 at poles)" : ""),
                  lengths.str()};

  if (report) {
    report->shape = shape;
    report->vertices = out.nVertices;
    report->edges = static_cast<int>(out.edges.size());
    report->faces = static_cast<int>(out.faces.size());
    report->exactLengths = exactCount;
    report->minAngle = M_PI, report->maxAngle = 0, report->totalArea = 0;
    for (size_t f = 0; f < out.faces.size(); ++f) {
      const double l0 = out.edges[out.cornerEdges[f][0]].length, l1 = out.edges[out.cornerEdges[f][1]].length,
                   l2 = out.edges[out.cornerEdges[f][2]].length;
      for (double ang : {angleFrom(l0, l1, l2), angleFrom(l1, l2, l0), angleFrom(l2, l0, l1)}) {
        report->minAngle = std::min(report->minAngle, ang);
        report->maxAngle = std::max(report->maxAngle, ang);
      }
      const double sp = 0.5 * (l0 + l1 + l2);
      report->totalArea += std::sqrt(std::max(0.0, sp * (sp - l0) * (sp - l1) * (sp - l2)));
    }
  }
  return out;
}

}  // namespace conformesh::intrinsic
