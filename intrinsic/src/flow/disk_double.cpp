// disk_double.cpp — the double of a disk (disk_double.h).
#include "flow/disk_double.h"

#include <array>

#include "conformesh/intrinsic/errors.h"

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

}  // namespace conformesh::intrinsic::detail
