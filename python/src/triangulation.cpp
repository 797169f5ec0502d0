// triangulation.cpp — conformesh.Triangulation, conformesh.read and conformesh.write.
#include "triangulation.h"

#include <algorithm>
#include <cmath>

#include <pybind11/stl.h>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/mesh/curvature.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"
#include "conformesh/intrinsic/mesh/mesh_summary.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::python {

using intrinsic::IntrinsicTriangulation;

TriangulationPtr fromMeshData(const intrinsic::MeshData& data) {
  auto t = std::make_shared<Triangulation>();
  intrinsic::ConversionReport conv;
  t->tri = intrinsic::toTriangulation(data, &conv);
  t->source = data.source;
  t->reading = conv;
  t->reading.vertexMap.clear();
  const int n = t->tri.mesh.nVertices();
  if (!data.positions.empty()) t->positions.resize(n);
  for (const auto& [name, values] : data.vertexProperties) t->fields[name].resize(n);
  for (std::size_t v = 0; v < conv.vertexMap.size(); ++v) {
    const int w = conv.vertexMap[v];
    if (w == intrinsic::kInvalid) continue;
    if (!data.positions.empty()) t->positions[w] = data.positions[v];
    for (const auto& [name, values] : data.vertexProperties) t->fields[name][w] = values[v];
  }
  return t;
}

TriangulationPtr fromIntrinsic(IntrinsicTriangulation tri, std::string source) {
  auto t = std::make_shared<Triangulation>();
  t->tri = std::move(tri);
  t->source = std::move(source);
  return t;
}

intrinsic::MeshData toMeshData(const Triangulation& t) {
  intrinsic::MeshData d = intrinsic::fromTriangulation(t.tri);
  d.source = t.source;
  d.positions = t.positions;
  d.vertexProperties = t.fields;
  return d;
}

namespace {

constexpr const char* kFromPositions = "Triangulation.from_positions";
constexpr const char* kFromLengths = "Triangulation.from_lengths";

// Every vertex 0 .. n−1 must be used by a face: the arrays' indices are the triangulation's.
int checkVertexUse(const std::vector<std::array<int, 3>>& faces, int nVertices, const std::string& where) {
  std::vector<char> used(nVertices, 0);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int v : faces[f]) {
      if (v >= nVertices)
        inputError(where + ": F: face " + std::to_string(f) + " has vertex index " + std::to_string(v) +
                   " but there are " + std::to_string(nVertices) + " vertices");
      used[v] = 1;
    }
  for (int v = 0; v < nVertices; ++v)
    if (!used[v]) inputError(where + ": vertex " + std::to_string(v) + " is used by no face");
  return nVertices;
}

TriangulationPtr fromPositions(const py::handle& V, const py::handle& F) {
  intrinsic::MeshData d;
  d.source = kFromPositions;
  d.positions = pointsFromArray(V, std::string(kFromPositions) + ": V");
  d.faces = facesFromArray(F, std::string(kFromPositions) + ": F");
  d.nVertices = static_cast<int>(d.positions.size());
  if (d.faces.empty()) inputError(std::string(kFromPositions) + ": F has no faces");
  checkVertexUse(d.faces, d.nVertices, kFromPositions);
  py::gil_scoped_release release;
  return fromMeshData(d);
}

