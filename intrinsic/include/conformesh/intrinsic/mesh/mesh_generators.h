// mesh_generators.h — surfaces with known answers at any size: icosphere, torus of revolution, closed genus-g slab,
// disk, annulus, flat torus of any lattice, and a random perturbation of the edge lengths into a non-embedded metric.
//
// Every generator returns MeshData (positions + faces, or faces + edges with lengths for the metric-only flat torus)
// in O(number of faces) time, consistently oriented (outward normals for the closed surfaces, counter-clockwise seen
// from +z for the planar ones), with exact vertex/edge/face counts stated below, so that tests and benchmarks can check
// topology (χ, genus, boundary loops), Gauss–Bonnet (total curvature 2πχ) and area convergence against closed forms.
// docs/cli.md ("generate") lists the known answers; `conformesh generate` is the command-line front end.
#pragma once

#include <complex>
#include <utility>

#include "conformesh/intrinsic/mesh/mesh_data.h"

namespace conformesh::intrinsic {

// =====================================================================================================================
// Icosphere
// =====================================================================================================================

struct IcosphereOptions {
  int level = 3;        // subdivision level L ≥ 0: 20·4^L faces, 30·4^L edges, 10·4^L + 2 vertices (χ = 2)
  double radius = 1.0;  // every vertex lies on the sphere of this radius
};
// The icosahedron inscribed in the sphere, subdivided L times: each triangle is split into four by its edge midpoints
// and the midpoints are projected radially onto the sphere (Loop-style 1-to-4 split with projection at every level).
// The inscribed polyhedron's area converges to 4πR² with error O(h²), h the mean edge length.
MeshData makeIcosphere(const IcosphereOptions& options = {});

// =====================================================================================================================
// Torus of revolution
// =====================================================================================================================

struct TorusOptions {
  double majorRadius = 1.0;         // R: distance from the axis (z) to the centre of the tube
  double minorRadius = 0.4;         // r: tube radius, 0 < r < R (no self-intersection)
  int n = 60;                       // vertices around the axis (u = 2πi/n), n ≥ 3; the default matches n/m = R/r
  int m = 24;                       // vertices around the tube (v = 2πj/m), m ≥ 3
  bool alternateDiagonals = false;  // false: every quad split along (i,j)–(i+1,j+1); true: checkerboard of the two
                                    // diagonals (then n and m must be even so the pattern closes up periodically)
};
// Vertex (i, j) at ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), index i·m + j. V = nm, E = 3nm, F = 2nm,
// χ = 0, genus 1. Area of the inscribed surface → 4π²Rr with error O(h²). Triangles are well shaped when the two grid
// spacings are comparable, i.e. n/m ≈ R/r.
MeshData makeTorus(const TorusOptions& options = {});

// =====================================================================================================================
// Closed genus-g surface: the boundary of a thickened planar domain with g square holes
// =====================================================================================================================

struct GenusSurfaceOptions {
  int genus = 2;          // g ≥ 0 (g = 0 gives the boundary of a box, a sphere)
  int resolution = 8;     // N ≥ 1: grid squares per unit cell along every side; all triangles are right isosceles
  double cellSize = 1.0;  // side of one unit cell in R³
};
// The planar domain D is the rectangle [0, 2g+1] × [0, 3] (in cells) minus the g unit squares [2k+1, 2k+2] × [1, 2],
// k = 0..g−1; the solid D × [0, 1] is a handlebody of genus g and its boundary is a closed orientable polyhedral
// surface of genus g without self-intersections. Top and bottom are N×N grids per cell, each grid square split along
// its (i,j)–(i+1,j+1) diagonal; the outer wall and the g hole walls are N-layer strips of squares split the same way.
// With W = 2g+1, P = 2(W+3)N + 4gN (grid edges on the g+1 boundary loops of D):
//   V = 2[(WN+1)(3N+1) − g(N−1)²] + (N−1)P,  F = 4(3W−g)N² + 2NP,  E = 3F/2,  χ = V − E + F = 2 − 2g.
// Area = cellSize²·(2(3W − g) + 2(W+3) + 4g) exactly. Curvature: +π/2 at the 8 corners of the outer wall, −π/2 at the
// 8g corners of the hole walls, 0 elsewhere; Σ = 2π(2 − 2g).
MeshData makeGenusSurface(const GenusSurfaceOptions& options = {});

// =====================================================================================================================
// Disk and annulus
// =====================================================================================================================

struct DiskOptions {
  int rings = 8;        // N ≥ 1 concentric rings of radii kR/N, k = 1..N, ring k carrying 6k vertices
  double radius = 1.0;  // R
};
// Centre vertex plus N rings; consecutive rings are stitched by merging their vertices in angular order. V = 3N(N+1)+1,
// F = 6N², E = 9N² + 3N, χ = 1, one boundary loop of 6N edges. The boundary is the regular 6N-gon inscribed in the
// circle, so the area is 3N·R² sin(π/(3N)) → πR² with error O(N⁻²).
MeshData makeDisk(const DiskOptions& options = {});

struct AnnulusOptions {
  double innerRadius = 0.5;  // r1 > 0
  double outerRadius = 1.0;  // r2 > r1
  int rings = 8;             // N ≥ 1 layers of triangles between r1 and r2
};
// Log-polar grid: ring k has radius r1·q^k, q = (r2/r1)^(1/N), k = 0..N, and every ring carries the same number
// n = max(3, round(2πN / ln(r2/r1))) of vertices, so that every grid cell is the image of a near-square under the
// conformal map exp and all triangles have nearly the same shape whatever r2/r1 is. Cells are split along the
// (k,j)–(k+1,j+1) diagonal. V = n(N+1), F = 2nN, E = 3nN + n, χ = 0, two boundary loops. The area is that of the outer
// inscribed n-gon minus the inner one: (n/2) sin(2π/n)(r2² − r1²) → π(r2² − r1²) with error O(n⁻²).
MeshData makeAnnulus(const AnnulusOptions& options = {});
// The n above, exposed so that tests and the CLI can state counts before generating.
int annulusRingVertexCount(const AnnulusOptions& options);

// =====================================================================================================================
// Flat torus C/(ω1 Z + ω2 Z), metric only
// =====================================================================================================================

struct FlatTorusOptions {
  std::complex<double> omega1{1.0, 0.0};  // periods: must be R-linearly independent (Im(ω2/ω1) ≠ 0)
  std::complex<double> omega2{0.0, 1.0};
  int n = 16;  // n ≥ 1: an n×n grid of the period parallelogram
  // Replace (ω1, ω2) by the Lagrange–Gauss reduced basis of the same lattice (|ω1| ≤ |ω2| ≤ |ω2 ± ω1|) before building
  // the grid. The vertex set (1/n)Λ mod Λ is the same for every basis of Λ; with the reduced basis every triangle is
  // non-obtuse, so the triangulation is Delaunay. false keeps the given basis (cells may then be long and thin).
  bool reduceBasis = true;
};
// Vertex (i, j) ↔ (iω1 + jω2)/n, index i·n + j. Edges along ω1/n, ω2/n and the shorter of (ω1 ± ω2)/n (the Delaunay
// diagonal of the parallelogram cell), lengths from the lattice vectors; no positions. V = n², E = 3n², F = 2n², χ = 0,
// every vertex has angle sum exactly 2π (curvature 0), area = |Im(conj(ω1)·ω2)|. For n < 3 the grid has multi-edges
// and self-loops, so the faces carry `cornerEdges` (a Δ-complex: n = 1 is the one-vertex torus).
MeshData makeFlatTorus(const FlatTorusOptions& options = {});
// The Lagrange–Gauss reduction used above: a basis of the same lattice with |ω1| ≤ |ω2| ≤ |ω2 ± ω1|.
std::pair<std::complex<double>, std::complex<double>> reduceLatticeBasis(std::complex<double> omega1,
                                                                         std::complex<double> omega2);

// =====================================================================================================================
// Known answers
// =====================================================================================================================

// What a generated surface is known to be, from the construction and the smooth surface it samples: printed by
// `conformesh generate` and used by tests and benchmarks as references. Total curvature is 2π·eulerCharacteristic.
struct KnownAnswers {
  int eulerCharacteristic = 0;
  int genus = 0;
  int boundaryLoops = 0;
  double area = 0;  // area of the smooth surface (icosphere 4πR², torus 4π²Rr, disk πR², annulus π(r2²−r1²))
  bool areaIsExact = false;  // true when the mesh area equals `area` to round-off (genus slab, flat torus); otherwise
                             // the mesh area converges to it at order 2 in the edge length
};
KnownAnswers knownAnswers(const IcosphereOptions& options);
KnownAnswers knownAnswers(const TorusOptions& options);
KnownAnswers knownAnswers(const GenusSurfaceOptions& options);
KnownAnswers knownAnswers(const DiskOptions& options);
KnownAnswers knownAnswers(const AnnulusOptions& options);
KnownAnswers knownAnswers(const FlatTorusOptions& options);

// =====================================================================================================================
// Random metric perturbation
// =====================================================================================================================

// Relative slack every perturbed triangle keeps: (b + c − a)/(a + b + c) ≥ min(kPerturbMinRelativeSlack, σ₀/2) for
// each side a, σ₀ being the face's slack before perturbation. 10⁻³ keeps every angle below ≈ 173°, far from the caps
// where angles would lose digits, while allowing amplitudes up to ~1 on well-shaped meshes.
constexpr double kPerturbMinRelativeSlack = 1e-3;

struct PerturbReport {
  int edges = 0;                 // edges in the output `edges` list
  int shrunkEdges = 0;           // edges whose perturbation had to be reduced to restore the triangle inequalities
  int passes = 0;                // validation passes over all faces
  double maxRelativeChange = 0;  // max |ℓ'/ℓ − 1| over edges (≤ amplitude)
};

// Replaces the metric of `data` by ℓ'_e = ℓ_e·(1 + amplitude·t_e), t_e uniform in (−1, 1) from std::mt19937(seed)
// (raw 32-bit outputs, so the result is the same on every platform). ℓ comes from `edges` when present, otherwise from
// the positions, in which case the `edges` list is created (one record per mesh edge; from `cornerEdges` when present).
// Then every face's triangle inequality is checked with the margin above; the t_e of the three edges of each offending
// face are halved, and the check repeated until all faces pass (t_e reaches exactly 0 after 60 halvings, so this
// terminates with the original, valid lengths as the worst case).
//
// The result is a genuine piecewise-flat metric (a cone metric with generally nonzero angle defects everywhere) that in
// general has no isometric realization in R³ with these triangles as flat faces — positions are kept only as a picture
// of the unperturbed surface and no longer agree with the lengths; toTriangulation() uses the `edges`. Throws
// InputError for amplitude ∉ [0, 1), a mesh without positions or edges, or an input face that already violates the
// triangle inequality (named with its index and lengths).
PerturbReport perturbLengths(MeshData& data, double amplitude, unsigned seed);

}  // namespace conformesh::intrinsic
