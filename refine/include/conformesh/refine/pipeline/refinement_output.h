// refinement_output.h — a Delaunay refinement's result (delaunay_refinement.h) as the file data `conformesh refine`
// writes and the Python module returns: the output's faces and lengths in the input's background, each vertex's
// place on the input (input_face, input_b0..2), λ when the refinement was graded, and positions interpolated from
// the input's when it is Euclidean with positions. Reads results only; no files.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"

namespace conformesh::refine {

// `input` is the triangulation refineDelaunay was given; `inputPositions` one point per vertex of it, or empty (then
// the output has none). `graded`: write r.lambda as the vertex property "lambda". A location is a point of the
// input's flat triangle, so its position is the barycentric combination of the corners (extended linearly for
// boundary-circle points beyond a chord); positions are interpolated on a Euclidean background only.
intrinsic::MeshData refinementMeshData(const RefineResult& r, const intrinsic::IntrinsicTriangulation& input,
                                       const std::vector<Eigen::Vector3d>& inputPositions, bool graded);

}  // namespace conformesh::refine
