// component_remesh.h — remeshMesh (mesh_remesh.h) on a surface of several connected components: the input split
// (splitComponents), each component remeshed alone by either route (on the uniformized route, uniformized to its own
// target), and the outputs merged into one file's data with a per-vertex `component` index. Pure functions of their
// arguments: no files (progress only through the options' callback). The command: docs/cli.md#remesh.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/mesh/mesh_components.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/output_verification.h"

namespace conformesh::refine {

struct ComponentRemesh {
  std::vector<intrinsic::MeshComponent> components;  // the input's, with their maps back to its vertices and faces
  std::vector<MeshRemeshResult> parts;               // parts[i]: components[i] remeshed (its own numbering)
  double epsilon = 0;                                // the one ε of every component (input units)
};

// Remeshes each component of `input` with `options` (validated first, as remeshMesh does). One ε for all: options'
// epsilon, or epsilonRelative · √(total input area). maxVertices caps each component. `positions` per input vertex
// (or empty) are handed to each component. Throws InputError / ConvergenceError as remeshMesh does, the message
// prefixed "remesh: " and describeComponent() of the failing component.
ComponentRemesh remeshComponents(const intrinsic::IntrinsicTriangulation& input,
                                 const std::vector<Eigen::Vector3d>& positions, const MeshRemeshOptions& options);

// The file data of the merged output: `parts[i]` is toMeshData(result.parts[i], …) with any properties the caller
// added (the curvature-measure fields), concatenated (concatenateMeshData: per-vertex `component`), with the vertex
// property input_face renumbered to the INPUT's face indices. Throws InputError when the counts disagree.
intrinsic::MeshData mergeComponentOutputs(const ComponentRemesh& result, const std::vector<intrinsic::MeshData>& parts);

// Every component checked by verifyMeshRemesh against its own input component; each failure prefixed with
// describeComponent(); faces checked summed; areaRelativeError is the largest in magnitude.
OutputVerification verifyComponentRemesh(const ComponentRemesh& result, const VerificationTolerances& tolerances = {});

// The merged data for ParaView: its positions, faces and vertex properties but input_*. Throws InputError without
// positions (a metric-only input).
intrinsic::VtkMesh componentsVtkMesh(const intrinsic::MeshData& merged);

}  // namespace conformesh::refine
