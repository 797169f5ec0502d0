// mesh_components.h — a triangulation cut into its connected components, each a triangulation of its own with the
// maps of its vertices and faces back to the input, and the inverse: per-component file data concatenated into one
// MeshData with a per-vertex `component` index. Used by `uniformize` and `remesh` on surfaces of several components
// (each is uniformized to its own target); pure functions, no files.
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/halfedge_mesh.h"
#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::intrinsic {

struct MeshComponent {
  IntrinsicTriangulation triangulation;  // the component alone: same background, same edge lengths
  std::vector<int> vertices;             // per component vertex: its index in the input (increasing)
  std::vector<int> faces;                // per component face: its index in the input (increasing)
  ComponentTopology topology;            // as HalfedgeMesh::components() reports it for this component
};

// The connected components of `tri` (faces joined through shared edges; a valid triangulation has one fan per vertex,
// so each vertex lies in one component), in HalfedgeMesh::components()'s order: by smallest face index. Each
// component's faces keep the input's corner order and its edges their lengths, so its geometry is the input's
// restricted to it. A connected input gives one component equal to the input.
std::vector<MeshComponent> splitComponents(const IntrinsicTriangulation& tri);

// "component 2 of 6 (120 vertices, 236 faces, genus 0, 1 boundary loop)": how errors and reports name a component
// (index 0-based).
std::string describeComponent(int index, int count, const ComponentTopology& topology);

// The parts concatenated in order: vertices and faces renumbered (part i's vertex v becomes offset_i + v), edges,
// corner edges, positions (all parts or none) and the vertex properties every part has, plus the vertex property
// `component` (the part's index). Background, source and comments are part 0's. Throws InputError when parts
// disagree on having positions.
MeshData concatenateMeshData(const std::vector<MeshData>& parts);

}  // namespace conformesh::intrinsic
