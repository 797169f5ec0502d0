// boundary_flattening.h — corner-aware flat uniformization of a topological disk: the flat metric conformal to the
// input that keeps every boundary edge's length (Dirichlet u = 0 on the boundary, zero curvature inside). Unlike the
// map to the unit disk (uniformization.h, CircleDomain), it has a bounded conformal factor up to the boundary, so the
// corners of a patch whose chart is a rectangle stay corners with their own angles instead of becoming z^{1/2}
// singularities of the map; the domain is the flat polygon whose sides are the input's boundary chords.
//
// Smooth statement (docs/refinement.md, "Surfaces whose boundary has corners"): g_flat = e^{-2λ} g with Δ_g λ = −K on
// the surface and λ = 0 on its boundary (a linear Poisson problem). λ is bounded and, at a convex corner, C¹ up to the
// corner, so every corner keeps its angle and the paper's grading ε·e^{−λ} (§4.2.3) stays bounded and Lipschitz.
#pragma once

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/flow/uniformization.h"

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
