// gaussian_curvature_measure.cpp — per-vertex discrete and smooth Gaussian curvature measures over graph-geodesic balls
// (paper eqs. 1 and 5), with the smooth side integrated triangle by triangle on the chart's reference surface.
#include "conformesh/intrinsic/gaussian_curvature_measure.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include <Eigen/LU>

#include "conformesh/intrinsic/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/reference_surface.h"

namespace conformesh::intrinsic {

namespace {

// The 7-point degree-5 rule on the triangle (Radon 1948; Strang–Fix): nodes as (s, t) in the unit triangle
// {s, t ≥ 0, s + t ≤ 1} (barycentric (1 − s − t, s, t)), weights summing to 1.
constexpr double kA1 = 0.059715871789769820, kB1 = 0.470142064105115090, kW1 = 0.132394152788506181;
constexpr double kA2 = 0.797426985353087322, kB2 = 0.101286507323456339, kW2 = 0.125939180544827153;
constexpr double kNodes[7][2] = {{1.0 / 3, 1.0 / 3}, {kB1, kB1}, {kA1, kB1}, {kB1, kA1},
                                 {kB2, kB2}, {kA2, kB2}, {kB2, kA2}};
constexpr double kWeights[7] = {0.225, kW1, kW1, kW1, kW2, kW2, kW2};

// The pulled-back curvature density ρ(s, t) = K √det g |∂(u,v)/∂(s,t)| of one mesh triangle, sampled at the seven
// nodes. From those samples: ∫K dA and ∫|K| dA over the triangle (the degree-5 rule: error O(h⁶) relative to the
// integral for a triangle of size h, far below the O(ε) errors being measured), and the least-squares quadratic q(s, t)
// through them, which the rim of a ball integrates over cut triangles (midpoint rule, exact for quadratics).
struct FaceDensity {
  double integral = 0, absIntegral = 0;
  std::array<double, 6> q{};  // q = q0 + q1 s + q2 t + q3 s² + q4 st + q5 t²

