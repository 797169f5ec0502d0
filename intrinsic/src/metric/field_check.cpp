// field_check.cpp — the `field check` report (see field_check.h).
#include "conformesh/intrinsic/metric/field_check.h"

#include <cmath>
#include <limits>

#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"

namespace conformesh::intrinsic {

FieldCheckReport checkField(const SampledField& f) {
  const SampledMetric metric(f);  // runs checkFieldGridOrder, checkFieldPoles and the per-sample checks
  FieldCheckReport r;
  r.source = f.source, r.nu = f.nu, r.nv = f.nv;
  r.shape = toString(f.domain.shape());
  r.genus = f.domain.genus(), r.boundaryLoops = f.domain.boundaryLoops();
  r.eulerCharacteristic = f.domain.eulerCharacteristic();
  const QuadratureResult area = metricArea(metric), curvature = metricTotalCurvature(metric);
  r.area = area.value, r.areaError = area.errorEstimate;
  r.totalCurvature = curvature.value, r.totalCurvatureError = curvature.errorEstimate;
  r.gaussBonnet = r.boundaryLoops == 0 ? 2 * M_PI * r.eulerCharacteristic : std::numeric_limits<double>::quiet_NaN();
  const bool poles = f.domain.poleAtV0 && f.domain.poleAtV1;
  r.minDetG = std::numeric_limits<double>::infinity();
  r.minDetRegular = poles ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
  for (int j = 0; j < f.nv; ++j)
    for (int i = 0; i < f.nu; ++i) {
      const size_t k = static_cast<size_t>(j) * f.nu + i;
      const double det = f.guu[k] * f.gvv[k] - f.guv[k] * f.guv[k];
      if (det < r.minDetG) {
        r.minDetG = det, r.minDetNodeU = i, r.minDetNodeV = j;
        r.minDetLine = f.lines.empty() ? 0 : f.lines[k];
      }
      if (poles) {
        const double s = std::sin(f.nodeV(j));
        r.minDetRegular = std::min(r.minDetRegular, det / (s * s));
      }
    }
  return r;
}

}  // namespace conformesh::intrinsic
