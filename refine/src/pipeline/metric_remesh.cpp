// remesh.cpp — discretize → uniformize → refine → pull back, for a surface given by a smooth metric (remesh.h).
#include "conformesh/refine/pipeline/metric_remesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "conformesh/intrinsic/flow/boundary_flattening.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/reference_surface.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A refined vertex on a boundary circle of the uniformized domain lies beyond the chord of its T0* boundary face (one
// barycentric coordinate is negative, see input_location.h). Its image is placed on the chart's boundary between the
// images of the chord's ends (both T0 vertices, exactly known), at the same fraction τ of the chord: a monotone
// piecewise-linear map of each boundary loop onto itself, hence a homeomorphism of the boundary.
Eigen::Vector3d boundaryImage(const ChartDomain& d, const Eigen::Vector3d& xi, const Eigen::Vector3d& xj, double tau) {
  if (d.shape() == ChartShape::Disk) {
    // The boundary is the circle |x| = v1 of the plane: interpolate the angle the short way round.
    const double ai = std::atan2(xi.y(), xi.x());
    double aj = std::atan2(xj.y(), xj.x());
    if (aj - ai > M_PI) aj -= 2 * M_PI;
    if (ai - aj > M_PI) aj += 2 * M_PI;
    const double a = (1 - tau) * ai + tau * aj;
    return {d.v1 * std::cos(a), d.v1 * std::sin(a), 0.0};
  }
  // Rectangle and cylinder charts: boundary sides are straight in (u, v) and T0's corners are vertices.
  return (1 - tau) * xi + tau * unwrapNear(d, xi, xj);
}

// Refinement only adds vertices, so T0 must be coarser than the output: aim T0 at about a quarter of the output's
// expected size (area / (1.1 ε²) vertices, the density Delaunay refinement reaches; measured in
// convergence_study.cpp), clamped to resolutions [8, 32] so that the discrete conformal map stays accurate and the flow
// cheap. Vertex counts grow like resolution² for every chart: an icosahedral sphere chart has 10 r² + 2 vertices, so
// r = √(N/40); other charts (disks, and grids whose u-count follows the metric's aspect ratio) are probed once at
// resolution 8 — a few hundred vertices, milliseconds — and scaled: r = 8·√(N/4 / n₈).
int automaticT0Resolution(const SmoothMetric& metric, double epsilon, const DiscretizationOptions& options) {
  if (!(epsilon > 0) || !std::isfinite(epsilon)) return 32;
  QuadratureOptions q;
  q.absoluteTolerance = q.relativeTolerance = 1e-6;
  const double expected = metricArea(metric, q).value / (1.1 * epsilon * epsilon);
  double r = std::sqrt(expected / 40);
  if (metric.domain().shape() != ChartShape::Sphere) {
    DiscretizationOptions probe = options;
    probe.resolution = 8;
    r = 8 * std::sqrt(expected / 4 / discretizeMetric(metric, probe).nVertices);
  }
  return std::clamp(static_cast<int>(std::lround(r)), 8, 32);
}

}  // namespace

std::string toString(DiskTarget target) {
  switch (target) {
    case DiskTarget::Auto:
      return "auto";
    case DiskTarget::Circle:
      return "circle";
    case DiskTarget::KeepBoundary:
      return "keep-boundary";
  }
  return "unknown";
}

DiskTarget parseDiskTarget(const std::string& name) {
  for (DiskTarget t : {DiskTarget::Auto, DiskTarget::Circle, DiskTarget::KeepBoundary})
    if (toString(t) == name) return t;
  throw InputError("disk target '" + name + "' is not one of auto, circle, keep-boundary");
}

