// metric_remesh.cpp — discretize → uniformize → refine → pull back, for a surface given by a smooth metric
// (metric_remesh.h); stages 3 and 4 are the class UniformizedRemesh, one method per step.
#include "conformesh/refine/pipeline/metric_remesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/boundary_flattening.h"
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
    // The pull-back maps every vertex of T1* through the correspondence, which the half of the double lacks.
    const std::string gap = correspondenceUnavailable(out.uniformization);
    if (!gap.empty())
      throw ConvergenceError(
          "remesh: " + gap +
          ", and the pull-back to the chart needs a correspondence that carries "
          "them (--disk-target keep-boundary or another --t0-resolution may avoid the flipped boundary edges)");
  }
  out.uniformizeSeconds = secondsSince(t);
  return out;
}

std::string RemeshOptions::validate() const {
  if (epsilonRelative != 0 || !std::isfinite(epsilonRelative)) {
    if (!(epsilonRelative > 0) || !std::isfinite(epsilonRelative))
      return "remesh: --eps-rel must be a positive fraction of sqrt(area), found " + std::to_string(epsilonRelative);
    if (epsilon != 0) return "remesh: give --eps or --eps-rel, not both";
    return "";
  }
  if (!(epsilon > 0) || !std::isfinite(epsilon))
    return "remesh: --eps must be a positive size in the metric's units, found " + std::to_string(epsilon);
  return "";
}

namespace {

// Stages 3 and 4 on a prepared uniformization: refine T0* graded by e^(−λ), then pull back — T1* vertices → T0
// points → chart — and measure each output edge in the original metric.
class UniformizedRemesh {
 public:
  UniformizedRemesh(const UniformizedMetric& prepared, const SmoothMetric& metric, const RemeshOptions& options)
      : prepared_(prepared),
        metric_(metric),
        options_(options),
        domain_(metric.domain()),
        t0_(prepared.t0),
        n0_(prepared.t0.mesh.nVertices()),
        keepBoundary_(prepared.diskTarget == DiskTarget::KeepBoundary) {}

  RemeshResult run() {
    out_.t0Vertices = n0_;
    out_.t0Faces = t0_.mesh.nFaces();
    out_.uniformization = prepared_.uniformization.report;
    out_.diskTarget = prepared_.diskTarget;
    out_.seconds.discretize = prepared_.discretizeSeconds;
    out_.seconds.uniformize = prepared_.uniformizeSeconds;
    const RefineResult refined = refine();
    const auto t = std::chrono::steady_clock::now();
    say("pulling back " + std::to_string(refined.triangulation.mesh.nVertices()) + " vertices to the surface");
    placeVertices(refined);
    placeOnChart();
    measureLengths(refined.triangulation.mesh);
    countInvertedTriangles();
    out_.quality = measureQuality(out_.mesh);
    out_.seconds.pullBack = secondsSince(t);
    return std::move(out_);
  }

 private:
  void say(const std::string& s) const {
    if (options_.progress) options_.progress(s);
  }

  // === 3. refine T0*, graded by e^(−λ)
  RefineResult refine() {
    const auto t = std::chrono::steady_clock::now();
    RefineOptions ref = options_.refinement;
    ref.epsilon = options_.epsilon;
    ref.ratioBound = options_.ratioBound;
    ref.maxInsertions = insertionCapFor(options_.maxVertices, ref.maxInsertions);
    if (!options_.uniform) ref.lambda = prepared_.uniformization.lambda;
    out_.epsilon = options_.epsilon;
    out_.expected = expectedVertices(prepared_.uniformization.uniform, ref.lambda, options_.epsilon);
    say("expected output: about " + std::to_string(std::llround(out_.expected.expected)) + " vertices (area " +
        std::to_string(out_.expected.area) + " / (1.1 eps^2))");
    checkVertexBudget(out_.expected, options_.epsilon, options_.maxVertices);
    // The kept-boundary domain is the polygon of T0's boundary chords: split its sides on the chords.
    if (keepBoundary_) ref.boundarySplit = BoundarySplit::Geodesic;
    if (!ref.progress && options_.progress)
      ref.progress = [this](const RefineProgress& p) {
        say("refining: " + std::to_string(p.vertices) + " vertices, " + std::to_string(p.queuedTriangles) +
            " bad triangles queued");
      };
    say("refining the uniformized surface, eps = " + std::to_string(options_.epsilon));
    RefineResult refined = refineDelaunay(prepared_.uniformization.uniform, ref);
    if (refined.triangulation.mesh.nVertices() == refined.statistics.inputVertices)  // nothing inserted: said
      out_.notices.push_back(
          epsilonAboveSpacingNotice(options_.epsilon, measureQuality(refined.triangulation).maxCircumradius) +
          " (T0, circumradii in the uniformized metric)");
    out_.refinement = refined.statistics;
    out_.uniformQuality = measureQuality(refined.triangulation);
    out_.seconds.refine = secondsSince(t);
    return refined;
  }

