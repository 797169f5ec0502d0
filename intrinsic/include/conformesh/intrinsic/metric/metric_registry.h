// metric_registry.h — the name registry of the built-in metric families: what each family is called, its parameters
// with defaults and meanings (what `conformesh discretize --list` prints), and makeMetric, which builds a family from
// `key=value` parameters. Depends on metric_families.h and teapot_data.h (downward only); the families know nothing of
// the registry. A new family is added here: one FamilyInfo entry and one line in makeMetric.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "conformesh/intrinsic/metric/metric_families.h"

namespace conformesh::intrinsic {

struct FamilyParameter {
  std::string name;
  double defaultValue;
  std::string meaning;
};
struct FamilyInfo {
  std::string name;
  std::string summary;  // what the surface is, its chart, topology and closed forms
  std::vector<FamilyParameter> parameters;
};

// Every family makeMetric knows, with its parameters and their defaults (what `conformesh discretize --list` prints).
const std::vector<FamilyInfo>& metricFamilies();

// Builds family `name` with `params` (missing ones take their defaults). Throws InputError naming the family and the
// parameter for an unknown family, an unknown parameter, or a value outside the family's range.
std::unique_ptr<SmoothMetric> makeMetric(const std::string& name, const std::map<std::string, double>& params = {});

}  // namespace conformesh::intrinsic
