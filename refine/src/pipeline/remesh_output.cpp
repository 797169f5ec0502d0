// remesh_output.cpp — both pipelines' results, and a refinement's, as file data: MeshData for PLY/OFF/OBJ (faces, edge
// lengths, per-vertex properties, comments naming the source and ε) and VtkMesh for ParaView. Declared in
// metric_remesh.h, mesh_remesh.h, component_remesh.h and refinement_output.h; reads results only.
#include <cstdio>
#include <string>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/refine/pipeline/component_remesh.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "conformesh/refine/pipeline/refinement_output.h"
#include "conformesh/refine/trace/input_location.h"

namespace conformesh::refine {

using namespace conformesh::intrinsic;

// === a refinement (refinement_output.h)

MeshData refinementMeshData(const RefineResult& r, const IntrinsicTriangulation& input,
                            const std::vector<Eigen::Vector3d>& inputPositions, bool graded) {
  MeshData out = fromTriangulation(r.triangulation);
  const int n = r.triangulation.mesh.nVertices();
  std::vector<double> face(n), b0(n), b1(n), b2(n);
  for (int v = 0; v < n; ++v) {
    face[v] = r.locations[v].face;
    b0[v] = r.locations[v].bary[0];
    b1[v] = r.locations[v].bary[1];
    b2[v] = r.locations[v].bary[2];
  }
  out.vertexProperties["input_face"] = std::move(face);
  out.vertexProperties["input_b0"] = std::move(b0);
  out.vertexProperties["input_b1"] = std::move(b1);
  out.vertexProperties["input_b2"] = std::move(b2);
  if (graded) out.vertexProperties["lambda"] = r.lambda;
  if (input.background == Background::Euclidean && !inputPositions.empty()) {
    if (static_cast<int>(inputPositions.size()) != input.mesh.nVertices())
      throw InputError("refinementMeshData: " + std::to_string(inputPositions.size()) + " positions for an input of " +
                       std::to_string(input.mesh.nVertices()) + " vertices");
    out.positions = interpolatePositions(input.mesh, inputPositions, r.locations);
  }
  return out;
}

// === the smooth-metric pipeline

MeshData toMeshData(const RemeshResult& r, const SmoothMetric& metric, double epsilon) {
  MeshData d = fromTriangulation(r.mesh);
  d.source = metric.description();
  if (!r.positions.empty()) d.positions = r.positions;
  const int n = r.mesh.mesh.nVertices();
  auto& p = d.vertexProperties;
  p["u"].resize(n);
  p["v"].resize(n);
  p["smooth_curvature"].resize(n);
  p["input_face"].resize(n);
  for (const char* b : {"input_b0", "input_b1", "input_b2"}) p[b].resize(n);
  for (int v = 0; v < n; ++v) {
    p["u"][v] = r.chart[v].x();
    p["v"][v] = r.chart[v].y();
    p["smooth_curvature"][v] = metric.gaussianCurvature(r.chart[v].x(), r.chart[v].y());
    p["input_face"][v] = r.t0Face[v];
    p["input_b0"][v] = r.t0Bary[v][0];
    p["input_b1"][v] = r.t0Bary[v][1];
    p["input_b2"][v] = r.t0Bary[v][2];
  }
  p["lambda"] = r.lambda;
  p["curvature"] = vertexCurvatures(r.mesh);
  char eps[64];
  std::snprintf(eps, sizeof eps, "%.17g", epsilon);
  d.comments.push_back("conformesh remesh: " + metric.description());
  d.comments.push_back("eps " + std::string(eps) + " (circumradius bound in the original metric)");
  d.comments.push_back("lengths: metric lengths of the edges' curves in the original metric");
  d.comments.push_back("input: T0 of " + std::to_string(r.t0Vertices) + " vertices, " + std::to_string(r.t0Faces) +
                       " faces (input_face, input_b0..2)");
  return d;
}

VtkMesh toVtkMesh(const MeshData& data, const RemeshResult& r) {
  VtkMesh vtk;
  vtk.title = "conformesh remesh: " + data.source;
  // No embedding (e.g. Kerr a/M > sqrt 3/2): the points are the chart's reference surface; the title says so, and
  // scripts/render_mesh.py puts it on the picture.
  if (r.positions.empty()) vtk.title += kDrawnOnReferenceSurface;
  vtk.points = r.positions.empty() ? r.reference : r.positions;
  vtk.triangles = data.faces;
  for (const auto& [name, values] : data.vertexProperties)
    if (name.rfind("input_", 0) != 0) vtk.pointFields[name] = values;
  return vtk;
}

// === the mesh-file pipeline

MeshData toMeshData(const MeshRemeshResult& r, const std::string& source, double epsilon) {
  MeshData d = fromTriangulation(r.mesh);
  d.source = source;
  if (!r.positions.empty()) d.positions = r.positions;
  const int n = r.mesh.mesh.nVertices();
  auto& p = d.vertexProperties;
  p["input_face"].resize(n);
  for (const char* b : {"input_b0", "input_b1", "input_b2"}) p[b].resize(n);
  for (int v = 0; v < n; ++v) {
    p["input_face"][v] = r.location[v].face;
    p["input_b0"][v] = r.location[v].bary[0];
    p["input_b1"][v] = r.location[v].bary[1];
    p["input_b2"][v] = r.location[v].bary[2];
  }
  p["lambda"] = r.lambda;
  p["curvature"] = vertexCurvatures(r.mesh);
  char eps[64];
  std::snprintf(eps, sizeof eps, "%.17g", epsilon);
  d.comments.push_back("conformesh remesh: mesh " + source);
  d.comments.push_back("eps " + std::string(eps) + " (circumradius bound in the input mesh's metric)");
  d.comments.push_back(r.refinedIn == RefineMetric::Input
                           ? "lengths: refined in the input's own metric; the refined triangulation's lengths"
                           : "lengths: lengths of the edges' image paths across the input faces");
  d.comments.push_back("input: " + std::to_string(r.inputVertices) + " vertices, " + std::to_string(r.inputFaces) +
                       " faces (input_face, input_b0..2)");
  return d;
}

namespace {

// A mesh input's output for ParaView: its triangles at the given positions with every per-vertex field but the
// input_* locations (which index the input, not points to draw).
VtkMesh meshInputVtk(const MeshData& data, const std::vector<Eigen::Vector3d>& positions) {
  if (positions.empty())
    throw InputError(data.source + ": a metric-only input has no positions to draw; VTK output needs positions");
  VtkMesh vtk;
  vtk.title = "conformesh remesh: " + data.source;
  vtk.points = positions;
  vtk.triangles = data.faces;
  for (const auto& [name, values] : data.vertexProperties)
    if (name.rfind("input_", 0) != 0) vtk.pointFields[name] = values;
  return vtk;
}

}  // namespace

VtkMesh toVtkMesh(const MeshData& data, const MeshRemeshResult& r) {
  return meshInputVtk(data, r.positions);
}

VtkMesh componentsVtkMesh(const MeshData& merged) {
  return meshInputVtk(merged, merged.positions);
}

}  // namespace conformesh::refine