UniformizedMetric uniformizeMetric(const SmoothMetric& metric, const RemeshOptions& options) {
  auto say = [&](const std::string& s) {
    if (options.progress) options.progress(s);
  };
  const ChartDomain domain = metric.domain();
  UniformizedMetric out;

  // === 1. discretize: T0 with chart coordinates per vertex
  auto t = std::chrono::steady_clock::now();
  DiscretizationOptions disc = options.discretization;
  disc.resolution =
      options.t0Resolution > 0 ? options.t0Resolution : automaticT0Resolution(metric, options.epsilon, disc);
  say("discretizing " + metric.description() + " at resolution " + std::to_string(disc.resolution));
  const MeshData t0Data = discretizeMetric(metric, disc);
  ConversionReport conversion;
  out.t0 = toTriangulation(t0Data, &conversion);
  const int n0 = out.t0.mesh.nVertices();
  const auto& uProp = t0Data.vertexProperties.at("u");
  const auto& vProp = t0Data.vertexProperties.at("v");
  out.t0Reference.resize(n0);
  out.t0Chart.resize(n0);
  for (int v = 0; v < t0Data.nVertices; ++v) {
    const int w = conversion.vertexMap[v];
    if (w == kInvalid) continue;
    out.t0Chart[w] = {uProp[v], vProp[v]};
    out.t0Reference[w] = referencePoint(domain, uProp[v], vProp[v]);
  }
  out.discretizeSeconds = secondsSince(t);

  // === 2. uniformize: T0* with λ and the correspondence T0* → T0
  t = std::chrono::steady_clock::now();
  UniformizationOptions uni = options.uniformization;
  if (!uni.progress) uni.progress = options.progress;
  // A chart with one boundary loop is a disk. The rectangle's four corners would be z^{π/α} singularities of the map
  // to the unit disk, so by default such a chart keeps its boundary (boundary_flattening.h); a polar disk chart's
  // boundary is smooth and goes to the circle.
  const std::vector<ComponentTopology> topology = out.t0.mesh.components();
  const bool disk = topology.size() == 1 && topology[0].genus == 0 && topology[0].boundaryLoops == 1;
  out.diskTarget = options.diskTarget;
  if (out.diskTarget == DiskTarget::Auto)
    out.diskTarget = disk && domain.shape() == ChartShape::Rectangle ? DiskTarget::KeepBoundary : DiskTarget::Circle;
  if (out.diskTarget == DiskTarget::KeepBoundary) {
    say("flattening T0 (" + std::to_string(n0) + " vertices) by discrete Ricci flow, boundary lengths kept");
    out.uniformization = flattenKeepingBoundary(out.t0, uni);
  } else {
    say("uniformizing T0 (" + std::to_string(n0) + " vertices) by discrete Ricci flow");
    out.uniformization = uniformize(out.t0, uni);
  }
  out.uniformizeSeconds = secondsSince(t);
  return out;
}

RemeshResult remeshMetric(const SmoothMetric& metric, const RemeshOptions& options) {
  if (!(options.epsilon > 0) || !std::isfinite(options.epsilon))
    throw InputError("remesh: --eps must be a positive size in the metric's units, found " +
                     std::to_string(options.epsilon));
  return remeshUniformized(uniformizeMetric(metric, options), metric, options);
}

