// convergence_study.h — the paper's experiment (§6, Table 2, Figs. 10–12) on any smooth metric: remesh one
// uniformization at a sequence of ε calibrated to hit target vertex counts, measure each mesh's quality in the original
// metric and its Gaussian-curvature-measure error e_G (and, with an embedding, the extrinsic checks), and fit the
// orders: e_G against the mean circumradius (Theorem 3.4: ≥ 1), the mean circumradius against the vertex count
// (−1/2, Fig. 10b), the area error against the mean circumradius (2). Built on metric_remesh.h; no files.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "conformesh/embedding/extrinsic/mean_curvature_measure.h"
#include "conformesh/embedding/extrinsic/surface_projection.h"
#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/measure/convergence_order.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/refine/pipeline/metric_remesh.h"

namespace conformesh::refine {

// The vertex counts of the paper's Table 2 (T1 … T11).
std::vector<int> paperTable2Vertices();

struct ConvergenceOptions {
  std::vector<int> targetVertices = paperTable2Vertices();
  // Pipeline settings shared by every level (epsilon is chosen per level): T0 at resolution 10, below the smallest
  // target, so that every level refines one T0; one smoothing pass (0 is the paper's study; docs/studies.md).
  RemeshOptions remesh = [] {
    RemeshOptions r;
    r.t0Resolution = 10;
    r.refinement.smoothingPasses = 1;
    return r;
  }();
  intrinsic::CurvatureMeasureOptions measure;
  // The extrinsic checks, when the metric has an embedding: the mean curvature measure (paper eq. 2), the Hausdorff
  // distance and the normal deviation (Lemmas 4.8, 4.9). Off by default; `conformesh convergence` turns them on.
  bool extrinsic = false;
  embedding::MeanCurvatureMeasureOptions meanCurvature;
  embedding::ProjectionOptions projection;
  // A level whose vertex count misses its target by more than this fraction is remeshed once more at a corrected ε
  // (vertex counts scale like ε⁻²).
  double calibrationTolerance = 0.15;
  std::function<void(const std::string&)> progress;

  // What is wrong with these options ("" when valid): at least three target vertex counts (a least-squares order over
  // two points is just their slope), each at least 10, strictly increasing.
  std::string validate() const;
};

struct ConvergenceLevel {
  int targetVertices = 0, vertices = 0, triangles = 0;
  double epsilon = 0;
  QualityReport quality;  // in the original metric
  int invertedTriangles = 0;
  double totalArea = 0;
  intrinsic::CurvatureMeasureResult measure;  // per-vertex vectors are kept only for the finest level
  // Only when ConvergenceStudy::extrinsic (per-vertex vectors kept only for the finest level, as above).
  embedding::MeanCurvatureMeasureResult meanCurvature;
  embedding::SurfaceDeviation deviation;
  double seconds = 0;
};

struct ConvergenceStudy {
  std::string metric;
  double smoothArea = 0;  // ∫ dA of the metric over its chart (adaptive quadrature)
  intrinsic::UniformizationReport uniformization;
  int t0Vertices = 0;
  std::vector<ConvergenceLevel> levels;
  // Least-squares slopes of the log–log data over all levels, each strictly finer than the one before (more vertices
  // and a smaller mean circumradius; runConvergenceStudy refuses a study where it is not, so no point repeats).
  double orderErrorVsCircumradius = 0;     // log e_G against log mean circumradius
  double orderCircumradiusVsVertices = 0;  // log mean circumradius against log vertices
  double orderAreaVsCircumradius = 0;      // log |area − smooth area| against log mean circumradius
  // With an embedding (extrinsic = true): e_H (Theorem 3.4: ≥ 1), the Hausdorff distance max |q − π(q)| (Lemma 4.9:
  // 2) and the largest normal deviation (Lemma 4.9: 1), each against the mean circumradius.
  bool extrinsic = false;
  double orderMeanCurvatureVsCircumradius = 0;
  double orderHausdorffVsCircumradius = 0;
  double orderNormalDeviationVsCircumradius = 0;
};

// The options' targets do not give a sequence of ever finer meshes (runConvergenceStudy): a mistake in the request,
// which `conformesh convergence` reports as a usage error (exit status 2).
class UnrefinedLevelError : public InputError {
 public:
  using InputError::InputError;
};

// Runs the study. Throws InputError with options.validate()'s text; UnrefinedLevelError when a level's mesh is not
// finer than the previous level's (as many vertices or fewer, or a mean circumradius not smaller: targets near or below
// T0's vertex count all give T0 itself), naming the level, its target, T0's vertex count and a fix (a coarser
// --t0-resolution whose T0 has at most half the smallest target's vertices, or larger targets); and what
// remeshUniformized throws.
ConvergenceStudy runConvergenceStudy(const intrinsic::SmoothMetric& metric, const ConvergenceOptions& options = {});

}  // namespace conformesh::refine
