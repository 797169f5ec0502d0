// mesh_repair.h — turning what is almost a surface into one, on MeshData (a file's content) before toTriangulation:
// merge duplicate boundary vertices, drop degenerate faces and duplicate faces that crowd an edge, cut non-manifold edges into boundary, duplicate
// pinched vertices into one vertex per fan, orient consistently. Each step is counted and its first elements named in
// a RepairReport. Positions and per-vertex properties follow the vertices (a duplicated vertex copies them; a merged
// one keeps the lowest index's); per-edge lengths follow their vertex pairs. docs/cli.md#repair documents the steps.
// Depends on mesh_data.h and halfedge_mesh.h (the orientation and the final validation).
#pragma once

#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::intrinsic {

struct RepairOptions {
  // Boundary vertices (on an edge of one face) closer than mergeTolerance × (bounding-box diagonal) are merged
  // (positions needed; 0: exact duplicates only; negative: no merging): borders are stitched, while coincident vertices
  // inside a surface stay apart. The default merges what a file's rounding made distinct, not features.
  double mergeTolerance = 1e-10;
  // A face is degenerate when it repeats a vertex or, with positions, when its area is at most
  // degenerateTolerance × (its longest side)²: its height over the longest side is below 2·tolerance of that side.
  double degenerateTolerance = 1e-12;
  int examples = 5;  // elements named per kind in the report
  // "" when the options are usable, else what is wrong (expected against found).
  std::string validate() const;
};

struct RepairReport {
  struct Step {
    int count = 0;
    std::vector<std::string> examples;  // the first few, e.g. "vertex 12 → 3" or "face 7 (1, 2, 2)"
  };
  double mergeDistance = 0;  // the absolute tolerance used (mergeTolerance × bounding-box diagonal)
  Step mergedVertices, degenerateFaces, duplicateFaces, nonManifoldEdges, pinchedVertices, reorientedFaces,
      unreferencedVertices;
  // True when any step changed the connectivity that toTriangulation would refuse (everything but merges,
  // reorientations and unreferenced vertices, which it accepts or fixes itself).
  bool neededForTriangulation() const;
  bool changedAnything() const;
  std::string summary() const;  // one line per step that did something
};

// Repairs `data` (a polygon soup: a Δ-complex with edge_index is refused with an InputError). The result has no
// unreferenced vertices and is a consistently oriented manifold with boundary whenever every component is orientable
// (a non-orientable one is an InputError from the orientation step, naming the conflict). Throws InputError for
// invalid options.
MeshData repairMesh(const MeshData& data, const RepairOptions& options = {}, RepairReport* report = nullptr);

// What repairMesh would do, without merging vertices: throws InputError naming the first defect that toTriangulation
// would refuse, and saying that repair (`--repair`) would fix it; returns quietly otherwise.
void requireNoRepairNeeded(const MeshData& data);

}  // namespace conformesh::intrinsic