RemeshResult remeshUniformized(const UniformizedMetric& prepared, const SmoothMetric& metric,
                               const RemeshOptions& options) {
  if (!(options.epsilon > 0) || !std::isfinite(options.epsilon))
    throw InputError("remesh: --eps must be a positive size in the metric's units, found " +
                     std::to_string(options.epsilon));
  auto say = [&](const std::string& s) {
    if (options.progress) options.progress(s);
  };
  const ChartDomain domain = metric.domain();
  const IntrinsicTriangulation& t0 = prepared.t0;
  const std::vector<Eigen::Vector3d>& t0Reference = prepared.t0Reference;
  const std::vector<Eigen::Vector2d>& t0Chart = prepared.t0Chart;
  const Uniformization& u = prepared.uniformization;
  const int n0 = t0.mesh.nVertices();
  DiscretizationOptions disc = options.discretization;
  RemeshResult out;
  out.t0Vertices = n0;
  out.t0Faces = t0.mesh.nFaces();
  out.uniformization = u.report;
  out.diskTarget = prepared.diskTarget;
  const bool keepBoundary = prepared.diskTarget == DiskTarget::KeepBoundary;
  out.seconds.discretize = prepared.discretizeSeconds;
  out.seconds.uniformize = prepared.uniformizeSeconds;
  auto t = std::chrono::steady_clock::now();

  // === 3. refine T0*, graded by e^(−λ)
  RefineOptions ref = options.refinement;
  ref.epsilon = options.epsilon;
  ref.ratioBound = options.ratioBound;
  if (!options.uniform) ref.lambda = u.lambda;
  // The kept-boundary domain is the polygon of T0's boundary chords: split its sides on the chords.
  if (keepBoundary) ref.boundarySplit = BoundarySplit::Geodesic;
  if (!ref.progress && options.progress)
    ref.progress = [&](const RefineProgress& p) {
      say("refining: " + std::to_string(p.vertices) + " vertices, " + std::to_string(p.queuedTriangles) +
          " bad triangles queued");
    };
  say("refining the uniformized surface, eps = " + std::to_string(options.epsilon));
  RefineResult refined = refineDelaunay(u.uniform, ref);
  out.refinement = refined.statistics;
  out.uniformQuality = measureQuality(refined.triangulation);
  out.seconds.refine = secondsSince(t);

  // === 4. pull back: T1* vertices → T0 points → chart; lengths from the original metric
  t = std::chrono::steady_clock::now();
  say("pulling back " + std::to_string(refined.triangulation.mesh.nVertices()) + " vertices to the surface");
  const HalfedgeMesh& m1 = refined.triangulation.mesh;
  const HalfedgeMesh& mStar = u.uniform.mesh;
  const int n1 = m1.nVertices();
  out.reference.resize(n1);
  out.chart.resize(n1);
  out.t0Face.assign(n1, kInvalid);
  out.t0Bary.assign(n1, Eigen::Vector3d::Zero());
  out.lambda = refined.lambda;

  // Interior points go through the correspondence together; boundary-circle points are placed on the chart boundary.
  std::vector<FacePoint> onUniform;
  std::vector<int> interiorVertex;
  for (int v = n0; v < n1; ++v) {
    const InputLocation& loc = refined.locations[v];
    const Eigen::Vector3d& b = loc.bary;
    int negative = -1;  // the most negative coordinate, if any
    for (int k = 0; k < 3; ++k)
      if (b[k] < 0 && (negative < 0 || b[k] < b[negative])) negative = k;
    // On the kept-boundary polygon a boundary vertex lies ON a T0* chord; its coordinate 0 may come out as round-off
    // of either sign (1e-9 is the correspondence's own tolerance, mapToInput). Such a point goes through the
    // correspondence, which keeps a boundary chord on the same T0 chord (u = 0 at both ends: the map is affine there).
    if (keepBoundary && negative >= 0 && b[negative] > -1e-9) negative = -1;
    if (negative < 0) {
      FacePoint p;
      p.face = loc.face;
      const Eigen::Vector3d c = b.cwiseMax(0.0);
      const double s = c.sum();
      p.bary = {c[0] / s, c[1] / s, c[2] / s};
      onUniform.push_back(p);
      interiorVertex.push_back(v);
      continue;
    }
    // The chord opposite corner `negative`: its ends are T0* vertices, which are T0 vertices.
    const int i = mStar.faceVertex(loc.face, (negative + 1) % 3), j = mStar.faceVertex(loc.face, (negative + 2) % 3);
    const double bi = b[(negative + 1) % 3], bj = b[(negative + 2) % 3];
    const double tau = bj / (bi + bj);
    out.reference[v] = boundaryImage(domain, t0Reference[i], t0Reference[j], tau);
    // Its T0 location: the T0 boundary face of chord (i, j) is not known without a search, so record the nearest chord
    // end's corner; the reference point above is the vertex's place.
    const int h = t0.mesh.vertexHalfedge(tau < 0.5 ? i : j);
    out.t0Face[v] = HalfedgeMesh::face(h);
    out.t0Bary[v][h % 3] = 1.0;
  }
  const std::vector<FacePoint> onInput = u.correspondence.mapToInput(mStar, onUniform);
  for (size_t k = 0; k < interiorVertex.size(); ++k) {
    const int v = interiorVertex[k];
    const FacePoint& p = onInput[k];
    const Eigen::Vector3d b(p.bary[0], p.bary[1], p.bary[2]);
    out.reference[v] = interpolateOnReference(domain, t0Reference[t0.mesh.faceVertex(p.face, 0)],
                                              t0Reference[t0.mesh.faceVertex(p.face, 1)],
                                              t0Reference[t0.mesh.faceVertex(p.face, 2)], b);
    out.t0Face[v] = p.face;
    out.t0Bary[v] = b;
  }
  for (int v = 0; v < n0; ++v) {
    out.reference[v] = t0Reference[v];
    const int h = t0.mesh.vertexHalfedge(v);
    out.t0Face[v] = HalfedgeMesh::face(h);
    out.t0Bary[v][h % 3] = 1.0;
  }
  // Interpolation across a periodic seam leaves a point's unwrapped coordinates outside the chart; bring every
  // reference point of a non-polar chart back into it, so that edges are measured between canonical representatives.
  const bool polar = domain.shape() == ChartShape::Sphere || domain.shape() == ChartShape::Disk;
  for (int v = 0; v < n1; ++v) {
    out.chart[v] = v < n0 ? t0Chart[v] : chartCoordinates(domain, out.reference[v]);
    if (!polar) out.reference[v] = {out.chart[v].x(), out.chart[v].y(), 0.0};
  }
  if (metric.hasEmbedding()) {
    out.positions.resize(n1);
    for (int v = 0; v < n1; ++v) out.positions[v] = metric.position(out.chart[v].x(), out.chart[v].y());
  }

  // Output lengths: the metric length of each edge's curve (the reference-straight segment between its ends). Output
  // edges are short, so 6 Gauss–Legendre nodes per piece (exact for speeds of degree 11) with pieces halved until two
  // sums agree to 1e-12 relative cost a few dozen metric evaluations per edge, ~100× below the errors measured. The
  // edges are independent: shared among threads.
  disc.gaussPoints = 6;
  disc.lengthTolerance = 1e-12;
  out.mesh.mesh = m1;
  out.mesh.background = Background::Euclidean;
  out.mesh.edgeLengths.resize(m1.nEdges());
#pragma omp parallel for schedule(dynamic, 256)
  for (int e = 0; e < m1.nEdges(); ++e) {
    const int h = m1.edgeHalfedge(e);
    const Eigen::Vector3d& xa = out.reference[m1.tail(h)];
    out.mesh.edgeLengths[e] = chartCurveLength(metric, xa, unwrapNear(domain, xa, out.reference[m1.tip(h)]), disc);
  }
  // Lengths of chart-straight curves can fail the triangle inequality where T0 is too coarse for the metric: a T1*
  // triangle whose three vertices pull back onto one chart-straight line (e.g. three T0 grid vertices joined by a
  // flipped edge) is degenerate. That is a failure of the approximation, not of the input.
  try {
    validateLengths(out.mesh, "remeshed surface");
  } catch (const InputError& e) {
    throw ConvergenceError(std::string(e.what()) + " (the pull-back through T0 of " + std::to_string(n0) +
                           " vertices is too coarse for this metric here: raise --t0-resolution or lower --eps)");
  }

  // The map back is a homeomorphism only if no triangle's image is inverted: compare with T0's orientation.
  double t0Sign = 0;
  for (int f = 0; f < t0.mesh.nFaces(); ++f)
    t0Sign += referenceOrientation(domain, t0Reference[t0.mesh.faceVertex(f, 0)], t0Reference[t0.mesh.faceVertex(f, 1)],
                                   t0Reference[t0.mesh.faceVertex(f, 2)]) > 0
                  ? 1
                  : -1;
  for (int f = 0; f < m1.nFaces(); ++f) {
    const double o = referenceOrientation(domain, out.reference[m1.faceVertex(f, 0)],
                                          out.reference[m1.faceVertex(f, 1)], out.reference[m1.faceVertex(f, 2)]);
    if (!(o * t0Sign > 0)) ++out.invertedTriangles;
  }
  out.quality = measureQuality(out.mesh);
  out.seconds.pullBack = secondsSince(t);
  return out;
}

