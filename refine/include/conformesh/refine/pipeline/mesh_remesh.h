// mesh_remesh.h — the pipeline for a surface given by a TRIANGLE MESH (a file with positions, or a metric-only PLY
// with edge lengths). Two routes (RefineMetric): Uniformized, the paper's — uniformize the input T0 by discrete Ricci
// flow (T0*, λ), Delaunay-refine T0* graded by e^(−λ) (T1*), pull back through the input faces (each output vertex
// gets its input face and barycentric coordinates, each output edge the developed length of its image path across
// the input faces); Input — Delaunay-refine T0 in its own flat cone metric. Both check the result against the input.
// The default is Input: it keeps the angle bound in the input's metric (≥ 20.7° at B = √2), while the uniformized
// route's piecewise-projective pull-back distorts angles by a fixed amount per input face (eight.off at ε = 0.02:
// 30.2° against 9.6°; docs/cli.md#remesh-meshfile). Metrics (metric_remesh.h) have no input faces and are always
// refined uniformized. Pure functions of their arguments: no files, no global state (progress only through the
// callback).
// Derivations (image paths, development, why two routes): docs/refinement.md §9; the command: docs/cli.md.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/flow_correspondence.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"
#include "conformesh/refine/pipeline/vertex_budget.h"

namespace conformesh::refine {

// The metric the Delaunay refinement runs in.
enum class RefineMetric {
  Uniformized,  // the paper's: refine T0* (constant curvature) graded by e^(−λ), pull back through the input faces
  Input,        // the input's own flat cone metric: refine T0 itself, uniform size bound ε
};
std::string toString(RefineMetric metric);                // "uniformized", "input"
RefineMetric parseRefineMetric(const std::string& name);  // InputError naming the value otherwise

struct MeshRemeshOptions {
  // Size bound ε in the INPUT's units: circumradii of T1* are at most ε·e^(−λ) in the uniformized metric, i.e. ≈ ε
  // on the input (paper §4.2.3). Required, > 0.
  double epsilon = 0;
  double ratioBound = 1.4142135623730951;  // shape bound B (circumradius / shortest edge), RefineOptions::ratioBound
  RefineMetric refineIn = RefineMetric::Input;  // the default keeps the angle bound in the input's metric
  bool uniform = false;  // λ ≡ 0: uniform in the uniformized domain, for comparisons. Uniformized route only.
  // Midpoint (1-to-4) subdivisions of the input before uniformizing (the same flat surface, finer; lowers the
  // pull-back's angle distortion per face). 0..6; uniformized route only.
  int inputSubdivisions = 0;
  intrinsic::UniformizationOptions uniformization;
  // Passed through to the refinement (epsilon, ratioBound and lambda are set from the fields above). On the input
  // route boundary edges are split at their midpoints (BoundarySplit::Circle is an error there).
  RefineOptions refinement;
  // Halvings of every straight piece before measuring its image: the lengths must not change (to round-off); a check
  // of the exact edge crossings, for tests. 0 = only where needed.
  int extraBisections = 0;
  // ε as a fraction of √area instead (--eps-rel; area of the input): used when > 0, and then epsilon must be 0.
  double epsilonRelative = 0;
  // Refuse, before refining, an ε whose expected vertex count (vertex_budget.h) exceeds this; the refinement's
  // insertion cap is lowered to twice it. ≤ 0: no cap.
  std::int64_t maxVertices = kDefaultMaxVertices;
  std::function<void(const std::string&)> progress;

