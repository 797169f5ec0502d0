// disk_double.cpp — the double of a disk (disk_double.h).
#include "flow/disk_double.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/mesh/intrinsic_flips.h"

namespace conformesh::intrinsic::detail {

DiskDouble doubleDisk(const IntrinsicTriangulation& disk) {
  const HalfedgeMesh& m = disk.mesh;
  const int nV = m.nVertices(), nF = m.nFaces(), nE = m.nEdges();
  DiskDouble out;
  int next = nV;
  std::vector<int> copy(nV);
  for (int v = 0; v < nV; ++v) copy[v] = m.isBoundaryVertex(v) ? v : next++;
  out.mirror.resize(next);
  for (int v = 0; v < nV; ++v) {
    out.mirror[v] = copy[v];
    out.mirror[copy[v]] = v;
  }
  bool anyBoundary = false;
  std::vector<std::array<int, 3>> faces(2 * nF), edgeIds(2 * nF);
  for (int f = 0; f < nF; ++f) {
    int v[3], e[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = m.faceVertex(f, k);
      e[k] = m.edge(HalfedgeMesh::halfedge(f, k));
      anyBoundary = anyBoundary || m.isBoundaryEdge(e[k]);
    }
    // A boundary edge is shared by the disk and its mirror; an interior one gets its own mirror id.
    auto mirrored = [&](int edge) { return m.isBoundaryEdge(edge) ? edge : nE + edge; };
    faces[f] = {v[0], v[1], v[2]};
    edgeIds[f] = {e[0], e[1], e[2]};
    // (c', b', a'): corner 0 runs c'→b' (the mirror of b→c), corner 1 b'→a', corner 2 a'→c'.
    faces[nF + f] = {out.mirror[v[2]], out.mirror[v[1]], out.mirror[v[0]]};
    edgeIds[nF + f] = {mirrored(e[1]), mirrored(e[0]), mirrored(e[2])};
  }
  if (!anyBoundary) throw InputError("doubleDisk: the surface has no boundary to glue along");
  // fromFaces wants the ids 0..E−1 without gaps: number them in order of first use; keep each one's disk edge.
  std::vector<int> renumber(2 * nE, -1), diskEdge;
  for (std::array<int, 3>& ids : edgeIds)
    for (int& id : ids) {
      if (renumber[id] < 0) {
        renumber[id] = static_cast<int>(diskEdge.size());
        diskEdge.push_back(id < nE ? id : id - nE);
      }
      id = renumber[id];
    }
  out.surface.mesh = HalfedgeMesh::fromFaces(faces, next, "double of a disk", nullptr, edgeIds);
  out.surface.background = disk.background;
  out.surface.edgeLengths.assign(out.surface.mesh.nEdges(), 0.0);
  for (int f = 0; f < 2 * nF; ++f)
    for (int k = 0; k < 3; ++k)
      out.surface.edgeLengths[out.surface.mesh.edge(HalfedgeMesh::halfedge(f, k))] =
          disk.edgeLengths[diskEdge[edgeIds[f][k]]];
  out.diskFaces = nF;
  return out;
}

namespace {

// The side of the mirror a vertex of the double lies on: +1 the disk's interior, −1 the mirror's, 0 the boundary.
int halfSide(const DiskDouble& twin, int v, int diskVertices) {
  return twin.mirror[v] == v ? 0 : (v < diskVertices ? 1 : -1);
}

// Twice the signed area of the planar triangle (a, b, c) over its squared perimeter-ish scale: a scale-free quality,
// negative for a clockwise (folded) triangle.
double halfTriangleQuality(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d ab = b - a, ac = c - a;
  const double area2 = ab.x() * ac.y() - ab.y() * ac.x();
  return area2 / (ab.squaredNorm() + ac.squaredNorm() + (c - b).squaredNorm());
}

}  // namespace

void locateOnInputBoundary(const IntrinsicTriangulation& disk, const DiskDouble& twin, const HalfedgeMesh& doubled,
                           const FlowCorrespondence& log, const std::vector<FacePoint>& crossings,
                           std::vector<HalfBoundaryVertex>& inserted) {
  const std::vector<FacePoint> onInput = log.mapToInput(doubled, crossings);
  for (std::size_t i = 0; i < onInput.size(); ++i) {
    int f = onInput[i].face;
    std::array<double, 3> b = onInput[i].bary;
    if (f >= twin.diskFaces) {
      f -= twin.diskFaces;
      std::swap(b[0], b[2]);
    }
    const int j = static_cast<int>(std::min_element(b.begin(), b.end()) - b.begin());
    const int h = HalfedgeMesh::halfedge(f, (j + 1) % 3);  // the edge opposite corner j
    const int e = disk.mesh.edge(h);
    HalfBoundaryVertex& q = inserted[i];
    q.inputEdge = e;
    q.offEdge = b[j];
    const double tail = b[(j + 1) % 3], tip = b[(j + 2) % 3];
    q.parameter = disk.mesh.edgeHalfedge(e) == h ? tip / (tail + tip) : tail / (tail + tip);
    if (!disk.mesh.isBoundaryEdge(e) || !(std::abs(b[j]) <= 1e-8)) {
      std::ostringstream message;
      message.precision(3);
      message << "uniformize: half of the double: new boundary vertex " << q.vertex << " maps to face " << f
              << " of the input at barycentric (" << b[0] << ", " << b[1] << ", " << b[2]
              << "), not onto an input boundary edge";
      throw ConvergenceError(message.str());
    }
  }
}

DiskHalf halveDoubleSphere(const IntrinsicTriangulation& disk, const DiskDouble& twin, const Uniformization& sphere) {
  const HalfedgeMesh& m = sphere.uniform.mesh;
  const int n = disk.mesh.nVertices();
  // The mirror plane's normal, toward the disk (the solution is symmetric up to a rotation, docs/ricci_flow.md §3.3).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int v = 0; v < n; ++v) normal += sphere.positions[v] - sphere.positions[twin.mirror[v]];
  normal.normalize();
  for (int v = 0; v < m.nVertices(); ++v) {
    const int side = halfSide(twin, v, n);
    if (side * sphere.positions[v].dot(normal) < 0 || (side != 0 && sphere.positions[v].dot(normal) == 0))
      throw ConvergenceError("uniformize: half of the double: vertex " + std::to_string(v) +
                             " of the double lies on the wrong side of the mirror's great circle");
  }
  DiskHalf out;
  std::vector<Eigen::Vector3d> x(sphere.positions.begin(), sphere.positions.begin() + n);
  std::vector<int> crossingVertex(m.nEdges(), -1);
  std::vector<FacePoint> crossings;
  for (int e = 0; e < m.nEdges(); ++e) {
    const int h = m.edgeHalfedge(e), a = m.tail(h), b = m.tip(h);
    if (halfSide(twin, a, n) * halfSide(twin, b, n) >= 0) continue;
    // The geodesic ab meets the great circle x·n = 0 where its chord (1 − s) x_a + s x_b does, s = a·n/(a·n − b·n):
    // the chord triangle's coordinates are those of the correspondence (flow_correspondence.h).
    const double da = sphere.positions[a].dot(normal), db = sphere.positions[b].dot(normal);
    const double s = da / (da - db);
    crossingVertex[e] = n + static_cast<int>(crossings.size());
    x.push_back(((1 - s) * sphere.positions[a] + s * sphere.positions[b]).normalized());
    FacePoint p;
    p.face = HalfedgeMesh::face(h);
    p.bary = {0, 0, 0};
    p.bary[h % 3] = 1 - s;
    p.bary[(h % 3 + 1) % 3] = s;
    crossings.push_back(p);
    HalfBoundaryVertex q;
    q.vertex = crossingVertex[e];
    q.selfMirror = twin.mirror[a] == b;
    out.selfMirrorCrossings += q.selfMirror;
    out.inserted.push_back(q);
  }
  out.crossingEdges = static_cast<int>(crossings.size());
  // Stereographic projection from the mirror pole −n: z = x⊥/(1 + x·n), the great circle onto |z| = 1.
  const Eigen::Vector3d e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
  std::vector<Eigen::Vector2d> z(x.size());
  for (std::size_t v = 0; v < x.size(); ++v)
    z[v] = Eigen::Vector2d(x[v].dot(e1), x[v].dot(e2)) / (1 + x[v].dot(normal));
  // Each face of the double clipped to the disk's side: a triangle, a quadrilateral (split along the better diagonal
  // in the plane), or nothing.
  std::vector<std::array<int, 3>> faces;
  for (int f = 0; f < m.nFaces(); ++f) {
    int positive = 0, negative = 0;
    std::vector<int> polygon;
    for (int k = 0; k < 3; ++k) {
      const int v = m.faceVertex(f, k), side = halfSide(twin, v, n);
      positive += side > 0;
      negative += side < 0;
      if (side >= 0) polygon.push_back(v);
      if (crossingVertex[m.edge(HalfedgeMesh::halfedge(f, k))] >= 0)
        polygon.push_back(crossingVertex[m.edge(HalfedgeMesh::halfedge(f, k))]);
    }
    if (positive == 0 && negative == 0)
      throw ConvergenceError("uniformize: half of the double: face " + std::to_string(f) +
                             " of the double has all three vertices on the mirror's great circle");
    if (positive == 0) continue;
    if (polygon.size() == 3) {
      faces.push_back({polygon[0], polygon[1], polygon[2]});
      continue;
    }
    const int* p = polygon.data();
    const double q02 =
        std::min(halfTriangleQuality(z[p[0]], z[p[1]], z[p[2]]), halfTriangleQuality(z[p[0]], z[p[2]], z[p[3]]));
    const double q13 =
        std::min(halfTriangleQuality(z[p[1]], z[p[2]], z[p[3]]), halfTriangleQuality(z[p[1]], z[p[3]], z[p[0]]));
    if (q02 >= q13) {
      faces.push_back({p[0], p[1], p[2]});
      faces.push_back({p[0], p[2], p[3]});
    } else {
      faces.push_back({p[1], p[2], p[3]});
      faces.push_back({p[1], p[3], p[0]});
    }
  }
  for (const std::array<int, 3>& t : faces)
    if (!(halfTriangleQuality(z[t[0]], z[t[1]], z[t[2]]) > 0)) {
      std::ostringstream message;
      message << "uniformize: half of the double: the projected face (" << t[0] << ", " << t[1] << ", " << t[2]
              << ") is folded or degenerate in the plane";
      throw ConvergenceError(message.str());
    }
  out.plane.mesh = HalfedgeMesh::fromFaces(faces, static_cast<int>(x.size()), "half of the double of a disk");
  out.plane.background = Background::Euclidean;
  out.plane.edgeLengths.resize(out.plane.mesh.nEdges());
  for (int e = 0; e < out.plane.mesh.nEdges(); ++e) {
    const int h = out.plane.mesh.edgeHalfedge(e);
    out.plane.edgeLengths[e] = (z[out.plane.mesh.tip(h)] - z[out.plane.mesh.tail(h)]).norm();
  }
  // A straight-line triangulation of the plane stays one under Lawson flips (a non-Delaunay edge's quad is convex).
  out.delaunayFlips = static_cast<int>(makeDelaunay(out.plane).flips);
  out.positions.resize(x.size());
  for (std::size_t v = 0; v < x.size(); ++v) out.positions[v] = Eigen::Vector3d(z[v].x(), z[v].y(), 0.0);
  // λ of an input vertex: the sphere's, less the projection's factor log 2 − 2 log|x − p| (the restart's u, negated).
  out.lambda.resize(x.size());
  for (int v = 0; v < n; ++v)
    out.lambda[v] = sphere.lambda[v] - std::log(2.0) + 2 * std::log((sphere.positions[v] + normal).norm());
  locateOnInputBoundary(disk, twin, sphere.uniform.mesh, sphere.correspondence, crossings, out.inserted);
  for (const HalfBoundaryVertex& q : out.inserted) {
    const int h = disk.mesh.edgeHalfedge(q.inputEdge);
    out.lambda[q.vertex] =
        (1 - q.parameter) * out.lambda[disk.mesh.tail(h)] + q.parameter * out.lambda[disk.mesh.tip(h)];
  }
  return out;
}

}  // namespace conformesh::intrinsic::detail
