// convergence_study.cpp — a sweep of remeshings at calibrated ε with the curvature-measure checks, intrinsic and (with
// an embedding) extrinsic (convergence_study.h).
#include "conformesh/refine/pipeline/convergence_study.h"

#include <chrono>
#include <cmath>
#include <memory>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;

std::vector<int> paperTable2Vertices() {
  return {1021, 2045, 4093, 6141, 8189, 10237, 12285, 14333, 16381, 18429, 21876};
}

std::string ConvergenceOptions::validate() const {
  if (targetVertices.size() < 2) return "convergence: give at least two target vertex counts to fit an order";
  for (int n : targetVertices)
    if (n < 10) return "convergence: target vertex count " + std::to_string(n) + " is too small";
  return "";
}

ConvergenceStudy runConvergenceStudy(const SmoothMetric& metric, const ConvergenceOptions& options) {
  const std::string problem = options.validate();
  if (!problem.empty()) throw InputError(problem);
  auto say = [&](const std::string& s) {
    if (options.progress) options.progress(s);
  };
  ConvergenceStudy study;
  study.metric = metric.description();
  QuadratureOptions areaQuadrature;
  areaQuadrature.absoluteTolerance = 1e-12;
  areaQuadrature.relativeTolerance = 1e-12;
  study.smoothArea = metricArea(metric, areaQuadrature).value;

  RemeshOptions base = options.remesh;
  if (!base.progress) base.progress = options.progress;
  base.epsilon = 1;  // set per level
  const UniformizedMetric prepared = uniformizeMetric(metric, base);
  study.uniformization = prepared.uniformization.report;
  study.t0Vertices = prepared.t0.mesh.nVertices();
  study.extrinsic = options.extrinsic && metric.hasEmbedding();
  std::unique_ptr<embedding::EmbeddedSurface> surface;
  if (study.extrinsic) surface = std::make_unique<embedding::EmbeddedSurface>(metric);

  // Vertex counts scale like area / (c ε²); c is learnt from each run (≈ 1.1 for Ruppert-quality meshes).
  double c = 1.1;
  for (size_t level = 0; level < options.targetVertices.size(); ++level) {
    const int target = options.targetVertices[level];
    const auto t0 = std::chrono::steady_clock::now();
    RemeshOptions o = base;
    o.progress = nullptr;
    RemeshResult r;
    for (int attempt = 0; attempt < 2; ++attempt) {
      o.epsilon = std::sqrt(study.smoothArea / (c * target));
      say("level " + std::to_string(level + 1) + "/" + std::to_string(options.targetVertices.size()) + ": target " +
          std::to_string(target) + " vertices, eps = " + std::to_string(o.epsilon));
      r = remeshUniformized(prepared, metric, o);
      const int n = r.mesh.mesh.nVertices();
      c = study.smoothArea / (n * o.epsilon * o.epsilon);
      if (std::abs(n - target) <= options.calibrationTolerance * target) break;
    }
    ConvergenceLevel L;
    L.targetVertices = target;
    L.vertices = r.mesh.mesh.nVertices();
    L.triangles = r.mesh.mesh.nFaces();
    L.epsilon = o.epsilon;
    L.quality = r.quality;
    L.invertedTriangles = r.invertedTriangles;
    L.totalArea = totalArea(r.mesh);
    L.measure = gaussianCurvatureMeasure(r.mesh, r.reference, metric, options.measure);
    if (level + 1 < options.targetVertices.size()) {
      // Keep only the summary of coarser levels; the finest level's per-vertex values feed Fig. 12.
      L.measure.discrete.clear();
      L.measure.smooth.clear();
      L.measure.absoluteScale.clear();
      L.measure.relativeError.clear();
    }
    if (study.extrinsic) {
      L.meanCurvature =
          embedding::meanCurvatureMeasure(r.mesh, r.positions, r.reference, *surface, options.meanCurvature);
      L.deviation = embedding::surfaceDeviation(r.mesh.mesh, r.positions, r.reference, *surface, options.projection);
      if (level + 1 < options.targetVertices.size()) {
        L.meanCurvature.discrete.clear();
        L.meanCurvature.smooth.clear();
        L.meanCurvature.absoluteScale.clear();
        L.meanCurvature.relativeError.clear();
      }
      say("  e_H = " + std::to_string(L.meanCurvature.meanAbsoluteError) + ", Hausdorff " +
          std::to_string(L.deviation.hausdorffClosest) + ", normal deviation " +
          std::to_string(L.deviation.normalDeviation) + " rad");
    }
    L.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    say("  " + std::to_string(L.vertices) + " vertices: e_G = " + std::to_string(L.measure.meanAbsoluteError) +
        ", smallest angle " + std::to_string(L.quality.minAngleDeg) + " deg");
    study.levels.push_back(std::move(L));
  }

  std::vector<double> vertices, radius, error, areaError, errorH, hausdorff, normal;
  for (const auto& L : study.levels) {
    vertices.push_back(L.vertices);
    radius.push_back(L.quality.meanCircumradius);
    error.push_back(L.measure.meanAbsoluteError);
    areaError.push_back(std::abs(L.totalArea - study.smoothArea));
    errorH.push_back(L.meanCurvature.meanAbsoluteError);
    hausdorff.push_back(L.deviation.hausdorffClosest);
    normal.push_back(L.deviation.normalDeviation);
  }
  if (study.extrinsic) {
    study.orderMeanCurvatureVsCircumradius = fitLogLogSlope(radius, errorH);
    study.orderHausdorffVsCircumradius = fitLogLogSlope(radius, hausdorff);
    study.orderNormalDeviationVsCircumradius = fitLogLogSlope(radius, normal);
  }
  study.orderErrorVsCircumradius = fitLogLogSlope(radius, error);
  study.orderCircumradiusVsVertices = fitLogLogSlope(vertices, radius);
  study.orderAreaVsCircumradius = fitLogLogSlope(radius, areaError);
  return study;
}

}  // namespace conformesh::refine
