// mesh_remesh.h — the whole pipeline for a surface given by a TRIANGLE MESH (a file: positions, or a metric-only PLY
// with edge lengths): uniformize the input T0 by discrete Ricci flow (T0*, conformal factor λ) → Delaunay refinement
// of T0* graded by e^(−λ) (T1*) → pull back through the INPUT FACES: each output vertex gets its input face and
// barycentric coordinates, and each output edge the length of its image path across the input faces, measured in the
// input's own flat metric.
//
// The image path: the correspondence T0* → T0 (flow_correspondence.h) is projective on each cell (uniform face ∩
// flipped input face). A piece of an output edge inside one T0* face maps to a geodesic of the decorated ideal
// surface, which is straight in the projective coordinates of every input face it crosses, i.e. straight inside each
// flat input face; it bends where it crosses an input edge or a T0* edge. Its crossings with input edges are found
// exactly. The output length is the distance between the path's ends in its DEVELOPMENT (the faces it crosses
// unfolded into the plane): equal to the sum of the straight pieces where the path does not bend, and — because an
// output triangle's image contains no input vertex, so its three paths develop consistently — always the side of a
// flat triangle, whereas the sum of pieces is not (the map's derivative jumps by O(1) across cells of a coarse input,
// and a bent side can exceed the other two). docs/ricci_flow.md §5, docs/cli.md.
//
// That is the paper's route (RefineMetric::Uniformized). Its angle bound holds in the uniformized metric only: the
// pull-back's angle distortion on an input face is fixed by T0 and T0* and does not shrink under refinement (Theorems
// 3.3/3.4 assume a smooth metric, not a polyhedral one; docs/studies.md (e)). The other route (RefineMetric::Input)
// refines T0 itself, in its own flat cone metric: the input is Lawson-flipped to its intrinsic Delaunay triangulation
// and Delaunay-refined with size bound ε uniform on the input and shape bound B; the cone points are the input's
// vertices, which the refinement keeps (signposts carry directions at them), and every inserted vertex is flat. No
// Ricci flow and no pull-back map are involved: the output's lengths are the refined triangulation's own, which ARE
// the input metric, so Ruppert's bound holds for the angles measured in it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"

