// metrics.h — the Python Metric: a shared, immutable SmoothMetric.
#pragma once

#include <memory>

#include "bind_util.h"
#include "conformesh/intrinsic/metric/smooth_metric.h"

namespace conformesh::python {

struct Metric {
  std::shared_ptr<const intrinsic::SmoothMetric> metric;
};

void bindMetrics(py::module_& metrics);

}  // namespace conformesh::python
