// convergence_study.cpp — a sweep of remeshings at calibrated ε with the curvature-measure checks, intrinsic and (with
// an embedding) extrinsic (convergence_study.h). The class ConvergenceRun names the steps: prepare the shared T0,
// remesh each level at a calibrated ε, measure it, require it finer than the level before, fit the orders.
#include "conformesh/refine/pipeline/convergence_study.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_discretization.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;

std::vector<int> paperTable2Vertices() {
  return {1021, 2045, 4093, 6141, 8189, 10237, 12285, 14333, 16381, 18429, 21876};
}

std::string ConvergenceOptions::validate() const {
  if (targetVertices.size() < 3)
    return "convergence: give at least three target vertex counts (found " + std::to_string(targetVertices.size()) +
           "): an order is fitted by least squares, and two points always lie on a line";
  for (size_t i = 0; i < targetVertices.size(); ++i) {
    const int n = targetVertices[i];
    if (n < 10) return "convergence: target vertex count " + std::to_string(n) + " is too small";
    if (i > 0 && n <= targetVertices[i - 1])
      return "convergence: target vertex counts must increase: level " + std::to_string(i + 1) + "'s " +
             std::to_string(n) + " follows " + std::to_string(targetVertices[i - 1]);
  }
  return "";
}

namespace {

std::string fourDigits(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.4g", x);
  return s;
}

// The finest T0 coarser than the study's whose vertex count is at most half the smallest target, so that every level
// refines it; {0, 0} when even resolution 2 is too fine. Discretizing small T0s takes milliseconds.
struct T0Suggestion {
  int resolution = 0, vertices = 0;
};
T0Suggestion suggestCoarserT0(const SmoothMetric& metric, const RemeshOptions& remesh, int smallestTarget) {
  DiscretizationOptions disc = remesh.discretization;
  for (int r = remesh.t0Resolution > 0 ? remesh.t0Resolution - 1 : 32; r >= 2; --r) {
    disc.resolution = r;
    const int n = discretizeMetric(metric, disc).nVertices;
    if (2 * n <= smallestTarget) return {r, n};
  }
  return {};
}

class ConvergenceRun {
 public:
  ConvergenceRun(const SmoothMetric& metric, const ConvergenceOptions& options) : metric_(metric), options_(options) {}

  ConvergenceStudy run() {
    prepare();
    for (size_t level = 0; level < options_.targetVertices.size(); ++level) {
      const auto t0 = std::chrono::steady_clock::now();
      double epsilon = 0;
      const RemeshResult r = calibratedRemesh(level, epsilon);
      ConvergenceLevel L = measure(level, r, epsilon);
      L.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      say("  " + std::to_string(L.vertices) + " vertices: e_G = " + std::to_string(L.measure.meanAbsoluteError) +
          ", smallest angle " + std::to_string(L.quality.minAngleDeg) + " deg");
      if (level > 0) requireFiner(level, L, study_.levels.back());
      study_.levels.push_back(std::move(L));
    }
    fitOrders();
    return std::move(study_);
  }

 private:
  void say(const std::string& s) const {
    if (options_.progress) options_.progress(s);
  }
  bool finest(size_t level) const { return level + 1 == options_.targetVertices.size(); }

  // The smooth area, the one T0 every level refines and its uniformization, and the embedding's surface.
  void prepare() {
    study_.metric = metric_.description();
    QuadratureOptions areaQuadrature;
    areaQuadrature.absoluteTolerance = 1e-12;
    areaQuadrature.relativeTolerance = 1e-12;
    study_.smoothArea = metricArea(metric_, areaQuadrature).value;
    base_ = options_.remesh;
    if (!base_.progress) base_.progress = options_.progress;
    base_.epsilon = 1;  // set per level
    prepared_ = uniformizeMetric(metric_, base_);
    study_.uniformization = prepared_.uniformization.report;
    study_.t0Vertices = prepared_.t0.mesh.nVertices();
    study_.extrinsic = options_.extrinsic && metric_.hasEmbedding();
    if (study_.extrinsic) surface_ = std::make_unique<embedding::EmbeddedSurface>(metric_);
  }

  // Vertex counts scale like area / (c ε²); c is learnt from each run (≈ 1.1 for Ruppert-quality meshes). A run that
  // inserted nothing returned T0 for any ε above T0's largest circumradius R₀: its ε says nothing, R₀ gives c.
  RemeshResult calibratedRemesh(size_t level, double& epsilon) {
    const int target = options_.targetVertices[level];
    RemeshOptions o = base_;
    o.progress = nullptr;
    RemeshResult r;
    for (int attempt = 0; attempt < 2; ++attempt) {
      o.epsilon = std::sqrt(study_.smoothArea / (c_ * target));
      say("level " + std::to_string(level + 1) + "/" + std::to_string(options_.targetVertices.size()) + ": target " +
          std::to_string(target) + " vertices, eps = " + std::to_string(o.epsilon));
      r = remeshUniformized(prepared_, metric_, o);
      const int n = r.mesh.mesh.nVertices();
      const bool close = std::abs(n - target) <= options_.calibrationTolerance * target;
      if (n <= study_.t0Vertices) {
        // T0 itself: ε is above every circumradius of T0. Refinement starts just below T0's largest, where the mesh
        // still has about n vertices; scale from there.
        if (close || target < n) break;
        c_ = study_.smoothArea / (n * r.quality.maxCircumradius * r.quality.maxCircumradius);
        continue;
      }
      c_ = study_.smoothArea / (n * o.epsilon * o.epsilon);
      if (close) break;
    }
    epsilon = o.epsilon;
    return r;
  }