  double at(double s, double t) const { return q[0] + q[1] * s + q[2] * t + q[3] * s * s + q[4] * s * t + q[5] * t * t; }
  // ∫ q over the (s, t)-triangle p0 p1 p2.
  double over(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) const {
    const Eigen::Vector2d a = p1 - p0, b = p2 - p0;
    const double area = 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
    const Eigen::Vector2d m0 = 0.5 * (p0 + p1), m1 = 0.5 * (p1 + p2), m2 = 0.5 * (p2 + p0);
    return area * (at(m0.x(), m0.y()) + at(m1.x(), m1.y()) + at(m2.x(), m2.y())) / 3;
  }
};

// The 6 × 7 least-squares operator from node values to quadratic coefficients, computed once.
const Eigen::Matrix<double, 6, 7>& quadraticFit() {
  static const Eigen::Matrix<double, 6, 7> fit = [] {
    Eigen::Matrix<double, 7, 6> V;
    for (int i = 0; i < 7; ++i) {
      const double s = kNodes[i][0], t = kNodes[i][1];
      V.row(i) << 1, s, t, s * s, s * t, t * t;
    }
    return Eigen::Matrix<double, 6, 7>((V.transpose() * V).inverse() * V.transpose());
  }();
  return fit;
}

FaceDensity sampleFace(const ChartDomain& d, const ChartFunction& density, const Eigen::Vector3d& y0,
                       const Eigen::Vector3d& y1, const Eigen::Vector3d& y2) {
  const Eigen::Vector3d es = y1 - y0, et = y2 - y0;
  Eigen::Matrix<double, 7, 1> values;
  FaceDensity fd;
  for (int i = 0; i < 7; ++i) {
    const Eigen::Vector3d x = y0 + kNodes[i][0] * es + kNodes[i][1] * et;
    Eigen::Vector2d ds, dt;
    chartPoint(d, x, es, &ds);
    chartPoint(d, x, et, &dt);
    const Eigen::Vector2d uv = chartCoordinates(d, x);
    values[i] = density(uv.x(), uv.y()) * std::abs(ds.x() * dt.y() - ds.y() * dt.x());
    fd.integral += 0.5 * kWeights[i] * values[i];  // the unit triangle has area 1/2
    fd.absIntegral += 0.5 * kWeights[i] * std::abs(values[i]);
  }
  const Eigen::Matrix<double, 6, 1> q = quadraticFit() * values;
  for (int k = 0; k < 6; ++k) fd.q[k] = q[k];
  return fd;
}

}  // namespace

QuadratureResult integrateOverReferenceTriangle(const SmoothMetric& metric, const ChartFunction& density,
                                                const Eigen::Vector3d& xa, const Eigen::Vector3d& xbIn,
                                                const Eigen::Vector3d& xcIn, const QuadratureOptions& options) {
  const ChartDomain d = metric.domain();
  const Eigen::Vector3d xb = unwrapNear(d, xa, xbIn), xc = unwrapNear(d, xa, xcIn);
  const Eigen::Vector3d es = xb - xa, et = xc - xa;
  // x(s, t) = xa + s·es + t·et on the unit triangle; on the reference sphere chartPoint reads only the direction of x,
  // so this is the gnomonic parametrization of the geodesic triangle. The density is pulled back with |det ∂(u,v)/∂(s,t)|.
  const ChartFunction pulledBack = [&](double s, double t) {
    const Eigen::Vector3d x = xa + s * es + t * et;
    Eigen::Vector2d ds, dt;
    chartPoint(d, x, es, &ds);
    chartPoint(d, x, et, &dt);
    const Eigen::Vector2d uv = chartCoordinates(d, x);
    return density(uv.x(), uv.y()) * std::abs(ds.x() * dt.y() - ds.y() * dt.x());
  };
  return integrateOverTriangle(pulledBack, {0, 0}, {1, 0}, {0, 1}, options);
}

CurvatureMeasureResult gaussianCurvatureMeasure(const IntrinsicTriangulation& mesh,
                                                const std::vector<Eigen::Vector3d>& referencePoints,
                                                const SmoothMetric& metric, const CurvatureMeasureOptions& options) {
  const HalfedgeMesh& m = mesh.mesh;
  if (mesh.background != Background::Euclidean)
    throw InputError("curvature measure: the mesh's lengths must be Euclidean (measured in the original metric), found " +
                     toString(mesh.background));
  if (static_cast<int>(referencePoints.size()) != m.nVertices())
    throw InputError("curvature measure: expected one reference point per vertex (" + std::to_string(m.nVertices()) +
                     "), found " + std::to_string(referencePoints.size()));
  if (!(options.radiusFraction > 0))
    throw InputError("curvature measure: the ball radius fraction must be positive, found " +
                     std::to_string(options.radiusFraction));
  const ChartDomain domain = metric.domain();

  // === smooth side, once per triangle: ∫K dA and ∫|K| dA over the triangle's image, and the quadratic fit of the
  // density for triangles that a ball's rim cuts.
  const ChartFunction kDensity = curvatureDensity(metric);
  const int nF = m.nFaces();
  std::vector<FaceDensity> face(nF);
  CurvatureMeasureResult r;
  for (int f = 0; f < nF; ++f) {
    const Eigen::Vector3d& a = referencePoints[m.faceVertex(f, 0)];
    face[f] = sampleFace(domain, kDensity, a, unwrapNear(domain, a, referencePoints[m.faceVertex(f, 1)]),
                         unwrapNear(domain, a, referencePoints[m.faceVertex(f, 2)]));
    r.smoothTotalCurvature += face[f].integral;
  }

  // === discrete side and the regions
  const std::vector<double> deficit = vertexCurvatures(mesh);
  r.radius = options.radiusFraction * std::sqrt(totalArea(mesh));
  // Distances are needed up to one edge beyond the rim, so that every triangle the rim cuts has all three.
  const double reach = r.radius + *std::max_element(mesh.edgeLengths.begin(), mesh.edgeLengths.end());
  const int nV = m.nVertices();
  r.discrete.assign(nV, 0.0);
  r.smooth.assign(nV, 0.0);
  r.absoluteScale.assign(nV, 0.0);
  r.relativeError.assign(nV, 0.0);
  std::vector<double> dist(nV, INFINITY);
  std::vector<int> reached;
  std::vector<int> faceStamp(nF, -1), vertexStamp(nV, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto relax = [&](int y, double dy) {
    if (dy <= reach && dy < dist[y]) {
      dist[y] = dy;
      heap.push({dy, y});
    }
  };
  for (int v = 0; v < nV; ++v) {
    reached.clear();
    dist[v] = 0;
    heap.push({0.0, v});
    while (!heap.empty()) {
      const auto [dv, x] = heap.top();
      heap.pop();
      if (dv > dist[x]) continue;
      if (vertexStamp[x] != v) {
        vertexStamp[x] = v;
        reached.push_back(x);
      }
      const int start = m.vertexHalfedge(x);
      int h = start;
      do {
        relax(m.tip(h), dv + mesh.length(h));
        // A boundary fan's last neighbour is reached through the incoming boundary halfedge.
        const int hp = HalfedgeMesh::prev(h);
        if (m.twin(hp) == kInvalid) relax(m.tail(hp), dv + mesh.length(hp));
        h = m.nextOutgoing(h);
      } while (h != kInvalid && h != start);
    }
    auto distanceOf = [&](int x) { return vertexStamp[x] == v ? dist[x] : INFINITY; };

    double smooth = 0, scale = 0, discrete = 0;
    if (options.region == MeasureRegion::GeodesicBall) {
      for (int x : reached)
        if (dist[x] < r.radius && !m.isBoundaryVertex(x)) discrete += deficit[x];
      for (int x : reached) {
        if (dist[x] >= r.radius) continue;
        const int start = m.vertexHalfedge(x);
        int h = start;
        do {
          const int f = HalfedgeMesh::face(h);
          h = m.nextOutgoing(h);
          if (faceStamp[f] == v) continue;
          faceStamp[f] = v;
          const double d[3] = {distanceOf(m.faceVertex(f, 0)), distanceOf(m.faceVertex(f, 1)),
                               distanceOf(m.faceVertex(f, 2))};
          int inside = 0;
          for (double dk : d) inside += dk < r.radius;
          if (inside == 3) {
            smooth += face[f].integral;
            scale += face[f].absIntegral;
            continue;
          }
          // The rim d = r cuts the triangle (d interpolated linearly): integrate the face's quadratic density over the
          // part inside, one or two sub-triangles in the face's (s, t) = (b1, b2) coordinates.
          const Eigen::Vector2d corner[3] = {{0, 0}, {1, 0}, {0, 1}};
          auto cut = [&](int i, int j, double& t) {  // the rim's crossing of edge i → j, i inside, j outside
            t = (r.radius - d[i]) / (d[j] - d[i]);
            return Eigen::Vector2d((1 - t) * corner[i] + t * corner[j]);
          };
          double fraction = 0, ti = 0, tj = 0;
          if (inside == 1) {
            const int i = d[0] < r.radius ? 0 : (d[1] < r.radius ? 1 : 2), j = (i + 1) % 3, k = (i + 2) % 3;
            const Eigen::Vector2d pj = cut(i, j, ti), pk = cut(i, k, tj);
            smooth += face[f].over(corner[i], pj, pk);
            fraction = ti * tj;
          } else {
            const int o = d[0] >= r.radius ? 0 : (d[1] >= r.radius ? 1 : 2), i = (o + 1) % 3, j = (o + 2) % 3;
            const Eigen::Vector2d pi = cut(i, o, ti), pj = cut(j, o, tj);
            smooth += face[f].over(corner[i], corner[j], pj) + face[f].over(corner[i], pj, pi);
            fraction = 1 - (1 - ti) * (1 - tj);
          }
          scale += fraction * face[f].absIntegral;
        } while (h != kInvalid && h != start);
      }
    } else {
      // Triangles with all three vertices within r, and the deficits of their union's interior vertices.
      for (int x : reached) {
        const int start = m.vertexHalfedge(x);
        int h = start;
        do {
          const int f = HalfedgeMesh::face(h);
          if (faceStamp[f] != v && distanceOf(m.faceVertex(f, 0)) < r.radius &&
              distanceOf(m.faceVertex(f, 1)) < r.radius && distanceOf(m.faceVertex(f, 2)) < r.radius) {
            faceStamp[f] = v;
            smooth += face[f].integral;
            scale += face[f].absIntegral;
          }
          h = m.nextOutgoing(h);
        } while (h != kInvalid && h != start);
      }
      for (int x : reached) {
        if (m.isBoundaryVertex(x) || dist[x] >= r.radius) continue;
        bool inside = true;
        const int start = m.vertexHalfedge(x);
        int h = start;
        do {
          inside = inside && faceStamp[HalfedgeMesh::face(h)] == v;
          h = m.nextOutgoing(h);
        } while (h != start && inside);
        if (inside) discrete += deficit[x];
      }
    }
    for (int x : reached) dist[x] = INFINITY;
    r.discrete[v] = discrete;
    r.smooth[v] = smooth;
    r.absoluteScale[v] = scale;
    r.relativeError[v] = scale > 0 ? (discrete - smooth) / scale : 0.0;
  }

  // === statistics
  r.histogram.assign(options.histogramBins, 0);
  int within = 0;
  double sumAbs = 0;
  for (int v = 0; v < nV; ++v) {
    const double err = std::abs(r.discrete[v] - r.smooth[v]);
    sumAbs += err;
    r.maxAbsoluteError = std::max(r.maxAbsoluteError, err);
    const double rel = r.relativeError[v];
    within += std::abs(rel) < options.withinBand;
    const double t = (rel + options.histogramRange) / (2 * options.histogramRange);
    const int bin = std::clamp(static_cast<int>(std::floor(t * options.histogramBins)), 0, options.histogramBins - 1);
    ++r.histogram[bin];
  }
  r.meanAbsoluteError = sumAbs / nV;
  r.fractionWithinBand = static_cast<double>(within) / nV;
  return r;
}

}  // namespace conformesh::intrinsic
