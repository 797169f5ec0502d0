// family_checks.h — private helpers shared by the metric families and their registry: the shortest decimal spelling
// of a parameter (for descriptions and messages) and the InputError naming a family's violated constraint.
// Touches nothing but strings; no state.
#pragma once

#include <sstream>
#include <string>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic::metric_detail {

// Shortest decimal (15 digits, else 17) that reads back as x, so that descriptions show "f=0.9", not
// "f=0.90000000000000002".
inline std::string fmt(double x) {
  for (int digits : {15, 17}) {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    if (digits == 17 || std::stod(s.str()) == x) return s.str();
  }
  return "";
}

inline void require(bool ok, const std::string& family, const std::string& what) {
  if (!ok) throw InputError("metric family '" + family + "': " + what);
}

}  // namespace conformesh::intrinsic::metric_detail