  // The level's quality, e_G and (with an embedding) the extrinsic checks; per-vertex vectors only for the finest.
  ConvergenceLevel measure(size_t level, const RemeshResult& r, double epsilon) const {
    ConvergenceLevel L;
    L.targetVertices = options_.targetVertices[level];
    L.vertices = r.mesh.mesh.nVertices();
    L.triangles = r.mesh.mesh.nFaces();
    L.epsilon = epsilon;
    L.quality = r.quality;
    L.invertedTriangles = r.invertedTriangles;
    L.totalArea = totalArea(r.mesh);
    L.measure = gaussianCurvatureMeasure(r.mesh, r.reference, metric_, options_.measure);
    if (!finest(level)) {  // the finest level's per-vertex values feed Fig. 12
      L.measure.discrete.clear();
      L.measure.smooth.clear();
      L.measure.absoluteScale.clear();
      L.measure.relativeError.clear();
    }
    if (!study_.extrinsic) return L;
    L.meanCurvature =
        embedding::meanCurvatureMeasure(r.mesh, r.positions, r.reference, *surface_, options_.meanCurvature);
    L.deviation = embedding::surfaceDeviation(r.mesh.mesh, r.positions, r.reference, *surface_, options_.projection);
    if (!finest(level)) {
      L.meanCurvature.discrete.clear();
      L.meanCurvature.smooth.clear();
      L.meanCurvature.absoluteScale.clear();
      L.meanCurvature.relativeError.clear();
    }
    say("  e_H = " + std::to_string(L.meanCurvature.meanAbsoluteError) + ", Hausdorff " +
        std::to_string(L.deviation.hausdorffClosest) + ", normal deviation " +
        std::to_string(L.deviation.normalDeviation) + " rad");
    return L;
  }

  // A level no finer than the one before (as many vertices or fewer, or a mean circumradius not smaller) would repeat
  // a point of the log–log fits: refuse, naming the level and a T0 or targets that work.
  void requireFiner(size_t level, const ConvergenceLevel& L, const ConvergenceLevel& previous) const {
    if (L.vertices > previous.vertices && L.quality.meanCircumradius < previous.quality.meanCircumradius) return;
    const int smallest = options_.targetVertices.front();
    const T0Suggestion coarser = suggestCoarserT0(metric_, base_, smallest);
    const std::string resolution =
        base_.t0Resolution > 0 ? "resolution " + std::to_string(base_.t0Resolution) : "automatic resolution";
    std::string fix = "give targets from " + std::to_string(2 * study_.t0Vertices) + " vertices up";
    if (coarser.resolution > 0)
      fix = "give --t0-resolution " + std::to_string(coarser.resolution) + " (a T0 of " +
            std::to_string(coarser.vertices) + " vertices, at most half the smallest target " +
            std::to_string(smallest) + ") or " + fix;
    throw UnrefinedLevelError("convergence: level " + std::to_string(level + 1) + " (target " +
                     std::to_string(L.targetVertices) + " vertices) is not finer than level " + std::to_string(level) +
                     ": " + std::to_string(L.vertices) + " vertices, mean circumradius " +
                     fourDigits(L.quality.meanCircumradius) + ", against " + std::to_string(previous.vertices) +
                     " and " + fourDigits(previous.quality.meanCircumradius) + ". Every level refines one T0, of " +
                     std::to_string(study_.t0Vertices) + " vertices (" + resolution +
                     "), and refinement only adds vertices, so targets near or below it repeat T0; " + fix);
  }

  // Least-squares slopes of the log–log data over all levels (each strictly finer than the last: requireFiner).
  void fitOrders() {
    std::vector<double> vertices, radius, error, areaError, errorH, hausdorff, normal;
    for (const auto& L : study_.levels) {
      vertices.push_back(L.vertices);
      radius.push_back(L.quality.meanCircumradius);
      error.push_back(L.measure.meanAbsoluteError);
      areaError.push_back(std::abs(L.totalArea - study_.smoothArea));
      errorH.push_back(L.meanCurvature.meanAbsoluteError);
      hausdorff.push_back(L.deviation.hausdorffClosest);
      normal.push_back(L.deviation.normalDeviation);
    }
    if (study_.extrinsic) {
      study_.orderMeanCurvatureVsCircumradius = fitLogLogSlope(radius, errorH);
      study_.orderHausdorffVsCircumradius = fitLogLogSlope(radius, hausdorff);
      study_.orderNormalDeviationVsCircumradius = fitLogLogSlope(radius, normal);
    }
    study_.orderErrorVsCircumradius = fitLogLogSlope(radius, error);
    study_.orderCircumradiusVsVertices = fitLogLogSlope(vertices, radius);
    study_.orderAreaVsCircumradius = fitLogLogSlope(radius, areaError);
  }

  const SmoothMetric& metric_;
  const ConvergenceOptions& options_;
  ConvergenceStudy study_;
  RemeshOptions base_;
  UniformizedMetric prepared_;
  std::unique_ptr<embedding::EmbeddedSurface> surface_;
  double c_ = 1.1;
};

}  // namespace

ConvergenceStudy runConvergenceStudy(const SmoothMetric& metric, const ConvergenceOptions& options) {
  const std::string problem = options.validate();
  if (!problem.empty()) throw InputError(problem);
  return ConvergenceRun(metric, options).run();
}

}  // namespace conformesh::refine
