// boundary_flattening.h — corner-aware flat uniformization of a topological disk: the flat metric conformal to the
// input that keeps every boundary edge's length (Dirichlet u = 0 on the boundary, zero curvature inside). Unlike the
// map to the unit disk (uniformization.h, CircleDomain) its conformal factor is bounded up to the boundary, so the
// corners of a patch keep their angles; the domain is the flat polygon of the input's boundary chords.
//
// Reads its input only; runs solveConformalFlow on a copy. The smooth statement (Δ_g λ = −K, λ = 0 on the boundary):
// docs/refinement.md, "Surfaces whose boundary has corners".
#pragma once

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic {

// Flattens `input` (any background; its Penner lengths are its chords, as in uniformize) keeping its boundary: the
// discrete Ricci flow of vertex scaling with u = 0 held at every boundary vertex and angle sum 2π at every interior
// vertex, Delaunay (Ptolemy) flips included. Returns T0* (Euclidean, boundary edges of the input's chord lengths),
// λ = −u (0 on the boundary), the correspondence T0* → T0, planar positions of a layout (z = 0) and a report with
// target FlatKeepBoundary. options.flow and options.progress are used; the genus-0 and centring options are not.
// Throws InputError unless the input is one connected component of genus 0 with exactly one boundary loop (a
// topological disk), naming what was found; ConvergenceError when the flow does not converge.
Uniformization flattenKeepingBoundary(const IntrinsicTriangulation& input, const UniformizationOptions& options = {});

}  // namespace conformesh::intrinsic
