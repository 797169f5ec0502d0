// extended_angles.h — angle sums of a Euclidean vertex-scaling metric in extended precision (long double) at u + δu,
// for the precision fallback of the Newton flow (newton_flow.cpp, polishInExtendedPrecision). Private to the flow;
// reads the metric only. docs/ricci_flow.md §2 "Where double precision runs out".
#pragma once

#include <vector>

#include "conformesh/intrinsic/flow/discrete_conformal.h"

namespace conformesh::intrinsic::detail {

// Per vertex Σ of corner angles over the non-frozen faces, every edge length e^{(U_i+U_j)/2} c⁰_ij and every angle
// computed in long double, U_v = u_v + du[v] (du: one entry per vertex, the correction that double cannot hold). A
// face violating the triangle inequality gets the flow's extension (π, 0, 0). Euclidean background only (the caller
// checks). `sums` gets one entry per vertex.
void extendedAngleSums(const DiscreteConformalMetric& metric, const std::vector<long double>& du,
                       std::vector<long double>& sums);

}  // namespace conformesh::intrinsic::detail