  // === 4. pull back: each T1* vertex to its T0 point and reference point. Interior points go through the
  // correspondence together; boundary-circle points are placed on the chart boundary; T0's vertices are themselves.
  void placeVertices(const RefineResult& refined) {
    const int n1 = refined.triangulation.mesh.nVertices();
    out_.reference.resize(n1);
    out_.chart.resize(n1);
    out_.t0Face.assign(n1, kInvalid);
    out_.t0Bary.assign(n1, Eigen::Vector3d::Zero());
    out_.lambda = refined.lambda;
    std::vector<FacePoint> onUniform;
    std::vector<int> interiorVertex;
    for (int v = n0_; v < n1; ++v) {
      const InputLocation& loc = refined.locations[v];
      const int negative = capCorner(loc.bary);
      if (negative >= 0) {
        placeOnBoundary(v, loc, negative);
        continue;
      }
      FacePoint p;
      p.face = loc.face;
      const Eigen::Vector3d c = loc.bary.cwiseMax(0.0);
      const double s = c.sum();
      p.bary = {c[0] / s, c[1] / s, c[2] / s};
      onUniform.push_back(p);
      interiorVertex.push_back(v);
    }
    const std::vector<FacePoint> onInput =
        prepared_.uniformization.correspondence.mapToInput(prepared_.uniformization.uniform.mesh, onUniform);
    const std::vector<Eigen::Vector3d>& t0Reference = prepared_.t0Reference;
    for (size_t k = 0; k < interiorVertex.size(); ++k) {
      const int v = interiorVertex[k];
      const FacePoint& p = onInput[k];
      const Eigen::Vector3d b(p.bary[0], p.bary[1], p.bary[2]);
      out_.reference[v] = interpolateOnReference(domain_, t0Reference[t0_.mesh.faceVertex(p.face, 0)],
                                                 t0Reference[t0_.mesh.faceVertex(p.face, 1)],
                                                 t0Reference[t0_.mesh.faceVertex(p.face, 2)], b);
      out_.t0Face[v] = p.face;
      out_.t0Bary[v] = b;
    }
    for (int v = 0; v < n0_; ++v) {
      out_.reference[v] = t0Reference[v];
      const int h = t0_.mesh.vertexHalfedge(v);
      out_.t0Face[v] = HalfedgeMesh::face(h);
      out_.t0Bary[v][h % 3] = 1.0;
    }
  }

  // The corner whose coordinate is negative (the most negative) for a point beyond a boundary chord, else −1. On the
  // kept-boundary polygon a boundary vertex lies ON a T0* chord; its coordinate 0 may come out as round-off of either
  // sign (1e-9 is the correspondence's own tolerance, mapToInput). Such a point goes through the correspondence, which
  // keeps a boundary chord on the same T0 chord (u = 0 at both ends: the map is affine there).
  int capCorner(const Eigen::Vector3d& b) const {
    int negative = -1;
    for (int k = 0; k < 3; ++k)
      if (b[k] < 0 && (negative < 0 || b[k] < b[negative])) negative = k;
    if (keepBoundary_ && negative >= 0 && b[negative] > -1e-9) negative = -1;
    return negative;
  }

  // A vertex beyond the chord opposite corner `negative` of its T0* face: the chord's ends are T0* vertices, which are
  // T0 vertices, and its image is on the chart's boundary between theirs (boundaryImage).
  void placeOnBoundary(int v, const InputLocation& loc, int negative) {
    const HalfedgeMesh& mStar = prepared_.uniformization.uniform.mesh;
    const Eigen::Vector3d& b = loc.bary;
    const int i = mStar.faceVertex(loc.face, (negative + 1) % 3), j = mStar.faceVertex(loc.face, (negative + 2) % 3);
    const double bi = b[(negative + 1) % 3], bj = b[(negative + 2) % 3];
    const double tau = bj / (bi + bj);
    out_.reference[v] = boundaryImage(domain_, prepared_.t0Reference[i], prepared_.t0Reference[j], tau);
    // Its T0 location: the T0 boundary face of chord (i, j) is not known without a search, so record the nearest chord
    // end's corner; the reference point above is the vertex's place.
    const int h = t0_.mesh.vertexHalfedge(tau < 0.5 ? i : j);
    out_.t0Face[v] = HalfedgeMesh::face(h);
    out_.t0Bary[v][h % 3] = 1.0;
  }

  // Chart coordinates per vertex, and the embedding where the metric has one. Interpolation across a periodic seam
  // leaves a point's unwrapped coordinates outside the chart; every reference point of a non-polar chart is brought
  // back into it, so that edges are measured between canonical representatives.
  void placeOnChart() {
    const int n1 = static_cast<int>(out_.reference.size());
    const bool polar = domain_.shape() == ChartShape::Sphere || domain_.shape() == ChartShape::Disk;
    for (int v = 0; v < n1; ++v) {
      out_.chart[v] = v < n0_ ? prepared_.t0Chart[v] : chartCoordinates(domain_, out_.reference[v]);
      if (!polar) out_.reference[v] = {out_.chart[v].x(), out_.chart[v].y(), 0.0};
    }
    if (metric_.hasEmbedding()) {
      out_.positions.resize(n1);
      for (int v = 0; v < n1; ++v) out_.positions[v] = metric_.position(out_.chart[v].x(), out_.chart[v].y());
    }
  }

