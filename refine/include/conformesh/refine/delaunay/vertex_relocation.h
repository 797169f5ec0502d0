// vertex_relocation.h — moving an inserted interior vertex of a refined intrinsic triangulation to another point of its
// star, laid out isometrically in the background model (background_model.h), keeping every invariant of the
// refinement: the lengths of its edges (background distances in the layout), its input location (re-traced on the
// input), its signposts and its neighbours' signposts toward it. Touches only the moved vertex's edges, location and
// signposts; input vertices and boundary vertices are never moved. docs/refinement.md §6, *Smoothing*.
#pragma once

#include <optional>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/refine/trace/background_model.h"
#include "conformesh/refine/trace/input_location.h"
#include "conformesh/refine/trace/signposts.h"

namespace conformesh::refine {

// The star of v laid out in the background model: v at BackgroundModel::origin(), its signpost frame the canonical
// frame (e1, e2) there. out[i] are v's outgoing halfedges counter-clockwise (nextOutgoing), ring[i] the layout of
// tip(out[i]); star triangle i is (v, ring[i], ring[i+1]) = face(out[i]).
struct VertexStar {
  int vertex = intrinsic::kInvalid;
  std::vector<int> out;
  std::vector<Vec3> ring;
};

// The star of v, or nullopt when v may not move: an input vertex (v < inputVertices), a boundary vertex, a vertex with
// a self-loop (it would be its own neighbour), or a vertex whose angle sum is not 2π to 1e-9 rad (then its star does
// not lay out in the model; inserted interior vertices are regular points, their sums are 2π to round-off ~1e-14).
std::optional<VertexStar> layoutStar(const intrinsic::IntrinsicTriangulation& tri, const Signposts& sp, int v,
                                     int inputVertices);

// Whether v may move to p: every triangle (p, ring[i], ring[i+1]) is strictly counter-clockwise by the exact predicate
// (p lies in the kernel of the star polygon, so the triangles tile the same disk) and its new lengths satisfy the
// strict triangle inequality of the background.
bool isValidStarPosition(const intrinsic::IntrinsicTriangulation& tri, const VertexStar& star, const Vec3& p);

// Moves star.vertex to p (a point of the star's layout). Updates the lengths of its edges, its input location
// (`locations[v]`: the geodesic origin → p followed on the input from the old location, InputSurface::follow), its
// signposts (the canonical frame of the new input face's layout, as for an inserted vertex) and the signposts of its
// neighbours' halfedges toward it. Returns false and changes nothing when p is not a valid position (see above), when
// p is the vertex's current position, or when the trace on the input leaves the surface.
bool relocateVertex(intrinsic::IntrinsicTriangulation& tri, Signposts& sp, std::vector<InputLocation>& locations,
                    const InputSurface& input, const VertexStar& star, const Vec3& p);

}  // namespace conformesh::refine