MeshData toMeshData(const RemeshResult& r, const SmoothMetric& metric, double epsilon) {
  MeshData d = fromTriangulation(r.mesh);
  d.source = metric.description();
  if (!r.positions.empty()) d.positions = r.positions;
  const int n = r.mesh.mesh.nVertices();
  auto& p = d.vertexProperties;
  p["u"].resize(n);
  p["v"].resize(n);
  p["smooth_curvature"].resize(n);
  p["input_face"].resize(n);
  for (const char* b : {"input_b0", "input_b1", "input_b2"}) p[b].resize(n);
  for (int v = 0; v < n; ++v) {
    p["u"][v] = r.chart[v].x();
    p["v"][v] = r.chart[v].y();
    p["smooth_curvature"][v] = metric.gaussianCurvature(r.chart[v].x(), r.chart[v].y());
    p["input_face"][v] = r.t0Face[v];
    p["input_b0"][v] = r.t0Bary[v][0];
    p["input_b1"][v] = r.t0Bary[v][1];
    p["input_b2"][v] = r.t0Bary[v][2];
  }
  p["lambda"] = r.lambda;
  p["curvature"] = vertexCurvatures(r.mesh);
  char eps[64];
  std::snprintf(eps, sizeof eps, "%.17g", epsilon);
  d.comments.push_back("conformesh remesh: " + metric.description());
  d.comments.push_back("eps " + std::string(eps) + " (circumradius bound in the original metric)");
  d.comments.push_back("lengths: metric lengths of the edges' curves in the original metric");
  d.comments.push_back("input: T0 of " + std::to_string(r.t0Vertices) + " vertices, " + std::to_string(r.t0Faces) +
                       " faces (input_face, input_b0..2)");
  return d;
}

VtkMesh toVtkMesh(const MeshData& data, const RemeshResult& r) {
  VtkMesh vtk;
  vtk.title = "conformesh remesh: " + data.source;
  vtk.points = r.positions.empty() ? r.reference : r.positions;
  vtk.triangles = data.faces;
  for (const auto& [name, values] : data.vertexProperties)
    if (name.rfind("input_", 0) != 0) vtk.pointFields[name] = values;
  return vtk;
}

}  // namespace conformesh::refine
