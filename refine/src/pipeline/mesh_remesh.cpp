// mesh_remesh.cpp — the mesh-file pipeline (mesh_remesh.h) as two routes of named steps. Uniformized: subdivide the
// input → uniformize T0 → refine T0* → pull back through the input faces (pull_back.h) → checks. Input: refine the
// input in its own metric → locate on the input → checks. Also the curvature-measure check of a result.
#include "conformesh/refine/pipeline/mesh_remesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <queue>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/refine/trace/input_location.h"
#include "pipeline/pull_back.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;
using detail::Point;

namespace {

double secondsSinceStart(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One midpoint (1-to-4) subdivision of a flat triangulation: the same flat metric, the same curvature atoms (a new
// vertex lies inside a flat face or on a straight edge between two, angle sum 2π), every face split into four similar
// ones. Old vertices keep their indices; the midpoint of edge e is vertex n + e. parentFace / parentBary carry each new
// face and its corners back to the face it came from.
struct Subdivision {
  IntrinsicTriangulation tri;
  std::vector<int> parentFace;                         // per new face
  std::vector<std::array<Eigen::Vector3d, 3>> corner;  // per new face: its corners in the parent's coordinates
};

Subdivision subdivide(const IntrinsicTriangulation& t) {
  const HalfedgeMesh& m = t.mesh;
  const int n = m.nVertices(), nf = m.nFaces();
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<double, 3>> sides;  // per new face corner k: length of its side k → k+1
  Subdivision out;
  for (int f = 0; f < nf; ++f) {
    int v[3], mid[3];
    double l[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = m.faceVertex(f, k);
      mid[k] = n + m.edge(3 * f + k);  // midpoint of side k → k+1
      l[k] = t.length(3 * f + k);
    }
    const Eigen::Vector3d e[3] = {Eigen::Vector3d::Unit(0), Eigen::Vector3d::Unit(1), Eigen::Vector3d::Unit(2)};
    for (int k = 0; k < 3; ++k) {  // corner triangle at corner k: (v_k, mid_k, mid_{k−1})
      const int km = (k + 2) % 3;
      faces.push_back({v[k], mid[k], mid[km]});
      sides.push_back({l[k] / 2, l[(k + 1) % 3] / 2, l[km] / 2});
      out.parentFace.push_back(f);
      out.corner.push_back({e[k], 0.5 * (e[k] + e[(k + 1) % 3]), 0.5 * (e[k] + e[km])});
    }
    faces.push_back({mid[0], mid[1], mid[2]});  // the middle triangle, sides parallel to the face's
    sides.push_back({l[2] / 2, l[0] / 2, l[1] / 2});
    out.parentFace.push_back(f);
    out.corner.push_back({0.5 * (e[0] + e[1]), 0.5 * (e[1] + e[2]), 0.5 * (e[2] + e[0])});
  }
  out.tri.mesh = HalfedgeMesh::fromFaces(faces, n + m.nEdges(), "subdivided input");
  out.tri.background = Background::Euclidean;
  out.tri.edgeLengths.assign(out.tri.mesh.nEdges(), 0.0);
  for (int f = 0; f < out.tri.mesh.nFaces(); ++f)
    for (int k = 0; k < 3; ++k) out.tri.edgeLengths[out.tri.mesh.edge(3 * f + k)] = sides[f][k];
  return out;
}

// Affine interpolation of the input's positions at each output vertex's location (empty without positions).
std::vector<Eigen::Vector3d> positionsAt(const IntrinsicTriangulation& input,
                                         const std::vector<Eigen::Vector3d>& inputPositions,
                                         const std::vector<FacePoint>& location) {
  std::vector<InputLocation> at(location.size());
  for (std::size_t i = 0; i < location.size(); ++i)
    at[i] = {location[i].face, {location[i].bary[0], location[i].bary[1], location[i].bary[2]}};
  return interpolatePositions(input.mesh, inputPositions, at);
}

class MeshRemeshPipeline {
 public:
  MeshRemeshPipeline(const IntrinsicTriangulation& input, const std::vector<Eigen::Vector3d>& positions,
                     const MeshRemeshOptions& options)
      : input_(input), positions_(positions), options_(options) {}

  MeshRemeshResult run() {
    checkInput();
    epsilon_ =
        options_.epsilonRelative > 0 ? options_.epsilonRelative * std::sqrt(totalArea(input_)) : options_.epsilon;
    MeshRemeshResult out = options_.refineIn == RefineMetric::Input ? runInInputMetric() : runUniformized();
    out.epsilon = epsilon_;
    return out;
  }

 private:
  void say(const std::string& s) const {
    if (options_.progress) options_.progress(s);
  }

  void checkInput() const {
    const std::string problem = options_.validate();
    if (!problem.empty()) throw InputError(problem);
    if (input_.background != Background::Euclidean)
      throw InputError("remesh: the input mesh must have a Euclidean background (flat faces)");
    validateLengths(input_, "remesh input");
    if (!positions_.empty() && positions_.size() != static_cast<std::size_t>(input_.mesh.nVertices()))
      throw InputError("remesh: " + std::to_string(positions_.size()) + " positions for " +
                       std::to_string(input_.mesh.nVertices()) + " input vertices");
  }

  // The expected size, printed and checked against the cap before refining `t` (graded by `lambda`, empty: uniform).
  void checkBudget(const IntrinsicTriangulation& t, const std::vector<double>& lambda, MeshRemeshResult& out) const {
    out.expected = expectedVertices(t, lambda, epsilon_);
    say("expected output: about " + std::to_string(std::llround(out.expected.expected)) + " vertices (area " +
        std::to_string(out.expected.area) + " / (1.1 eps^2))");
    checkVertexBudget(out.expected, epsilon_, options_.maxVertices);
  }

  // A refinement that inserted nothing returned its input: said, not silent.
  static void noticeIfUnrefined(const RefineResult& refined, double epsilon, MeshRemeshResult& out) {
    if (refined.triangulation.mesh.nVertices() > refined.statistics.inputVertices) return;
    out.notices.push_back(epsilonAboveSpacingNotice(epsilon, measureQuality(refined.triangulation).maxCircumradius));
  }

  // The refinement's options common to both routes: ε, B, the insertion cap and the progress report.
  RefineOptions refineOptions() const {
    RefineOptions ref = options_.refinement;
    ref.epsilon = epsilon_;
    ref.maxInsertions = insertionCapFor(options_.maxVertices, ref.maxInsertions);
    ref.ratioBound = options_.ratioBound;
    if (!ref.progress && options_.progress)
      ref.progress = [this](const RefineProgress& p) {
        say("refining: " + std::to_string(p.vertices) + " vertices, " + std::to_string(p.queuedTriangles) +
            " bad triangles queued");
      };
    return ref;
  }

  // === the uniformized route (the paper's)

  MeshRemeshResult runUniformized() const {
    const detail::SubdividedInput t0 = subdivideInput();
    MeshRemeshResult out;
    out.inputVertices = input_.mesh.nVertices();
    out.inputFaces = input_.mesh.nFaces();
    out.t0Vertices = t0.t0.mesh.nVertices();
    const Uniformization u = uniformizeT0(t0.t0, out);
    checkFlipLog(u, t0.t0);
    const RefineResult refined = refineUniformized(u, out);
    const auto t = std::chrono::steady_clock::now();
    say("pulling back " + std::to_string(refined.triangulation.mesh.nVertices()) + " vertices and " +
        std::to_string(refined.triangulation.mesh.nEdges()) + " edges through the input faces");
    detail::ImagePathPullBack pullBack(t0, u, refined, options_.extraBisections);
    pullBack.run(out);
    out.positions = positionsAt(input_, positions_, out.location);
    // Orientation of the map back, and the edges within one input face (on T0: with subdivisions, its faces).
    detail::checkAgainstLocations(t0.t0, out.mesh, pullBack.vertexImage(), out);
    out.quality = measureQuality(out.mesh);
    out.seconds.pullBack = secondsSinceStart(t);
    return out;
  }

  // T0: the input, midpoint-subdivided `inputSubdivisions` times, with each face's place in the input.
  detail::SubdividedInput subdivideInput() const {
    detail::SubdividedInput s;
    s.t0 = input_;
    s.parentFace.resize(input_.mesh.nFaces());
    s.parentCorner.resize(input_.mesh.nFaces());
    for (int f = 0; f < input_.mesh.nFaces(); ++f) {
      s.parentFace[f] = f;
      s.parentCorner[f] = {Eigen::Vector3d::Unit(0), Eigen::Vector3d::Unit(1), Eigen::Vector3d::Unit(2)};
    }
    for (int level = 0; level < options_.inputSubdivisions; ++level) {
      Subdivision sub = subdivide(s.t0);
      std::vector<int> face(sub.parentFace.size());
      std::vector<std::array<Eigen::Vector3d, 3>> corner(sub.parentFace.size());
      for (std::size_t f = 0; f < face.size(); ++f) {
        const int p = sub.parentFace[f];
        face[f] = s.parentFace[p];
        for (int k = 0; k < 3; ++k) {
          const Eigen::Vector3d& b = sub.corner[f][k];
          corner[f][k] = b[0] * s.parentCorner[p][0] + b[1] * s.parentCorner[p][1] + b[2] * s.parentCorner[p][2];
        }
      }
      s.t0 = std::move(sub.tri);
      s.parentFace = std::move(face);
      s.parentCorner = std::move(corner);
    }
    return s;
  }

  // T0 → T0*, λ and the correspondence, by discrete Ricci flow.
  Uniformization uniformizeT0(const IntrinsicTriangulation& t0, MeshRemeshResult& out) const {
    const auto t = std::chrono::steady_clock::now();
    UniformizationOptions uni = options_.uniformization;
    if (!uni.progress) uni.progress = options_.progress;
    say("uniformizing the input (" + std::to_string(t0.mesh.nVertices()) + " vertices) by discrete Ricci flow");
    Uniformization u = uniformize(t0, uni);
    out.uniformization = u.report;
    out.seconds.uniformize = secondsSinceStart(t);
    return u;
  }

  // The pull-back replays the flow's flip log once per bisection round, moving every point that sits in a flipped
  // face (flow_correspondence.h): its cost grows with the flips per edge. CGAL's data set needs at most
  // kMaxFlipsPerEdge (docs/robustness.md); lion.off's flow makes 5·10⁶ flips on 2.2·10⁴ edges (a flip cycle of the
  // flow), where the pull-back ran for hours and past 1.2 GB. Refused with the count, before refining.
  static constexpr double kMaxFlipsPerEdge = 50;
  // A circle domain with inserted boundary vertices (the half of the double) has no correspondence: refused too.
  void checkFlipLog(const Uniformization& u, const IntrinsicTriangulation& t0) const {
    const std::string gap = correspondenceUnavailable(u);
    if (!gap.empty())
      throw ConvergenceError("remesh: " + gap + "; use the default route --refine-in input");
    const double flips = static_cast<double>(u.correspondence.flips().size()), edges = t0.mesh.nEdges();
    if (flips <= kMaxFlipsPerEdge * edges) return;
    throw ConvergenceError("remesh: the flow made " + std::to_string(u.correspondence.flips().size()) +
                           " Ptolemy flips on " + std::to_string(t0.mesh.nEdges()) + " edges (" +
                           std::to_string(std::lround(flips / edges)) + " per edge, cap " +
                           std::to_string(std::lround(kMaxFlipsPerEdge)) +
                           "): the pull-back through that flip log would run away; use --refine-in input");
  }

  // T0* refined, graded by e^(−λ) (uniform with options.uniform).
  RefineResult refineUniformized(const Uniformization& u, MeshRemeshResult& out) const {
    const auto t = std::chrono::steady_clock::now();
    RefineOptions ref = refineOptions();
    if (!options_.uniform) ref.lambda = u.lambda;
    checkBudget(u.uniform, ref.lambda, out);
    say("refining the uniformized surface, eps = " + std::to_string(epsilon_));
    RefineResult refined = refineDelaunay(u.uniform, ref);
    noticeIfUnrefined(refined, epsilon_, out);
    out.refinement = refined.statistics;
    out.uniformQuality = measureQuality(refined.triangulation);
    out.seconds.refine = secondsSinceStart(t);
    return refined;
  }

  // === the input route: Delaunay refinement of the input in its own metric. The refiner flips the input to its
  // intrinsic Delaunay triangulation first and records every inserted vertex on the input's own faces, so the output
  // needs no map: its lengths are the refinement's, its locations the refinement's.

  MeshRemeshResult runInInputMetric() const {
    MeshRemeshResult out;
    out.refinedIn = RefineMetric::Input;
    out.inputVertices = out.t0Vertices = input_.mesh.nVertices();
    out.inputFaces = input_.mesh.nFaces();
    RefineResult refined = refineInInputMetric(out);
    const auto t = std::chrono::steady_clock::now();
    out.lambda = refined.lambda;  // λ ≡ 0: the refinement's metric is the input's
    const std::vector<Point> vertexImage = locateOnInput(refined, out);
    out.positions = positionsAt(input_, positions_, out.location);
    detail::checkAgainstLocations(input_, refined.triangulation, vertexImage, out,
                                  detail::signpostEdgeInFace(input_, refined));
    out.mesh = std::move(refined.triangulation);
    out.pathLength = out.mesh.edgeLengths;  // each edge is a geodesic of the input: its own path
    out.quality = measureQuality(out.mesh);
    out.uniformQuality = out.quality;
    out.seconds.pullBack = secondsSinceStart(t);
    return out;
  }

  RefineResult refineInInputMetric(MeshRemeshResult& out) const {
    const auto t = std::chrono::steady_clock::now();
    RefineOptions ref = refineOptions();
    ref.lambda.clear();
    // The input's boundary is a polygon of straight input edges: split it where it lies, never on a fitted circle
    // (which would put vertices off the input's faces).
    ref.boundarySplit = BoundarySplit::Geodesic;
    checkBudget(input_, {}, out);
    say("refining the input in its own metric, eps = " + std::to_string(epsilon_));
    RefineResult refined = refineDelaunay(input_, ref);
    noticeIfUnrefined(refined, epsilon_, out);
    out.refinement = refined.statistics;
    out.seconds.refine = secondsSinceStart(t);
    return refined;
  }

  // Each output vertex's point on the input (out.location, and as a Point for the checks).
  std::vector<Point> locateOnInput(const RefineResult& refined, MeshRemeshResult& out) const {
    const int n0 = input_.mesh.nVertices(), n1 = refined.triangulation.mesh.nVertices();
    out.location.resize(n1);
    std::vector<Point> vertexImage(n1);
    for (int v = 0; v < n1; ++v) {
      // Round-off may leave a coordinate of an inserted vertex at −1e-17; the output claims a point of its face.
      vertexImage[v] = v < n0 ? detail::vertexPoint(input_.mesh, v)
                              : Point{refined.locations[v].face, detail::clampToFace(refined.locations[v].bary)};
      const Eigen::Vector3d& b = vertexImage[v].bary;
      out.location[v] = {vertexImage[v].face, {b[0], b[1], b[2]}};
    }
    return vertexImage;
  }

  const IntrinsicTriangulation& input_;
  const std::vector<Eigen::Vector3d>& positions_;
  const MeshRemeshOptions& options_;
  double epsilon_ = 0;  // options.epsilon, or epsilonRelative · √(input area)
};

}  // namespace

std::string toString(RefineMetric metric) {
  return metric == RefineMetric::Input ? "input" : "uniformized";
}

RefineMetric parseRefineMetric(const std::string& name) {
  for (RefineMetric m : {RefineMetric::Uniformized, RefineMetric::Input})
    if (toString(m) == name) return m;
  throw InputError("refine metric '" + name + "' is not one of uniformized, input");
}

std::string MeshRemeshOptions::validate() const {
  if (epsilonRelative != 0 || !std::isfinite(epsilonRelative)) {
    if (!(epsilonRelative > 0) || !std::isfinite(epsilonRelative))
      return "remesh: --eps-rel must be a positive fraction of sqrt(area), found " + std::to_string(epsilonRelative);
    if (epsilon != 0) return "remesh: give --eps or --eps-rel, not both";
  } else if (!(epsilon > 0) || !std::isfinite(epsilon))
    return "remesh: --eps must be a positive size in the input mesh's units, found " + std::to_string(epsilon);
  if (inputSubdivisions < 0 || inputSubdivisions > 6)
    return "remesh: input subdivisions must be 0..6, found " + std::to_string(inputSubdivisions);
  if (refineIn != RefineMetric::Input) return "";
  // The input route is the default, so each message names the switch to the route the setting belongs to.
  if (inputSubdivisions != 0)
    return "remesh: input subdivisions apply when refining in the uniformized metric (--refine-in uniformized), not "
           "in the input's (found " +
           std::to_string(inputSubdivisions) + ")";
  if (uniform)
    return "remesh: --uniform (lambda = 0 in the uniformized domain) applies with --refine-in uniformized; refining "
           "in the input metric (the default for meshes), the size bound is uniform on the input already";
  if (refinement.boundarySplit == BoundarySplit::Circle)
    return "remesh: boundary splits on circles need the uniformized metric (--refine-in uniformized); the input's "
           "boundary is split at edge midpoints";
  return "";
}

MeshInput meshInputFromData(const MeshData& data) {
  if (data.background != Background::Euclidean)
    throw InputError(data.source + ": mesh remeshing needs a Euclidean input (flat faces); found a " +
                     std::string(data.background == Background::Spherical ? "spherical" : "hyperbolic") +
                     " background");
  MeshInput in;
  in.source = data.source;
  ConversionReport report;
  in.triangulation = toTriangulation(data, &report);
  if (!data.positions.empty()) {
    in.positions.resize(in.triangulation.mesh.nVertices());
    for (int v = 0; v < data.nVertices; ++v)
      if (report.vertexMap[v] != kInvalid) in.positions[report.vertexMap[v]] = data.positions[v];
  }
  return in;
}

MeshRemeshResult remeshMesh(const IntrinsicTriangulation& input, const std::vector<Eigen::Vector3d>& inputPositions,
                            const MeshRemeshOptions& options) {
  MeshRemeshPipeline pipeline(input, inputPositions, options);
  return pipeline.run();
}

// === the curvature-measure check

CurvatureMeasureResult meshCurvatureMeasure(const MeshRemeshResult& r, const IntrinsicTriangulation& input,
                                            const CurvatureMeasureOptions& options) {
  const HalfedgeMesh& m = r.mesh.mesh;
  const int n = m.nVertices(), n0 = input.mesh.nVertices();
  if (r.inputVertices != n0) throw InputError("curvature measure: the result is not a remeshing of this input");
  const std::vector<double> k1 = vertexCurvatures(r.mesh), k0 = vertexCurvatures(input);
  CurvatureMeasureResult c;
  c.radius = options.radiusFraction * std::sqrt(totalArea(r.mesh));
  c.discrete.assign(n, 0.0);
  c.smooth.assign(n, 0.0);
  c.absoluteScale.assign(n, 0.0);
  c.relativeError.assign(n, 0.0);
  c.histogram.assign(options.histogramBins, 0);
  for (double x : k0) c.smoothTotalCurvature += x;
  // Truncated Dijkstra from each vertex along the output's edges.
  std::vector<double> dist(n, INFINITY);
  std::vector<int> touched;
  using Item = std::pair<double, int>;
  int within = 0;
  for (int v = 0; v < n; ++v) {
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
    dist[v] = 0;
    touched.push_back(v);
    q.push({0.0, v});
    while (!q.empty()) {
      const auto [d, w] = q.top();
      q.pop();
      if (d > dist[w]) continue;
      c.discrete[v] += k1[w];
      if (w < n0) {
        c.smooth[v] += k0[w];
        c.absoluteScale[v] += std::abs(k0[w]);
      }
      const int h0 = m.vertexHalfedge(w);
      // Every outgoing halfedge of w, and for a boundary vertex the incoming boundary edge too.
      for (int h = h0;;) {
        for (int g : {h, HalfedgeMesh::prev(h)}) {
          const int x = g == h ? m.tip(h) : m.tail(g);
          const double nd = d + r.mesh.length(g);
          if (nd < c.radius && nd < dist[x]) {
            if (dist[x] == INFINITY) touched.push_back(x);
            dist[x] = nd;
            q.push({nd, x});
          }
        }
        h = m.nextOutgoing(h);
        if (h == kInvalid || h == h0) break;
      }
    }
    for (int w : touched) dist[w] = INFINITY;
    touched.clear();
    const double err = c.discrete[v] - c.smooth[v];
    c.meanAbsoluteError += std::abs(err) / n;
    c.maxAbsoluteError = std::max(c.maxAbsoluteError, std::abs(err));
    c.relativeError[v] = c.absoluteScale[v] > 0 ? err / c.absoluteScale[v] : 0.0;
    if (std::abs(c.relativeError[v]) < options.withinBand) ++within;
    const double x = (c.relativeError[v] + options.histogramRange) / (2 * options.histogramRange);
    const int bin = std::clamp(static_cast<int>(std::floor(x * options.histogramBins)), 0, options.histogramBins - 1);
    ++c.histogram[bin];
    if (options.progress && ((v + 1) % ((n + 99) / 100) == 0 || v + 1 == n)) options.progress(v + 1, n);
  }
  c.fractionWithinBand = n > 0 ? static_cast<double>(within) / n : 0.0;
  return c;
}

}  // namespace conformesh::refine