  // Output lengths: the metric length of each edge's curve (the reference-straight segment between its ends), by the
  // Gauss–Kronrod pair G7–K15, pieces halved until |K15 − G7| ≤ 1e-12·K15 (an estimate of G7's error; the K15 kept is
  // more accurate); the edges are shared among threads.
  void measureLengths(const HalfedgeMesh& m1) {
    DiscretizationOptions disc = options_.discretization;
    disc.curveRule = DiscretizationOptions::CurveRule::GaussKronrod15;
    disc.lengthTolerance = 1e-12;
    out_.mesh.mesh = m1;
    out_.mesh.background = Background::Euclidean;
    out_.mesh.edgeLengths.resize(m1.nEdges());
#pragma omp parallel for schedule(dynamic, 256)
    for (int e = 0; e < m1.nEdges(); ++e) {
      const int h = m1.edgeHalfedge(e);
      const Eigen::Vector3d& xa = out_.reference[m1.tail(h)];
      out_.mesh.edgeLengths[e] =
          chartCurveLength(metric_, xa, unwrapNear(domain_, xa, out_.reference[m1.tip(h)]), disc);
    }
    // Lengths of chart-straight curves can fail the triangle inequality where T0 is too coarse for the metric: a T1*
    // triangle whose three vertices pull back onto one chart-straight line (e.g. three T0 grid vertices joined by a
    // flipped edge) is degenerate. That is a failure of the approximation, not of the input.
    try {
      validateLengths(out_.mesh, "remeshed surface");
    } catch (const InputError& e) {
      throw ConvergenceError(std::string(e.what()) + " (the pull-back through T0 of " + std::to_string(n0_) +
                             " vertices is too coarse for this metric here: raise --t0-resolution or lower --eps)");
    }
  }

  // The map back is a homeomorphism only if no triangle's image is inverted: compare with T0's orientation.
  void countInvertedTriangles() {
    const std::vector<Eigen::Vector3d>& t0Reference = prepared_.t0Reference;
    const HalfedgeMesh& m1 = out_.mesh.mesh;
    double t0Sign = 0;
    for (int f = 0; f < t0_.mesh.nFaces(); ++f)
      t0Sign += referenceOrientation(domain_, t0Reference[t0_.mesh.faceVertex(f, 0)],
                                     t0Reference[t0_.mesh.faceVertex(f, 1)], t0Reference[t0_.mesh.faceVertex(f, 2)]) > 0
                    ? 1
                    : -1;
    for (int f = 0; f < m1.nFaces(); ++f) {
      const double o = referenceOrientation(domain_, out_.reference[m1.faceVertex(f, 0)],
                                            out_.reference[m1.faceVertex(f, 1)], out_.reference[m1.faceVertex(f, 2)]);
      if (!(o * t0Sign > 0)) ++out_.invertedTriangles;
    }
  }

  const UniformizedMetric& prepared_;
  const SmoothMetric& metric_;
  const RemeshOptions& options_;
  const ChartDomain domain_;
  const IntrinsicTriangulation& t0_;
  const int n0_;
  const bool keepBoundary_;
  RemeshResult out_;
};

void throwIfInvalid(const RemeshOptions& options) {
  const std::string problem = options.validate();
  if (!problem.empty()) throw InputError(problem);
}

}  // namespace

// --eps-rel becomes ε = fraction · √(smooth area), and an ε far too small is refused before T0 is even discretized
// (the smooth area / (1.1 ε²) is the same estimate as vertex_budget.h's, without λ).
RemeshResult remeshMetric(const SmoothMetric& metric, const RemeshOptions& options) {
  throwIfInvalid(options);
  RemeshOptions o = options;
  QuadratureOptions q;
  q.absoluteTolerance = q.relativeTolerance = 1e-6;
  const double area = metricArea(metric, q).value;
  if (o.epsilonRelative > 0) {
    o.epsilon = o.epsilonRelative * std::sqrt(area);
    o.epsilonRelative = 0;
  }
  checkVertexBudget({area, area / (1.1 * o.epsilon * o.epsilon)}, o.epsilon, o.maxVertices);
  return remeshUniformized(uniformizeMetric(metric, o), metric, o);
}

RemeshResult remeshUniformized(const UniformizedMetric& prepared, const SmoothMetric& metric,
                               const RemeshOptions& options) {
  throwIfInvalid(options);
  return UniformizedRemesh(prepared, metric, options).run();
}

}  // namespace conformesh::refine