TriangulationPtr fromLengths(const py::handle& F, const py::handle& L, double tolerance, const std::string& bg) {
  const std::string where = kFromLengths;
  std::vector<std::array<int, 3>> faces = facesFromArray(F, where + ": F");
  py::ssize_t rows = 0;
  std::vector<double> lengths = realsFromArray(L, where + ": L", 3, &rows);
  if (rows != static_cast<py::ssize_t>(faces.size()))
    inputError(where + ": L has " + std::to_string(rows) + " rows but F has " + std::to_string(faces.size()) +
               " faces (expected L of shape (m, 3), L[f, k] the length of edge F[f, k] -> F[f, (k + 1) % 3])");
  if (faces.empty()) inputError(where + ": F has no faces");
  if (!(tolerance >= 0)) inputError(where + ": tolerance must be >= 0");
  const intrinsic::Background background = intrinsic::backgroundFromString(bg, where + ": background");
  py::gil_scoped_release release;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (!(lengths[3 * f + k] > 0))
        throw InputError(where + ": face " + std::to_string(f) + ": L[" + std::to_string(f) + ", " +
                         std::to_string(k) + "] = " + formatNumber(lengths[3 * f + k]) +
                         " (expected a positive length)");
  int n = 0;
  for (const auto& fv : faces) n = std::max({n, fv[0] + 1, fv[1] + 1, fv[2] + 1});
  checkVertexUse(faces, n, where);
  intrinsic::BuildReport build;
  auto t = std::make_shared<Triangulation>();
  t->source = where;
  t->tri.mesh = intrinsic::HalfedgeMesh::fromFaces(faces, n, where, &build);
  t->tri.background = background;
  t->reading.build = build;
  const auto& mesh = t->tri.mesh;
  std::vector<double>& el = t->tri.edgeLengths;
  el.assign(mesh.nEdges(), std::nan(""));
  std::vector<int> setBy(mesh.nEdges(), -1);
  for (int f = 0; f < mesh.nFaces(); ++f) {
    const bool same = mesh.faceVertex(f, 0) == faces[f][0] && mesh.faceVertex(f, 1) == faces[f][1];
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      int h = 3 * f + k;
      if (!same) {  // reoriented face: the corner running b -> a
        for (int j = 0; j < 3; ++j)
          if (mesh.faceVertex(f, j) == b && mesh.faceVertex(f, (j + 1) % 3) == a) h = 3 * f + j;
      }
      const int e = mesh.edge(h);
      const double x = lengths[3 * f + k];
      if (setBy[e] < 0) {
        el[e] = x;
        setBy[e] = f;
      } else if (std::abs(el[e] - x) > tolerance * std::max(el[e], x)) {
        throw InputError(where + ": face " + std::to_string(f) + " gives edge (" + std::to_string(a) + ", " +
                         std::to_string(b) + ") length " + formatNumber(x) + " but face " + std::to_string(setBy[e]) +
                         " gives " + formatNumber(el[e]) + " (the two faces of an edge must agree to a relative " +
                         formatNumber(tolerance) + ")");
      }
    }
  }
  intrinsic::validateLengths(t->tri, where);
  return t;
}

py::array_t<std::int32_t> facesArray(const Triangulation& t) {
  const auto& m = t.tri.mesh;
  std::vector<int> f(3 * static_cast<std::size_t>(m.nFaces()));
  for (int h = 0; h < m.nHalfedges(); ++h) f[h] = m.tail(h);
  return toArray(std::move(f), 3);
}

py::array_t<double> cornerLengths(const Triangulation& t) {
  const auto& m = t.tri.mesh;
  std::vector<double> l(m.nHalfedges());
  for (int h = 0; h < m.nHalfedges(); ++h) l[h] = t.tri.length(h);
  return toArray(std::move(l), 3);
}

nlohmann::json summaryJson(const Triangulation& t) {
  // The keys of `conformesh info --json`, "file" being the source.
  nlohmann::json j = refine::meshSummaryJson(intrinsic::summarize(t.tri));
  j.update(refine::readingJson(t.reading));
  j["file"] = t.source;
  return j;
}

int componentSum(const Triangulation& t, int intrinsic::ComponentTopology::*field) {
  int s = 0;
  for (const auto& c : t.tri.mesh.components()) s += c.*field;
  return s;
}

bool endsWith(std::string s, const std::string& ext) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= ext.size() && s.compare(s.size() - ext.size(), ext.size(), ext) == 0;
}

TriangulationPtr readPath(const std::string& path) {
  py::gil_scoped_release release;
  return fromMeshData(intrinsic::readMesh(path));
}

void writePath(const std::string& path, const Triangulation& t, const py::object& fields, const py::object& positions,
               bool ascii) {
  intrinsic::MeshData d = toMeshData(t);
  const int n = t.tri.mesh.nVertices();
  if (!positions.is_none()) {
    d.positions = pointsFromArray(positions, "write: positions");
    if (static_cast<int>(d.positions.size()) != n)
      inputError("write: positions has " + std::to_string(d.positions.size()) + " rows, the triangulation " +
                 std::to_string(n) + " vertices");
  }
  if (!fields.is_none())
    for (const auto& [key, value] : fields.cast<py::dict>()) {
      const std::string name = py::str(key);
      d.vertexProperties[name] = vectorFromArray(value, "write: field '" + name + "'", n);
    }
  py::gil_scoped_release release;
  if (endsWith(path, ".vtk")) {
    if (d.positions.empty())
      throw InputError(path + ": VTK needs vertex positions; the triangulation has none (pass positions=...)");
    intrinsic::VtkMesh v;
    v.points = d.positions;
    v.triangles = d.faces;
    v.pointFields = d.vertexProperties;
    intrinsic::writeVtk(v, path);
    return;
  }
  intrinsic::WriteOptions w;
  if (ascii) w.plyEncoding = intrinsic::PlyEncoding::Ascii;
  intrinsic::writeMesh(d, path, w);
}

}  // namespace