  // What is wrong with these options ("" when valid): ε, the subdivision count, and the settings the input route
  // does not take (subdivisions, uniform, circle boundary splits).
  std::string validate() const;
};

struct MeshRemeshTimes {
  double uniformize = 0, refine = 0, pullBack = 0;  // input route: uniformize = 0, pullBack = locations and checks
};

struct MeshRemeshResult {
  RefineMetric refinedIn = RefineMetric::Uniformized;
  // T1: connectivity of T1*, Euclidean, lengths = developed lengths of the edges' image paths on the input. Input
  // route: the refined triangulation itself, with its own lengths.
  intrinsic::IntrinsicTriangulation mesh;
  // Per output vertex: its input face and (affine) barycentric coordinates. Vertices 0 .. inputVertices−1 are the
  // input's own, then T0's edge midpoints, then the inserted ones.
  std::vector<intrinsic::FacePoint> location;
  std::vector<Eigen::Vector3d> positions;  // per output vertex, interpolated on the input; empty without positions
  std::vector<double> lambda;              // per output vertex: λ at its place on T0* (input route: 0)
  int inputVertices = 0, inputFaces = 0;
  int t0Vertices = 0;  // vertices of T0 (the input after subdivision): output vertices 0 .. t0Vertices−1
  // Output triangles whose three vertices can be written in one input face, with a non-positive orientation there,
  // and how many could be checked so.
  int invertedTriangles = 0, orientationChecked = 0;
  // Output edges whose two ends can be written in one input face, and the largest relative difference between the
  // edge's length and the straight distance of its located ends there.
  int sameFaceEdges = 0;
  double maxSameFaceLengthError = 0;
  // The same difference relative to max(edge length, the face's longest side): the located ends' round-off scales
  // with the face (barycentric coordinates), so an edge far shorter than its face has a larger relative error.
  double maxSameFaceScaledError = 0;
  // The first inverted output triangle and the edge of the largest scaled same-face error, each with the T0 face it was
  // checked in ({−1, −1}: none). T0 is the input after subdivision (input route: the input itself).
  std::array<int, 2> firstInvertedTriangle{-1, -1};
  std::array<int, 2> worstSameFaceEdge{-1, -1};
  // Output edges from a vertex to itself (geodesic loops around a cone vertex of angle below π); they and their
  // triangles enter neither check above.
  int loopEdges = 0;
  // The image paths (uniformized route; input route: pathLength = the lengths, the others 0 or empty): straight
  // pieces measured, crossings of input edges, and the largest excess of a path's length (the sum of its straight
  // pieces) over its developed length.
  std::int64_t pathPieces = 0;
  std::vector<int> edgePieces;     // per output edge (1: one straight piece in one input face)
  std::vector<double> pathLength;  // per output edge: the sum of its image path's straight pieces
  std::int64_t inputEdgeCrossings = 0;
  double maxBendExcess = 0;
  intrinsic::UniformizationReport uniformization;  // uniformized route only
  RefineStatistics refinement;
  QualityReport uniformQuality;  // of T1* in its background metric (input route: the same as quality)
  QualityReport quality;         // of T1 in the input metric
  MeshRemeshTimes seconds;
  double epsilon = 0;                // the ε used (options.epsilon, or epsilonRelative · √(input area))
  VertexEstimate expected;           // before refining (vertex_budget.h)
  std::vector<std::string> notices;  // e.g. ε above the input's spacing (nothing inserted)
};

// Remeshes `input` (Euclidean background; one connected component). `positions`, per input vertex, may be empty;
// when given they are only interpolated at the output vertices (lengths come from `input`). Throws InputError with
// options.validate()'s text or for a bad input (naming it), ConvergenceError when a stage does not converge.
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

// The Gaussian-curvature-measure check for a mesh input (the analogue of paper eq. 5): per output vertex v, over the
// output vertices within graph distance r = radiusFraction·√area of v, Σ angle deficits of T1 against Σ deficits of
// the INPUT at the input vertices among them; relative error normalised by Σ |input deficit|. Throws InputError when
// `result` is not a remeshing of `input`.
intrinsic::CurvatureMeasureResult meshCurvatureMeasure(const MeshRemeshResult& result,
                                                       const intrinsic::IntrinsicTriangulation& input,
                                                       const intrinsic::CurvatureMeasureOptions& options = {});

// The output for files (remesh_output.cpp): faces, edges with their lengths, positions when the input has them,
// per-vertex properties input_face, input_b0..2, lambda and curvature (angle deficit / boundary turning).
intrinsic::MeshData toMeshData(const MeshRemeshResult& result, const std::string& source, double epsilon);
// The same for ParaView: points are the interpolated positions (required: throws InputError for a metric-only input).
intrinsic::VtkMesh toVtkMesh(const intrinsic::MeshData& data, const MeshRemeshResult& result);

}  // namespace conformesh::refine
