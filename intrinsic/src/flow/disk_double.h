// disk_double.h (private) — the double of a disk: the disk glued to its mirror copy along the boundary, a closed
// genus-0 surface in which every edge is interior (flippable), for the variational route to circle domains
// (docs/ricci_flow.md §3.3, "The double"). Combinatorics and lengths only; reads its input.
#pragma once

#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"

namespace conformesh::intrinsic::detail {

struct DiskDouble {
  IntrinsicTriangulation surface;  // closed; vertices 0..n−1 the disk's, then one mirror copy per interior vertex
  std::vector<int> mirror;         // per vertex of `surface`: its mirror image (a boundary vertex is its own)
  int diskFaces = 0;               // faces 0..diskFaces−1 are the disk's, the rest their mirror images
};

// The double of `disk` (one component, genus 0, one boundary loop; any background, lengths copied): mirror face of
// (a, b, c) is (c', b', a') (reversed, so the double is oriented), glued to the disk along the boundary edges; an
// interior edge between two boundary vertices appears twice (a multi-edge, kept apart by edge ids). Throws InputError
// when `disk` has no boundary.
DiskDouble doubleDisk(const IntrinsicTriangulation& disk);

}  // namespace conformesh::intrinsic::detail
