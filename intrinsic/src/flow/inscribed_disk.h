// inscribed_disk.h (private) — the circle domain of a disk whose vertices all lie on its boundary (a triangulated
// polygon), developed face by face onto its circle by cross-ratios in quadruple precision instead of solved by the flow
// (docs/ricci_flow.md §3.3, "Disks without interior vertices"). Writes the metric's u and returns the lengths.
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/flow/discrete_conformal.h"

namespace conformesh::intrinsic::detail {

// Sets metric.u() (Euclidean background) so that every vertex lies on the unit circle: the development starts from the
// middle face of a longest dual path; each further face's new vertex is placed on the other arc of the edge it is
// reached across. Each face must be reached exactly once (the dual graph of a triangulated polygon is a tree).
// Returns the development's edge lengths (per edge of metric.mesh()), e^{(u_a+u_b)/2} ℓ⁰_ab computed from the
// quadruple-precision u and rounded once to double: what a length from the rounded u cannot be, since an ulp of u
// (|u| up to ≈ 12 at a crowded end) is ≈ 8× the rounding of the length itself.
// Throws ConvergenceError when a vertex is reached twice (not a triangulated polygon), or when a face is outside the
// triangle inequality with those lengths (a strip so long that its circle domain's chords are below what
// double-precision lengths resolve, ≈ 10⁻⁸ diameters; the message gives the shortest chord).
std::vector<double> inscribeDiskWithoutInterior(DiscreteConformalMetric& metric);

// When the flow's polish of such a development fails: `failed` with the reason added if it is round-off — the
// smallest corner angle θ of the developed disk (at `metric`'s u) makes double's error in the angle sums ≈ ε/θ
// (ε = 2.2·10⁻¹⁶; the corners near π of a crowded end move by that under a relative length change ε), and if that is
// within a factor 100 of `tolerance` the message says that the strip is too long to be resolved to the tolerance in
// double precision. Otherwise `failed` unchanged.
ConvergenceError explainInscribedFailure(const DiscreteConformalMetric& metric, double tolerance,
                                         const ConvergenceError& failed);

// For a disk with interior vertices whose flow failed (docs/ricci_flow.md §3.3, "Disks without interior vertices"):
// its faces with all three corners on the boundary, in parts joined across interior edges, are each (when a disk)
// a triangulated polygon whose circle domain is a Möbius image of that part of the whole disk's (its vertices lie on
// the circle there too, its faces are concyclic, and vertex scaling keeps its interior edges' cross-ratios). Each
// part is developed as above; returns why the first one that is not representable in double precision is not
// (its face count, a face of it in `reference`, its vertex count, the shortest chord), or "" when all are.
// `reference`: the disk's lengths at u = 0 (Euclidean Penner lengths).
std::string unrepresentableBoundaryPart(const IntrinsicTriangulation& reference);

}  // namespace conformesh::intrinsic::detail
