// view_page.h — what `conformesh view` draws: a mesh file's surface as a scene (points, triangles, every per-vertex
// field, the figures of its report) and that scene as one self-contained HTML page with three.js inlined.
//
// Points are the file's positions when it has them. A metric-only mesh (lengths only, e.g. `remesh` of Kerr a/M = 0.99,
// which has no embedding in R³) is drawn in its uniformization domain: the triangulation is uniformized
// (intrinsic/flow/uniformization.h) and each vertex placed at its point of the model space — the unit sphere for
// genus 0, the plane for a disk or circle domain; the page says so. Flat tori and hyperbolic surfaces have no such
// picture here (`conformesh layout` draws their fundamental domains). docs/cli.md#view.
#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::embedding {

struct ViewScene {
  std::string title;   // the file (MeshData::source)
  std::string domain;  // what the points are: "positions from the file" or the uniformization domain
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::map<std::string, std::vector<double>> fields;         // per point, the file's vertex properties by name
  std::vector<Eigen::Vector2d> chart;                        // (u, v) per point when the file has both, else empty
  std::vector<std::pair<std::string, std::string>> figures;  // (label, value) rows shown beside the mesh
  std::vector<std::string> comments;                         // the file's header comments
};

struct ViewSceneOptions {
  intrinsic::UniformizationOptions uniformization;  // for metric-only meshes (its `progress` for progress lines)
  std::string validate() const { return uniformization.validate(); }
};

// The scene of a mesh file's content: the triangulation is built (toTriangulation: every check of the readers; vertices
// no face uses are dropped and the fields follow), points chosen as above, figures from summarize() — vertices,
// faces, genus, boundary loops, total area, Σ curvature against 2πχ, the Gauss–Bonnet residual — and each field's
// range. Throws InputError (naming data.source) for invalid meshes and for a metric-only surface with no model-space
// picture; ConvergenceError when the flow does not converge.
ViewScene makeViewScene(const intrinsic::MeshData& data, const ViewSceneOptions& options = {});

// The page's fixed parts: the template (viewer/view.html, with the markers /*@THREE@*/, /*@ORBIT_CONTROLS@*/ and
// /*@SCENE@*/) and three.js r111 and its OrbitControls as Debian's libjs-three installs them.
struct ViewAssets {
  std::string templateHtml, threeJs, orbitControlsJs;
};

// Reads viewerDir/view.html, threeDir/three.min.js and threeDir/examples/js/controls/OrbitControls.js. Throws
// InputError naming the missing file, with "apt-get install libjs-three" for the three.js files.
ViewAssets readViewAssets(const std::string& viewerDir, const std::string& threeDir);

// The scene as JSON: {"title", "domain", "positions": [x0, y0, z0, …], "triangles": [a0, b0, c0, …],
// "fields": {name: [values, null for non-finite]}, "figures": [[label, value], …], "comments": […]}; floats with 9
// significant digits (single precision is what WebGL draws), "</" escaped so the text can sit in a <script>.
std::string sceneJson(const ViewScene& scene);

// The page: the template with the assets and sceneJson inlined (no network access at view time). Throws InputError
// when a marker is missing from the template.
std::string viewPageHtml(const ViewScene& scene, const ViewAssets& assets);

// Writes viewPageHtml to path.tmp and renames it to path. Throws InputError naming the path on I/O failure.
void writeViewPage(const ViewScene& scene, const ViewAssets& assets, const std::string& path);

}  // namespace conformesh::embedding
