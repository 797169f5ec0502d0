// test_meshes.h — tiny closed-form meshes for the core tests (icosahedron, torus and planar grids, a one-vertex torus
// Δ-complex, a flat cylinder, disjoint surfaces joined in one file), built here rather than by the library's generators so that the core is tested
// independently of them; and the split of a real mesh file into its connected components.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::testing {

using intrinsic::MeshData;

// The regular icosahedron inscribed in the unit sphere.
inline MeshData icosahedron() {
  MeshData d;
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double raw[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                             {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : raw) d.positions.push_back(Eigen::Vector3d(p[0], p[1], p[2]).normalized());
  d.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  d.nVertices = 12;
  d.source = "icosahedron";
  return d;
}

// An n × m grid on the torus of revolution (R, r), each quad split along the same diagonal: closed, genus 1.
inline MeshData torusGrid(int n, int m, double R = 2.0, double r = 0.7) {
  MeshData d;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      d.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                               r * std::sin(v));
    }
  auto id = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      d.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      d.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  d.nVertices = n * m;
  d.source = "torus grid";
  return d;
}

// The unit square [0,1]² as an n × n grid of right triangles: a disk with one boundary loop.
inline MeshData squareGrid(int n) {
  MeshData d;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) d.positions.emplace_back(double(i) / n, double(j) / n, 0.0);
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      d.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      d.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  d.nVertices = (n + 1) * (n + 1);
  d.source = "square grid";
  return d;
}

// Moves every vertex by a uniform random vector of the given size: lengths stay a valid metric (they come from
// positions) while many edges stop being Delaunay.
inline void jitter(MeshData& d, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (auto& p : d.positions) p += Eigen::Vector3d(u(rng), u(rng), u(rng));
}

// The one-vertex torus: a unit square with sides a (bottom, top) and b (left, right) identified and diagonal c.
// Three self-loop edges, two faces; only constructible with explicit edge ids.
inline MeshData oneVertexTorus(double a = 1.0, double b = 1.0) {
  MeshData d;
  d.nVertices = 1;
  d.faces = {{0, 0, 0}, {0, 0, 0}};
  // Face 0: bottom a (→), right b (↑), diagonal c back to the start. Face 1: diagonal c (↗), top a (←), left b (↓).
  d.cornerEdges = {{0, 1, 2}, {2, 0, 1}};
  d.edges = {{0, 0, a}, {0, 0, b}, {0, 0, std::hypot(a, b)}};
  d.source = "one-vertex torus";
  return d;
}

// A tube over the regular n-gon inscribed in the unit circle, `rows` rows of triangles up to height `height`, ring i
// rotated by half a step against ring i − 1: a flat cylinder (its faces unroll into a strip) of circumference
// C = 2n sin(π/n), hence conformal to the annulus with log(R/r) = 2π height / C exactly.
inline MeshData cylinderGrid(int n, int rows, double height) {
  MeshData d;
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j < n; ++j) {
      const double t = 2 * M_PI * (j + 0.5 * i) / n;
      d.positions.emplace_back(std::cos(t), std::sin(t), height * i / rows);
    }
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * n + j, b = i * n + (j + 1) % n, c = (i + 1) * n + j, e = (i + 1) * n + (j + n - 1) % n;
      d.faces.push_back({a, b, c});
      d.faces.push_back({a, c, e});
    }
  d.nVertices = (rows + 1) * n;
  d.source = "cylinder grid";
  return d;
}

// The connected components of a polygon soup (faces joined through shared vertices), in the order of their first
// faces. Each keeps every position and only its own faces: toTriangulation drops the vertices no face uses. Used to
// take one surface out of a real file that holds several (CGAL's blobby_3cc.off), leaving its triangles untouched.
inline std::vector<MeshData> connectedComponents(const MeshData& d) {
  std::vector<int> parent(d.nVertices);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& f : d.faces)
    for (int k = 1; k < 3; ++k) parent[find(f[k])] = find(f[0]);
  std::map<int, int> componentOfRoot;
  std::vector<MeshData> out;
  for (const auto& f : d.faces) {
    const auto [it, added] = componentOfRoot.emplace(find(f[0]), static_cast<int>(out.size()));
    if (added) {
      out.emplace_back();
      out.back().nVertices = d.nVertices;
      out.back().positions = d.positions;
      out.back().source = d.source + " (component " + std::to_string(it->second) + ")";
    }
    out[it->second].faces.push_back(f);
  }
  return out;
}

// Disjoint surfaces side by side in one file's data (vertex indices offset), written out here rather than by the
// library's concatenateMeshData, which the component tests check against it.
inline MeshData joinByHand(const std::vector<MeshData>& parts) {
  MeshData out;
  for (const MeshData& p : parts) {
    for (const auto& f : p.faces) out.faces.push_back({f[0] + out.nVertices, f[1] + out.nVertices, f[2] + out.nVertices});
    out.positions.insert(out.positions.end(), p.positions.begin(), p.positions.end());
    out.nVertices += p.nVertices;
  }
  return out;
}

}  // namespace conformesh::testing
