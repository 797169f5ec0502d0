// from_edge_lengths.cpp — faces and per-corner lengths to an IntrinsicTriangulation (from_edge_lengths.h): the lengths
// are checked and merged per edge here, then toTriangulation builds and validates the triangulation.
#include "conformesh/intrinsic/mesh/from_edge_lengths.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

std::string FromEdgeLengthsOptions::validate() const {
  if (!(relativeTolerance >= 0 && relativeTolerance < 1))
    return "relativeTolerance must be in [0, 1), found " + formatNumber(relativeTolerance);
  return "";
}

namespace {

std::string sideName(const std::array<int, 3>& face, int f, int k) {
  return "face " + std::to_string(f) + " side " + std::to_string(k) + " (vertices " + std::to_string(face[k]) + ", " +
         std::to_string(face[(k + 1) % 3]) + ")";
}

// One EdgeRecord per endpoint pair, the corners' lengths checked and merged; also the vertex count.
MeshData mergedEdges(const std::vector<std::array<int, 3>>& faces, const std::vector<std::array<double, 3>>& lengths,
                     const FromEdgeLengthsOptions& o) {
  MeshData d;
  d.source = o.source;
  d.background = o.background;
  d.faces = faces;
  std::unordered_map<std::uint64_t, std::pair<int, int>> first;  // pair → (record, face that gave it)
  for (size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      if (a < 0 || b < 0)
        throw InputError(describeAt(
            o.source, "face " + std::to_string(f) + ": negative vertex index " + std::to_string(std::min(a, b))));
      d.nVertices = std::max({d.nVertices, a + 1, b + 1});
      const double l = lengths[f][k];
      if (!std::isfinite(l) || l <= 0)
        throw InputError(describeAt(o.source, sideName(faces[f], f, k) + ": length " + formatNumber(l) +
                                                  ", expected a finite positive number"));
      const std::uint64_t key = (static_cast<std::uint64_t>(std::max(a, b)) << 32) | std::uint64_t(std::min(a, b));
      const auto [it, fresh] = first.try_emplace(key, static_cast<int>(d.edges.size()), static_cast<int>(f));
      if (fresh) {
        d.edges.push_back({a, b, l});
        continue;
      }
      EdgeRecord& r = d.edges[it->second.first];
      if (std::abs(r.length - l) > o.relativeTolerance * std::max(r.length, l))
        throw InputError(describeAt(o.source, sideName(faces[f], f, k) + " has length " + formatNumber(l) +
                                                  " but face " + std::to_string(it->second.second) +
                                                  " gives that edge " + formatNumber(r.length) +
                                                  " (relative tolerance " + formatNumber(o.relativeTolerance) + ")"));
      r.length = 0.5 * (r.length + l);
    }
  }
  return d;
}

}  // namespace

IntrinsicTriangulation fromEdgeLengths(const std::vector<std::array<int, 3>>& faces,
                                       const std::vector<std::array<double, 3>>& lengths,
                                       const FromEdgeLengthsOptions& options, ConversionReport* report) {
  if (const std::string bad = options.validate(); !bad.empty())
    throw InputError(describeAt(options.source, "FromEdgeLengthsOptions: " + bad));
  if (faces.size() != lengths.size())
    throw InputError(describeAt(options.source, "expected one length triple per face (" + std::to_string(faces.size()) +
                                                    " faces), found " + std::to_string(lengths.size())));
  if (faces.empty()) throw InputError(describeAt(options.source, "the mesh has no faces"));
  return toTriangulation(mergedEdges(faces, lengths, options), report);
}

}  // namespace conformesh::intrinsic