namespace conformesh::refine {

// The metric the Delaunay refinement runs in (mesh_remesh.h, top).
enum class RefineMetric {
  Uniformized,  // the paper's: refine T0* (constant curvature) graded by e^(−λ), pull back through the input faces
  Input,        // the input's own flat cone metric: refine T0 itself, uniform size bound ε
};
std::string toString(RefineMetric metric);                // "uniformized", "input"
RefineMetric parseRefineMetric(const std::string& name);  // InputError naming the value otherwise

struct MeshRemeshOptions {
  // Size bound ε in the INPUT's metric: circumradii of T1* are at most ε·e^(−λ) in the uniformized metric, i.e.
  // ≈ ε on the input (paper §4.2.3). Required, > 0.
  double epsilon = 0;
  // Shape bound B (circumradius / shortest edge) of the refinement; see RefineOptions::ratioBound.
  double ratioBound = 1.4142135623730951;
  RefineMetric refineIn = RefineMetric::Uniformized;
  // λ ≡ 0: uniform in the uniformized domain (not on the input); for comparisons only. Uniformized route only.
  bool uniform = false;
  // Midpoint (1-to-4) subdivisions of the input before uniformizing: T0 is then the same flat surface with the same
  // curvature atoms, but finer. The pull-back map T0* → T0 is projective on each face with weights e^(−λ) at its
  // corners, so its angle distortion on a face grows with the spread of λ over the face; subdividing divides that
  // spread (≈ by 2 per level away from the cone vertices) at 4× the faces. 0..6; uniformized route only (on the
  // input route subdivision vertices would be kept by the refinement and only add vertices).
  int inputSubdivisions = 0;
  intrinsic::UniformizationOptions uniformization;
  // Passed through to the refinement (epsilon, ratioBound and lambda are set from the fields above). On the input
  // route boundary edges are split at their midpoints (the input's boundary is its polygon, not a circle:
  // BoundarySplit::Circle is an InputError there) and `smoothingPasses` smooths in the input metric, where inserted
  // vertices are flat points.
  RefineOptions refinement;
  // Halve every straight piece of every output edge this many times before measuring its image. The image of a piece
  // inside one T0* face is one geodesic of the decorated surface, so the lengths must not change (to round-off): a
  // check of the exact edge crossings, for tests. 0 = only where the two ends are not in one or two adjacent faces.
  int extraBisections = 0;
  std::function<void(const std::string&)> progress;
};

struct MeshRemeshTimes {
  double uniformize = 0, refine = 0, pullBack = 0;  // input route: uniformize = 0, pullBack = locations and checks
};

struct MeshRemeshResult {
  RefineMetric refinedIn = RefineMetric::Uniformized;
  // T1: connectivity of T1*, lengths = developed lengths of the edges' image paths on the input (Euclidean). On the
  // input route: the refined triangulation itself, with its own lengths.
  intrinsic::IntrinsicTriangulation mesh;
  // Per output vertex: its input face and barycentric coordinates (affine in the flat input face). Vertices
  // 0 .. inputVertices−1 are the input's own vertices (refinement only adds vertices), then T0's edge midpoints.
  std::vector<intrinsic::FacePoint> location;
  std::vector<Eigen::Vector3d> positions;  // per output vertex, interpolated on the input; empty without positions
  std::vector<double> lambda;              // per output vertex: λ interpolated at its place on T0* (input route: 0)
  int inputVertices = 0, inputFaces = 0;
  int t0Vertices = 0;  // vertices of T0 (the input after subdivision): output vertices 0 .. t0Vertices−1
  // Output triangles whose three vertices can be written in one input face (one face, or a vertex or a point on a side
  // re-expressed in a neighbouring face) with a negative or zero orientation there, and how many could be checked so;
  // triangles spread wider are not checked one by one (the exact area and deficits of T1 check them globally).
  int invertedTriangles = 0, orientationChecked = 0;
  // Output edges whose two ends can be written in one input face (as above), and the largest relative difference
  // between the edge's length and the straight distance of its located ends in that face. On the input route the two
  // are independent: the length comes from the refinement's flips and insertions, the locations from tracing each
  // inserted vertex's geodesic across the input (input_location.h).
  int sameFaceEdges = 0;
  double maxSameFaceLengthError = 0;
  // Output edges from a vertex to itself: geodesic loops around a cone vertex of angle below π (the intrinsic Delaunay
  // triangulation of a cone metric may contain them; the PLY then has faces with a repeated vertex). Neither they nor
  // their triangles enter the two checks above.
  int loopEdges = 0;
  // The image paths (uniformized route; on the input route every edge is its own path: pathLength = its length,
  // pathPieces = inputEdgeCrossings = 0 and edgePieces empty): straight pieces measured (pieces of an edge inside one
  // T0* face are halved until their ends lie in one input face or two adjacent ones), crossings of input edges, and the
  // largest excess over all edges of the path length (the sum of its straight pieces) over the developed length used
  // for T1 (0 where the path is straight).
  std::int64_t pathPieces = 0;
  std::vector<int> edgePieces;     // per output edge (1: one straight piece in one input face)
  std::vector<double> pathLength;  // per output edge: the sum of its image path's straight pieces
  std::int64_t inputEdgeCrossings = 0;
  double maxBendExcess = 0;
  intrinsic::UniformizationReport uniformization;  // uniformized route only
  RefineStatistics refinement;
  QualityReport uniformQuality;  // of T1* in its background metric (input route: T1* = T1, the same as quality)
  QualityReport quality;         // of T1 in the input metric
  MeshRemeshTimes seconds;
};

// Remeshes `input` (Euclidean background; one connected component). `positions`, per input vertex, may be empty;
// when given they are only interpolated at the output vertices (lengths come from `input`). Throws InputError for bad
// parameters or input (naming them), ConvergenceError when a stage does not converge.
MeshRemeshResult remeshMesh(const intrinsic::IntrinsicTriangulation& input,
                            const std::vector<Eigen::Vector3d>& positions, const MeshRemeshOptions& options);

// Reads a mesh file's data into the input of remeshMesh: the triangulation (validated by toTriangulation, which names
// the file and the element on non-manifold connectivity, NaN coordinates, bad lengths) and the positions of its
// vertices (empty for a metric-only file). Throws InputError for a non-Euclidean background.
struct MeshInput {
  intrinsic::IntrinsicTriangulation triangulation;
  std::vector<Eigen::Vector3d> positions;
  std::string source;
};
MeshInput meshInputFromData(const intrinsic::MeshData& data);

// The Gaussian-curvature-measure check for a mesh input (the analogue of paper eq. 5): for each output vertex v and
// B_v = the output vertices within output graph distance r of v (Dijkstra along edges, r = radiusFraction·√area),
// φ_T1(B_v) = Σ angle deficits of T1 over B_v and the reference φ_T0(η(B_v)) = Σ angle deficits OF THE INPUT at the
// input vertices in B_v — the input's own curvature measure (a sum of atoms at its vertices, which are output
// vertices the map fixes) over the region B_v maps to. Boundary vertices carry their turning angles. The relative
// error is normalised by Σ |input deficit| over B_v. Both measures total 2πχ; what differs is how T1 spreads each
// input atom over the O(ε) neighbourhood of its vertex, so the error of a ball comes from atoms within O(ε) of its
// rim and e_G is expected to fall like O(ε) (docs/studies.md).
intrinsic::CurvatureMeasureResult meshCurvatureMeasure(const MeshRemeshResult& result,
                                                       const intrinsic::IntrinsicTriangulation& input,
                                                       const intrinsic::CurvatureMeasureOptions& options = {});

// The output for files: faces, edges with their path lengths, positions when the input has them, per-vertex
// properties input_face, input_b0..2, lambda and curvature (angle deficit / boundary turning).
intrinsic::MeshData toMeshData(const MeshRemeshResult& result, const std::string& source, double epsilon);
// The same for ParaView: points are the interpolated positions (required: throws InputError for a metric-only input).
intrinsic::VtkMesh toVtkMesh(const intrinsic::MeshData& data, const MeshRemeshResult& result);

}  // namespace conformesh::refine
