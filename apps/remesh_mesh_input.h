// remesh_mesh_input.h — the mesh-file branch of `conformesh remesh`: when INPUT names a mesh file (.off, .obj, .ply),
// the pipeline is the refinement of the input in its own metric (the default, `--refine-in input`: it keeps the angle
// bound there), or with `--refine-in uniformized` uniformize → refine → pull back through the input faces
// (refine/pipeline/mesh_remesh.h); the curvature check compares the output's angle
// deficits with the input's own over the same balls. Parsing and printing only.
#pragma once

#include <string>

namespace conformesh::apps {

// True when `input` ends in .off, .obj or .ply (any case): `remesh` then reads it as a mesh, not a family name.
bool isMeshFilePath(const std::string& input);

struct MeshRemeshCliArgs {
  std::string input;
  double epsilon = 0;
  double ratio = 1.4142135623730951;
  bool uniform = false;
  std::string output, vtk;
  bool json = false, noCheck = false, ascii = false;
  std::string refineIn = "input";        // refine::parseRefineMetric
  int smoothing = 0;                     // smoothing passes, input route only (the uniformized route is unsmoothed)
  std::string smoothingRule = "odt";     // refine::parseSmoothingRule
  std::string segmentRule = "ruppert";   // refine::parseSegmentRule
  bool keepFailed = false;               // an output failing verification is written as NAME.failed.EXT
  double epsilonRelative = 0;            // --eps-rel: ε = this · √(input area) when > 0
  std::int64_t maxVertices = 0;          // refine::MeshRemeshOptions::maxVertices
};

void runRemeshMesh(const MeshRemeshCliArgs& args);

}  // namespace conformesh::apps
