// output_verification.h — what every command checks before it writes a mesh and exits 0: the output's lengths form
// triangles, its map back is not inverted, its lengths agree with its located vertices, its area is the input's (where
// it must be). Reads results only; never throws for a failed check (the command decides: exit 3, docs/cli.md).
// The tolerances and why: VerificationTolerances below.
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/metric_remesh.h"

namespace conformesh::refine {

struct VerificationTolerances {
  // Triangle inequalities are strict and exact (isValidTriangle of the background): a triangle whose lengths meet one
  // with equality has no angles, and a file with one cannot be read back (toTriangulation refuses it).
  // Same-face lengths: an edge whose two ends lie in one input face against their straight distance there, relative
  // to max(edge length, the face's longest side) — the located ends' round-off is relative to the face they are
  // written in. Relative to the edge alone: at most 3.0e-11 on cow.off down to ε = 0.005 (docs/cli.md); relative to
  // the face, at most 1e-12 over CGAL's data set at --eps-rel 0.05 (docs/robustness.md); the defects this catches are
  // 0.4–0.5. 1e-9 keeps a factor 30 above round-off (traces through ≲ 10⁴ faces, each unfolding ~1e-15).
  double sameFaceLength = 1e-9;
  // Area, relative, where the output is an exact retriangulation of the input (both mesh routes, refine): each face's
  // area has relative round-off ≲ 1e-14 (Heron's formula in the stable form, angles ≥ 1°), so a sum of F of them
  // ≲ 1e-14; 1e-9 stays far below the defects it catches (7e-5 – 2e-3 on the uniformized route).
  double area = 1e-9;
};

// The outcome: one line per failed check, naming the element and expected against found.
struct OutputVerification {
  std::vector<std::string> failures;
  int facesChecked = 0;
  double areaRelativeError = 0;  // (output − input) / input where the area must be kept; 0 otherwise
  bool passed() const { return failures.empty(); }
  std::string message() const;  // "output failed verification: " + the failures joined by "; "
};

// Both mesh routes (mesh_remesh.h): triangle inequalities of result.mesh, no inverted triangle on the input
// (result.invertedTriangles, naming the first), same-face lengths, area against `input`.
OutputVerification verifyMeshRemesh(const MeshRemeshResult& result, const intrinsic::IntrinsicTriangulation& input,
                                    const VerificationTolerances& tolerances = {});

// A smooth metric's remesh (metric_remesh.h): triangle inequalities and no inverted triangle in the map back to the
// chart. (Its area converges to the metric's at O(ε²); there is no equality to check.)
OutputVerification verifyMetricRemesh(const RemeshResult& result, const VerificationTolerances& tolerances = {});

// `refine`: triangle inequalities in the background, area equal to the input's (intrinsic refinement keeps the
// metric; not checked when a boundary loop is split on its circle, which adds the caps beyond its chords), every
// vertex located in a face of the input with finite barycentric coordinates.
OutputVerification verifyRefinement(const intrinsic::IntrinsicTriangulation& input, const RefineResult& result,
                                    const VerificationTolerances& tolerances = {});

// `uniformize`: triangle inequalities of T0* in its background and a finite λ at every vertex; for a circle domain
// with inserted boundary vertices (the half of the double, uniformization.h) also: each inserted vertex appended after
// the input's (ids V, V+1, …) and on the boundary, every boundary vertex on the unit circle to 1e-8, and the residual
// within the tolerance.
OutputVerification verifyUniformization(const intrinsic::Uniformization& u);

// The name under which a command writes an output that failed verification when asked to keep it:
// "out.ply" → "out.failed.ply" (the extension kept, so that readers still recognise the file).
std::string failedOutputName(const std::string& path);

}  // namespace conformesh::refine