void bindTriangulation(py::module_& m) {
  py::class_<Triangulation, TriangulationPtr> c(m, "Triangulation", R"doc(
A triangulated surface known by its connectivity and edge lengths (an intrinsic triangulation), in a Euclidean,
spherical or hyperbolic background, optionally with vertex positions and named per-vertex fields.

Build one with Triangulation.from_positions(V, F), Triangulation.from_lengths(F, L) or conformesh.read(path).
Halfedge h = 3 f + k is corner k of face f and runs from faces[f, k] to faces[f, (k + 1) % 3]; per-corner arrays
(lengths, corner_angles()) have shape (num_faces, 3) in that order.)doc");
  c.def_static("from_positions", &fromPositions, py::arg("V"), py::arg("F"), R"doc(
Triangulation of the mesh with vertex positions V (shape (n, 3), real) and faces F (shape (m, 3), integer).

Edge lengths are the distances between the positions; the positions are kept (``positions``). Every vertex must be
used by a face. Faces whose orientation disagrees with their neighbours are reoriented (``summary()["reoriented_faces"]``).
Raises InputError naming the element for a bad shape or dtype, NaN coordinates, an index out of range, a face that
repeats a vertex, a non-manifold edge or vertex, a non-orientable surface, or a degenerate triangle.)doc");
  c.def_static("from_lengths", &fromLengths, py::arg("F"), py::arg("L"), py::arg("tolerance") = 1e-12,
               py::arg("background") = "euclidean", R"doc(
Triangulation of faces F (shape (m, 3), integer) with corner lengths L (shape (m, 3), real): L[f, k] is the length of
the edge from F[f, k] to F[f, (k + 1) % 3].

The two faces of an interior edge must give it the same length to a relative ``tolerance``; each face's lengths must
be finite, positive and satisfy the strict triangle inequality of ``background`` ("euclidean", "spherical" or
"hyperbolic"). Every violation raises InputError naming the face.)doc");
  c.def_property_readonly("faces", &facesArray, "Faces, int32 array of shape (num_faces, 3) (after reorientation).");
  c.def_property_readonly("lengths", &cornerLengths,
                          "Corner lengths, float64 (num_faces, 3): lengths[f, k] of edge faces[f, k] -> faces[f, k+1].");
  c.def_property_readonly(
      "edges",
      [](const Triangulation& t) {
        const auto& mesh = t.tri.mesh;
        std::vector<int> e(2 * static_cast<std::size_t>(mesh.nEdges()));
        for (int i = 0; i < mesh.nEdges(); ++i) {
          e[2 * i] = mesh.tail(mesh.edgeHalfedge(i));
          e[2 * i + 1] = mesh.tip(mesh.edgeHalfedge(i));
        }
        return toArray(std::move(e), 2);
      },
      "Edge end points, int32 (num_edges, 2); parallel to edge_lengths.");
  c.def_property_readonly(
      "edge_lengths", [](const Triangulation& t) { return toArray(std::vector<double>(t.tri.edgeLengths)); },
      "Edge lengths, float64 (num_edges,).");
  c.def_property_readonly(
      "num_vertices", [](const Triangulation& t) { return t.tri.mesh.nVertices(); }, "Number of vertices.");
  c.def_property_readonly(
      "num_edges", [](const Triangulation& t) { return t.tri.mesh.nEdges(); }, "Number of edges.");
  c.def_property_readonly(
      "num_faces", [](const Triangulation& t) { return t.tri.mesh.nFaces(); }, "Number of faces.");
  c.def_property_readonly(
      "euler_characteristic", [](const Triangulation& t) { return t.tri.mesh.eulerCharacteristic(); },
      "Euler characteristic V - E + F.");
  c.def_property_readonly(
      "genus", [](const Triangulation& t) { return componentSum(t, &intrinsic::ComponentTopology::genus); },
      "Genus (summed over connected components), from chi = 2 - 2g - b.");
  c.def_property_readonly(
      "boundary_loops", [](const Triangulation& t) { return static_cast<int>(t.tri.mesh.boundaryLoops().size()); },
      "Number of boundary loops.");
  c.def_property_readonly(
      "num_components", [](const Triangulation& t) { return static_cast<int>(t.tri.mesh.components().size()); },
      "Number of connected components.");
  c.def_property_readonly(
      "total_area", [](const Triangulation& t) { return intrinsic::totalArea(t.tri); },
      "Sum of the triangle areas in the background geometry.");
  c.def_property_readonly(
      "background", [](const Triangulation& t) { return intrinsic::toString(t.tri.background); },
      "Background geometry of the triangles: 'euclidean', 'spherical' or 'hyperbolic'.");
  c.def_property_readonly(
      "positions",
      [](const Triangulation& t) -> py::object {
        if (t.positions.empty()) return py::none();
        return toArray(std::vector<Eigen::Vector3d>(t.positions));
      },
      "Vertex positions, float64 (num_vertices, 3), or None for a metric-only triangulation.");
  c.def_property_readonly(
      "fields",
      [](const Triangulation& t) {
        py::dict d;
        for (const auto& [name, values] : t.fields) d[py::str(name)] = toArray(std::vector<double>(values));
        return d;
      },
      "Per-vertex fields (a new dict of float64 arrays), e.g. those a PLY file carried.");
  c.def_property_readonly("source", [](const Triangulation& t) { return t.source; },
                          "Where the triangulation came from (a file name or a constructor), as errors name it.");
  c.def(
      "corner_angles",
      [](const Triangulation& t) {
        std::vector<double> a = intrinsic::allCornerAngles(t.tri);
        return toArray(std::move(a), 3);
      },
      "Corner angles in radians, float64 (num_faces, 3): [f, k] is the angle at vertex faces[f, k].");
  c.def(
      "angle_deficits", [](const Triangulation& t) { return toArray(intrinsic::vertexCurvatures(t.tri)); },
      "Discrete Gaussian curvature per vertex, float64 (num_vertices,): 2 pi - (angle sum) at interior vertices, "
      "pi - (angle sum) (the boundary turning angle) at boundary vertices.");
  c.def(
      "boundary_loop_vertices",
      [](const Triangulation& t) {
        py::list loops;
        for (const auto& loop : t.tri.mesh.boundaryLoops()) {
          std::vector<int> v;
          for (int h : loop) v.push_back(t.tri.mesh.tail(h));
          loops.append(toArray(std::move(v)));
        }
        return loops;
      },
      "The boundary loops, each an int32 array of its vertices in order.");
  c.def(
      "summary", [](const Triangulation& t) { return toPython(summaryJson(t)); },
      "The report of `conformesh info --json` as a dict: topology, curvature totals, the Gauss-Bonnet residual, "
      "angle and length ranges, non-Delaunay edges.");
  c.def(
      "delaunay",
      [](const Triangulation& t) {
        auto out = std::make_shared<Triangulation>();
        out->tri = t.tri;
        out->source = t.source;
        py::gil_scoped_release release;
        const intrinsic::DelaunayReport r = intrinsic::makeDelaunay(out->tri);
        return py::make_tuple(out, r.flips);
      },
      "The intrinsic Delaunay triangulation of the same surface (edge flips, `conformesh info --delaunay`): "
      "returns (triangulation, flips). Positions and fields are not carried (vertices are kept, faces change).");
  c.def(
      "with_fields",
      [](const Triangulation& t, const py::dict& fields) {
        auto out = std::make_shared<Triangulation>(t);
        for (const auto& [key, value] : fields) {
          const std::string name = py::str(key);
          out->fields[name] = vectorFromArray(value, "with_fields: '" + name + "'", t.tri.mesh.nVertices());
        }
        return out;
      },
      py::arg("fields"), "A copy with these per-vertex fields added (or replaced).");
  c.def("__repr__", [](const Triangulation& t) {
    return "<conformesh.Triangulation " + std::to_string(t.tri.mesh.nVertices()) + " vertices, " +
           std::to_string(t.tri.mesh.nFaces()) + " faces, genus " +
           std::to_string(componentSum(t, &intrinsic::ComponentTopology::genus)) + ", " +
           intrinsic::toString(t.tri.background) + ">";
  });

  m.def("read", &readPath, py::arg("path"), R"doc(
Reads a mesh file (.obj, .off, .ply: ASCII or binary) as a Triangulation, as the CLI does: lengths from the PLY edge
element when present, otherwise from the positions; per-vertex properties become ``fields``; vertices used by no face
are removed. Raises InputError naming the file, line and element.)doc");
  m.def("write", &writePath, py::arg("path"), py::arg("tri"), py::arg("fields") = py::none(),
        py::arg("positions") = py::none(), py::arg("ascii") = false, R"doc(
Writes ``tri`` by the file extension: .ply (binary little-endian, or ASCII with ascii=True; edge lengths, positions,
every field), .obj and .off (need positions; lengths and fields are dropped), .vtk (legacy VTK for ParaView; needs
positions). ``fields`` (name -> per-vertex array) are added to tri.fields; ``positions`` replace tri.positions.
Numbers are written exactly; the file is written to a temporary name and renamed, so a failed write leaves no
partial file. Raises InputError naming the path and the element.)doc");
}

}  // namespace conformesh::python
