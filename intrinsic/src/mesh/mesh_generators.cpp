// mesh_generators.cpp — icosphere, torus, genus-g slab, disk, annulus, flat torus, and the random length perturbation
// (see mesh_generators.h for the constructions and their exact counts).
//
// Everything is O(number of faces): the icosphere carries edge ids through its subdivision levels instead of looking
// midpoints up by endpoint pair, the grids index their vertices arithmetically, and the perturbation matches faces to
// edges through a bucket sort on the smaller endpoint. Orientation is built in (outward / counter-clockwise) rather
// than repaired afterwards.
#include "conformesh/intrinsic/mesh/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Face counts beyond this overflow the int indices of MeshData/HalfedgeMesh (3F halfedges must fit in an int).
constexpr long long kMaxFaces = std::numeric_limits<int>::max() / 3;

// The shortest decimal (at least 6 significant digits, as iostreams print) that reads back as x: 0.4, not
// 0.40000000000000002.
std::string shortestDecimal(double x) {
  for (int digits = 6;; ++digits) {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    if (digits >= 17 || !std::isfinite(x) || std::stod(s.str()) == x) return s.str();
  }
}

void requireGenerator(bool ok, const std::string& generator, const std::string& what) {
  if (!ok) throw InputError(generator + ": " + what);
}

void requireFaceCount(long long faces, const std::string& generator) {
  requireGenerator(faces <= kMaxFaces, generator,
          "would have " + std::to_string(faces) + " faces; at most " + std::to_string(kMaxFaces) + " are supported");
}

bool finitePositive(double x) {
  return std::isfinite(x) && x > 0;
}

}  // namespace

// =====================================================================================================================
// Icosphere
// =====================================================================================================================

MeshData makeIcosphere(const IcosphereOptions& options) {
  const std::string name = "icosphere";
  requireGenerator(options.level >= 0 && options.level <= 12, name,
          "level must be in 0..12 (20·4^L faces), found " + std::to_string(options.level));
  requireGenerator(finitePositive(options.radius), name, "radius must be finite and positive, found " + shortestDecimal(options.radius));
  requireFaceCount(20LL << (2 * options.level), name);

  // The icosahedron (0, ±1, ±φ) and its cyclic permutations; faces listed counter-clockwise seen from outside.
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> pos = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : pos) p = p.normalized() * options.radius;
  std::vector<std::array<int, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                           {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                           {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                           {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

  // Edge ids of level 0 by endpoint pair (60 corners: a quadratic search is cheapest). From then on edge ids are
  // derived arithmetically, which is what makes the subdivision O(F) without a hash map.
  std::vector<int> edgeTail, edgeTip;
  std::vector<std::array<int, 3>> faceEdges(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      int found = -1;
      for (std::size_t e = 0; e < edgeTail.size(); ++e)
        if ((edgeTail[e] == a && edgeTip[e] == b) || (edgeTail[e] == b && edgeTip[e] == a)) found = static_cast<int>(e);
      if (found < 0) {
        found = static_cast<int>(edgeTail.size());
        edgeTail.push_back(a);
        edgeTip.push_back(b);
      }
      faceEdges[f][k] = found;
    }
  }

  for (int level = 0; level < options.level; ++level) {
    const int nV = static_cast<int>(pos.size()), nE = static_cast<int>(edgeTail.size());
    const int nF = static_cast<int>(faces.size());
    // Midpoint of edge e becomes vertex nV + e. Edge e splits into 2e (tail → mid) and 2e+1 (mid → tip); the three
    // edges inside face f joining midpoints (k, k+1) get ids 2nE + 3f + k.
    pos.resize(nV + nE);
    for (int e = 0; e < nE; ++e) pos[nV + e] = (pos[edgeTail[e]] + pos[edgeTip[e]]).normalized() * options.radius;
    std::vector<int> newTail(2 * nE + 3 * nF), newTip(2 * nE + 3 * nF);
    for (int e = 0; e < nE; ++e) {
      newTail[2 * e] = edgeTail[e];
      newTip[2 * e] = nV + e;
      newTail[2 * e + 1] = nV + e;
      newTip[2 * e + 1] = edgeTip[e];
    }
    std::vector<std::array<int, 3>> newFaces(4 * static_cast<std::size_t>(nF)), newFaceEdges(newFaces.size());
    for (int f = 0; f < nF; ++f) {
      const auto& a = faces[f];
      const auto& fe = faceEdges[f];
      const int mid[3] = {nV + fe[0], nV + fe[1], nV + fe[2]};
      const int inner = 2 * nE + 3 * f;
      for (int k = 0; k < 3; ++k) {
        newTail[inner + k] = mid[k];
        newTip[inner + k] = mid[(k + 1) % 3];
      }
      // Half of edge e that touches vertex v.
      auto half = [&](int e, int v) { return edgeTail[e] == v ? 2 * e : 2 * e + 1; };
      for (int k = 0; k < 3; ++k) {
        const int km = (k + 2) % 3;  // k − 1
        newFaces[4 * f + k] = {a[k], mid[k], mid[km]};
        newFaceEdges[4 * f + k] = {half(fe[k], a[k]), inner + km, half(fe[km], a[k])};
      }
      newFaces[4 * f + 3] = {mid[0], mid[1], mid[2]};
      newFaceEdges[4 * f + 3] = {inner + 0, inner + 1, inner + 2};
    }
    faces.swap(newFaces);
    faceEdges.swap(newFaceEdges);
    edgeTail.swap(newTail);
    edgeTip.swap(newTip);
  }

  MeshData data;
  data.source = "icosphere(level=" + std::to_string(options.level) + ", radius=" + shortestDecimal(options.radius) + ")";
  data.nVertices = static_cast<int>(pos.size());
  data.faces = std::move(faces);
  data.positions = std::move(pos);
  return data;
}

// =====================================================================================================================
// Torus of revolution
// =====================================================================================================================

MeshData makeTorus(const TorusOptions& options) {
  const std::string name = "torus";
  const double R = options.majorRadius, r = options.minorRadius;
  requireGenerator(finitePositive(r) && std::isfinite(R) && r < R, name,
          "radii must satisfy 0 < r < R (else the torus self-intersects), found R=" + shortestDecimal(R) + ", r=" + shortestDecimal(r));
  requireGenerator(options.n >= 3 && options.m >= 3, name,
          "n and m must be at least 3 (else two vertices are joined by two edges), found n=" +
              std::to_string(options.n) + ", m=" + std::to_string(options.m));
  requireGenerator(!options.alternateDiagonals || (options.n % 2 == 0 && options.m % 2 == 0), name,
          "alternating diagonals need even n and m so the checkerboard closes up, found n=" +
              std::to_string(options.n) + ", m=" + std::to_string(options.m));
  const int n = options.n, m = options.m;
  requireFaceCount(2LL * n * m, name);

  MeshData data;
  data.source = "torus(R=" + shortestDecimal(R) + ", r=" + shortestDecimal(r) + ", n=" + std::to_string(n) + ", m=" + std::to_string(m) + ")";
  data.nVertices = n * m;
  data.positions.resize(static_cast<std::size_t>(n) * m);
  for (int i = 0; i < n; ++i) {
    const double u = 2 * kPi * i / n;
    for (int j = 0; j < m; ++j) {
      const double v = 2 * kPi * j / m;
      data.positions[i * m + j] = {(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                   r * std::sin(v)};
    }
  }
  // Quad (i,j),(i+1,j),(i+1,j+1),(i,j+1): ∂/∂u × ∂/∂v points away from the tube's core circle, so this corner order
  // gives outward normals.
  data.faces.reserve(2 * static_cast<std::size_t>(n) * m);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
      if (options.alternateDiagonals && (i + j) % 2 == 1) {
        data.faces.push_back({a, b, d});
        data.faces.push_back({b, c, d});
      } else {
        data.faces.push_back({a, b, c});
        data.faces.push_back({a, c, d});
      }
    }
  }
  return data;
}

// =====================================================================================================================
// Closed genus-g surface
// =====================================================================================================================

MeshData makeGenusSurface(const GenusSurfaceOptions& options) {
  const std::string name = "genus surface";
  const int g = options.genus, N = options.resolution;
  requireGenerator(g >= 0 && g <= 100000, name, "genus must be in 0..100000, found " + std::to_string(g));
  requireGenerator(N >= 1 && N <= 100000, name, "resolution must be in 1..100000, found " + std::to_string(N));
  requireGenerator(finitePositive(options.cellSize), name,
          "cell size must be finite and positive, found " + shortestDecimal(options.cellSize));
  const long long W = 2LL * g + 1;
  const long long P = 2 * (W + 3) * N + 4LL * g * N;
  requireFaceCount(4 * (3 * W - g) * N * N + 2LL * N * P, name);

  const int X = static_cast<int>(W) * N, Y = 3 * N;  // grid squares along x and y
  const double h = options.cellSize / N;
  // Hole k occupies cell (2k+1, 1), i.e. grid squares [(2k+1)N, (2k+2)N) × [N, 2N).
  auto holeCell = [&](int ci, int cj) { return cj == 1 && ci % 2 == 1; };
  auto insideHole = [&](int i, int j) {  // strictly inside a hole: no vertex there
    if (j <= N || j >= 2 * N) return false;
    const int ci = i / N;
    return i % N != 0 && ci % 2 == 1 && ci < W;
  };

  MeshData data;
  data.source = "genus surface(g=" + std::to_string(g) + ", resolution=" + std::to_string(N) +
                ", cell=" + shortestDecimal(options.cellSize) + ")";
  // Top sheet (z = cellSize) first, then the bottom sheet (z = 0) with the same numbering shifted by nSheet.
  std::vector<int> sheetId(static_cast<std::size_t>(X + 1) * (Y + 1), -1);
  auto gridIndex = [&](int i, int j) { return static_cast<std::size_t>(i) * (Y + 1) + j; };
  int nSheet = 0;
  for (int i = 0; i <= X; ++i)
    for (int j = 0; j <= Y; ++j)
      if (!insideHole(i, j)) sheetId[gridIndex(i, j)] = nSheet++;
  data.positions.resize(2 * static_cast<std::size_t>(nSheet));
  for (int i = 0; i <= X; ++i) {
    for (int j = 0; j <= Y; ++j) {
      const int id = sheetId[gridIndex(i, j)];
      if (id < 0) continue;
      data.positions[id] = {i * h, j * h, options.cellSize};
      data.positions[nSheet + id] = {i * h, j * h, 0.0};
    }
  }
  auto top = [&](int i, int j) { return sheetId[gridIndex(i, j)]; };
  auto bottom = [&](int i, int j) { return nSheet + sheetId[gridIndex(i, j)]; };

  // Top counter-clockwise seen from +z (outward), bottom reversed (outward is −z).
  for (int i = 0; i < X; ++i) {
    for (int j = 0; j < Y; ++j) {
      if (holeCell(i / N, j / N)) continue;
      data.faces.push_back({top(i, j), top(i + 1, j), top(i + 1, j + 1)});
      data.faces.push_back({top(i, j), top(i + 1, j + 1), top(i, j + 1)});
      data.faces.push_back({bottom(i, j), bottom(i + 1, j + 1), bottom(i + 1, j)});
      data.faces.push_back({bottom(i, j), bottom(i, j + 1), bottom(i + 1, j + 1)});
    }
  }

  // Walls: each boundary loop of D traversed with D on its left (outer loop counter-clockwise, holes clockwise), so
  // that the outward normal of the wall points to the right of the direction of travel.
  std::vector<std::vector<std::array<int, 2>>> loops;
  {
    std::vector<std::array<int, 2>> outer;
    for (int i = 0; i < X; ++i) outer.push_back({i, 0});
    for (int j = 0; j < Y; ++j) outer.push_back({X, j});
    for (int i = X; i > 0; --i) outer.push_back({i, Y});
    for (int j = Y; j > 0; --j) outer.push_back({0, j});
    loops.push_back(std::move(outer));
  }
  for (int k = 0; k < g; ++k) {
    const int x0 = (2 * k + 1) * N, y0 = N;
    std::vector<std::array<int, 2>> hole;
    for (int t = 0; t < N; ++t) hole.push_back({x0, y0 + t});
    for (int t = 0; t < N; ++t) hole.push_back({x0 + t, y0 + N});
    for (int t = 0; t < N; ++t) hole.push_back({x0 + N, y0 + N - t});
    for (int t = 0; t < N; ++t) hole.push_back({x0 + N - t, y0});
    loops.push_back(std::move(hole));
  }
  std::vector<int> layer;  // vertex of loop point s at height level l (0 = bottom, N = top): layer[l * L + s]
  for (const auto& loop : loops) {
    const int L = static_cast<int>(loop.size());
    layer.assign(static_cast<std::size_t>(N + 1) * L, -1);
    for (int s = 0; s < L; ++s) {
      layer[s] = bottom(loop[s][0], loop[s][1]);
      layer[static_cast<std::size_t>(N) * L + s] = top(loop[s][0], loop[s][1]);
      for (int l = 1; l < N; ++l) {
        layer[static_cast<std::size_t>(l) * L + s] = static_cast<int>(data.positions.size());
        data.positions.push_back({loop[s][0] * h, loop[s][1] * h, l * h});
      }
    }
    for (int l = 0; l < N; ++l) {
      for (int s = 0; s < L; ++s) {
        const int s1 = (s + 1) % L;
        const int a = layer[l * L + s], b = layer[l * L + s1], c = layer[(l + 1) * L + s1], d = layer[(l + 1) * L + s];
        data.faces.push_back({a, b, c});
        data.faces.push_back({a, c, d});
      }
    }
  }
  data.nVertices = static_cast<int>(data.positions.size());
  return data;
}

// =====================================================================================================================
// Disk and annulus
// =====================================================================================================================

MeshData makeDisk(const DiskOptions& options) {
  const std::string name = "disk";
  const int N = options.rings;
  requireGenerator(N >= 1 && N <= 100000, name, "rings must be in 1..100000, found " + std::to_string(N));
  requireGenerator(finitePositive(options.radius), name, "radius must be finite and positive, found " + shortestDecimal(options.radius));
  requireFaceCount(6LL * N * N, name);

  MeshData data;
  data.source = "disk(rings=" + std::to_string(N) + ", radius=" + shortestDecimal(options.radius) + ")";
  data.nVertices = 3 * N * (N + 1) + 1;
  data.positions.reserve(data.nVertices);
  data.positions.push_back({0, 0, 0});
  auto ringStart = [](int k) { return 1 + 3 * k * (k - 1); };  // first vertex of ring k ≥ 1
  for (int k = 1; k <= N; ++k) {
    const double rho = options.radius * k / N;
    for (int i = 0; i < 6 * k; ++i) {
      const double phi = 2 * kPi * i / (6 * k);
      data.positions.push_back({rho * std::cos(phi), rho * std::sin(phi), 0});
    }
  }
  data.faces.reserve(6 * static_cast<std::size_t>(N) * N);
  for (int i = 0; i < 6; ++i) data.faces.push_back({0, ringStart(1) + i, ringStart(1) + (i + 1) % 6});
  // Between rings k−1 and k: walk both in angular order from angle 0, always advancing the ring whose next vertex
  // comes first (exact integer comparison of (a+1)/n0 and (b+1)/n1), so every triangle spans adjacent angles.
  for (int k = 2; k <= N; ++k) {
    const int n0 = 6 * (k - 1), n1 = 6 * k, in = ringStart(k - 1), out = ringStart(k);
    int a = 0, b = 0;
    while (a < n0 || b < n1) {
      const bool advanceOuter =
          a == n0 || (b < n1 && static_cast<long long>(b + 1) * n0 < static_cast<long long>(a + 1) * n1);
      if (advanceOuter) {
        data.faces.push_back({out + b, out + (b + 1) % n1, in + a % n0});
        ++b;
      } else {
        data.faces.push_back({in + a, out + b % n1, in + (a + 1) % n0});
        ++a;
      }
    }
  }
  return data;
}

int annulusRingVertexCount(const AnnulusOptions& options) {
  const std::string name = "annulus";
  const double r1 = options.innerRadius, r2 = options.outerRadius;
  requireGenerator(finitePositive(r1) && std::isfinite(r2) && r1 < r2, name,
          "radii must satisfy 0 < r1 < r2, found r1=" + shortestDecimal(r1) + ", r2=" + shortestDecimal(r2));
  requireGenerator(options.rings >= 1 && options.rings <= 100000, name,
          "rings must be in 1..100000, found " + std::to_string(options.rings));
  const double n = std::round(2 * kPi * options.rings / std::log(r2 / r1));
  requireGenerator(n <= static_cast<double>(kMaxFaces), name,
          "r2/r1 = " + shortestDecimal(r2 / r1) + " is so close to 1 that square cells need " + shortestDecimal(n) + " vertices per ring");
  return std::max(3, static_cast<int>(n));
}

MeshData makeAnnulus(const AnnulusOptions& options) {
  const int n = annulusRingVertexCount(options), N = options.rings;
  const double r1 = options.innerRadius, r2 = options.outerRadius;
  requireFaceCount(2LL * n * N, "annulus");

  MeshData data;
  data.source = "annulus(r1=" + shortestDecimal(r1) + ", r2=" + shortestDecimal(r2) + ", rings=" + std::to_string(N) + ")";
  data.nVertices = n * (N + 1);
  data.positions.resize(data.nVertices);
  for (int k = 0; k <= N; ++k) {
    // r1·(r2/r1)^(k/N), with the last ring exactly r2.
    const double rho = k == N ? r2 : r1 * std::exp(std::log(r2 / r1) * k / N);
    for (int j = 0; j < n; ++j) {
      const double phi = 2 * kPi * j / n;
      data.positions[k * n + j] = {rho * std::cos(phi), rho * std::sin(phi), 0};
    }
  }
  // Cell (k,j): radial step first, then angular, is counter-clockwise (exp is orientation-preserving).
  data.faces.reserve(2 * static_cast<std::size_t>(n) * N);
  for (int k = 0; k < N; ++k) {
    for (int j = 0; j < n; ++j) {
      const int a = k * n + j, b = (k + 1) * n + j, c = (k + 1) * n + (j + 1) % n, d = k * n + (j + 1) % n;
      data.faces.push_back({a, b, c});
      data.faces.push_back({a, c, d});
    }
  }
  return data;
}

// =====================================================================================================================
// Flat torus
// =====================================================================================================================

std::pair<std::complex<double>, std::complex<double>> reduceLatticeBasis(std::complex<double> omega1,
                                                                         std::complex<double> omega2) {
  // Lagrange–Gauss: keep ω1 the shorter, subtract from ω2 the nearest integer multiple of ω1, until nothing changes.
  // |ω2| strictly decreases at every effective step, so this ends; the cap only guards against NaN input.
  for (int step = 0; step < 10000; ++step) {
    if (std::norm(omega2) < std::norm(omega1)) std::swap(omega1, omega2);
    const double mu = std::round(std::real(omega2 * std::conj(omega1)) / std::norm(omega1));
    if (mu == 0 || !std::isfinite(mu)) break;
    omega2 -= mu * omega1;
  }
  return {omega1, omega2};
}

MeshData makeFlatTorus(const FlatTorusOptions& options) {
  const std::string name = "flat torus";
  std::complex<double> w1 = options.omega1, w2 = options.omega2;
  const int n = options.n;
  requireGenerator(std::isfinite(w1.real()) && std::isfinite(w1.imag()) && std::isfinite(w2.real()) && std::isfinite(w2.imag()),
          name, "periods must be finite");
  // Relative test: the parallelogram's area against the product of its sides (sin of the angle between the periods).
  const double cross = std::imag(std::conj(w1) * w2);
  requireGenerator(std::abs(cross) > 1e-12 * std::abs(w1) * std::abs(w2), name,
          "periods ω1=" + shortestDecimal(w1.real()) + "+" + shortestDecimal(w1.imag()) + "i and ω2=" + shortestDecimal(w2.real()) + "+" + shortestDecimal(w2.imag()) +
              "i are linearly dependent over R (Im(conj(ω1)·ω2) = " + shortestDecimal(cross) + ")");
  requireGenerator(n >= 1 && n <= 30000, name, "n must be in 1..30000, found " + std::to_string(n));
  if (options.reduceBasis) std::tie(w1, w2) = reduceLatticeBasis(w1, w2);

  const double l1 = std::abs(w1) / n, l2 = std::abs(w2) / n;
  const double lPlus = std::abs(w1 + w2) / n, lMinus = std::abs(w1 - w2) / n;
  const bool mainDiagonal = lPlus <= lMinus;  // the shorter diagonal joins the obtuse corners: Delaunay

  MeshData data;
  auto fmtComplex = [](std::complex<double> z) { return "(" + shortestDecimal(z.real()) + "," + shortestDecimal(z.imag()) + ")"; };
  data.source = "flat torus(omega1=" + fmtComplex(options.omega1) + ", omega2=" + fmtComplex(options.omega2) +
                ", n=" + std::to_string(n) + (options.reduceBasis ? ", reduced basis)" : ")");
  data.nVertices = n * n;
  auto vid = [n](int i, int j) { return (i % n) * n + j % n; };
  // Edge ids: 3·vid(i,j) + 0 along ω1 from (i,j), + 1 along ω2 from (i,j), + 2 the diagonal of cell (i,j).
  data.edges.resize(3 * static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int v = vid(i, j);
      data.edges[3 * v + 0] = {v, vid(i + 1, j), l1};
      data.edges[3 * v + 1] = {v, vid(i, j + 1), l2};
      data.edges[3 * v + 2] =
          mainDiagonal ? EdgeRecord{v, vid(i + 1, j + 1), lPlus} : EdgeRecord{vid(i + 1, j), vid(i, j + 1), lMinus};
    }
  }
  const bool deltaComplex = n < 3;  // multi-edges (n = 2) and self-loops (n = 1): glue by edge id, not endpoints
  data.faces.reserve(2 * static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = vid(i, j), b = vid(i + 1, j), c = vid(i + 1, j + 1), d = vid(i, j + 1);
      const int ea = 3 * a, eb = 3 * b, ed = 3 * d;  // edges leaving a, b, d
      if (mainDiagonal) {
        data.faces.push_back({a, b, c});
        data.faces.push_back({a, c, d});
        if (deltaComplex) {
          data.cornerEdges.push_back({ea + 0, eb + 1, ea + 2});
          data.cornerEdges.push_back({ea + 2, ed + 0, ea + 1});
        }
      } else {
        data.faces.push_back({a, b, d});
        data.faces.push_back({b, c, d});
        if (deltaComplex) {
          data.cornerEdges.push_back({ea + 0, ea + 2, ea + 1});
          data.cornerEdges.push_back({eb + 1, ed + 0, ea + 2});
        }
      }
    }
  }
  return data;
}

// =====================================================================================================================
// Known answers
// =====================================================================================================================

KnownAnswers knownAnswers(const IcosphereOptions& options) {
  return {2, 0, 0, 4 * kPi * options.radius * options.radius, false};
}

KnownAnswers knownAnswers(const TorusOptions& options) {
  return {0, 1, 0, 4 * kPi * kPi * options.majorRadius * options.minorRadius, false};
}

KnownAnswers knownAnswers(const GenusSurfaceOptions& options) {
  // Top and bottom: 3W − g cells each; outer wall: perimeter 2(W + 3) cells, one cell high; each hole wall: 4 cells.
  const double g = options.genus, W = 2 * g + 1, c = options.cellSize;
  return {2 - 2 * options.genus, options.genus, 0, c * c * (2 * (3 * W - g) + 2 * (W + 3) + 4 * g), true};
}

KnownAnswers knownAnswers(const DiskOptions& options) {
  return {1, 0, 1, kPi * options.radius * options.radius, false};
}

KnownAnswers knownAnswers(const AnnulusOptions& options) {
  const double r1 = options.innerRadius, r2 = options.outerRadius;
  return {0, 0, 2, kPi * (r2 * r2 - r1 * r1), false};
}

KnownAnswers knownAnswers(const FlatTorusOptions& options) {
  return {0, 1, 0, std::abs(std::imag(std::conj(options.omega1) * options.omega2)), true};
}

// =====================================================================================================================
// Random metric perturbation
// =====================================================================================================================

namespace {

// min over the three sides of (sum of the other two − this one), relative to the perimeter.
double relativeSlack(double a, double b, double c) {
  const double p = a + b + c;
  return std::min({b + c - a, a + c - b, a + b - c}) / p;
}

// Groups items by their smaller endpoint (counting sort, O(n + V)) and returns for each item the index of the first
// item with the same unordered endpoint pair. `lo`/`hi` are the sorted endpoints.
std::vector<int> firstWithSamePair(const std::vector<int>& lo, const std::vector<int>& hi, int nVertices) {
  const std::size_t count = lo.size();
  std::vector<int> start(static_cast<std::size_t>(nVertices) + 1, 0);
  for (std::size_t i = 0; i < count; ++i) ++start[lo[i] + 1];
  for (int v = 0; v < nVertices; ++v) start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1), order(count);
  for (std::size_t i = 0; i < count; ++i) order[fill[lo[i]]++] = static_cast<int>(i);
  std::vector<int> first(count);
  for (int v = 0; v < nVertices; ++v) {
    // Buckets hold the items at one vertex: a few dozen at most on a mesh, so sorting each by `hi` is O(deg log deg).
    auto begin = order.begin() + start[v], end = order.begin() + start[v + 1];
    std::stable_sort(begin, end, [&](int x, int y) { return hi[x] < hi[y]; });
    for (auto it = begin; it != end; ++it)
      first[*it] = (it != begin && hi[*(it - 1)] == hi[*it]) ? first[*(it - 1)] : *it;
  }
  return first;
}

// The steps of perturbLengths over their shared state: the edge of every face corner, the unperturbed lengths, the
// slack each face must keep and the drawn offsets t_e.
class LengthPerturbation {
 public:
  LengthPerturbation(MeshData& data, double amplitude, unsigned seed)
      : data_(data), amplitude_(amplitude), seed_(seed), where_(data.source.empty() ? "perturbLengths" : data.source) {}

  PerturbReport run() {
    checkInput();
    faceEdges_.resize(nF_);
    if (!data_.edges.empty())
      takeRecordedLengths();
    else
      takeLengthsFromPositions();
    computeRequiredSlack();
    draw();
    PerturbReport report;
    report.edges = nE_;
    shrinkOffenders(report);
    writeBack(report);
    return report;
  }

 private:
  void fail(const std::string& what) const { throw InputError(describeAt(where_, what)); }

  // The amplitude's range, the corner-edge table's size and the faces' vertex indices.
  void checkInput() {
    if (!(amplitude_ >= 0 && amplitude_ < 1))
      fail("perturbation amplitude must be in [0, 1) so lengths stay positive, found " + shortestDecimal(amplitude_));
    nF_ = static_cast<int>(data_.faces.size()), nV_ = data_.nVertices;
    if (!data_.cornerEdges.empty() && data_.cornerEdges.size() != data_.faces.size())
      fail("cornerEdges has " + std::to_string(data_.cornerEdges.size()) + " entries, expected one per face (" +
           std::to_string(nF_) + ")");
    for (int f = 0; f < nF_; ++f)
      for (int k = 0; k < 3; ++k)
        if (data_.faces[f][k] < 0 || data_.faces[f][k] >= nV_)
          fail("face " + std::to_string(f) + " has vertex index " + std::to_string(data_.faces[f][k]) +
               ", expected 0.." + std::to_string(nV_ - 1));
  }

  // Lengths from the `edges` records; corners matched through `cornerEdges` or by endpoint pair.
  void takeRecordedLengths() {
    for (std::size_t e = 0; e < data_.edges.size(); ++e) {
      const auto& rec = data_.edges[e];
      if (!finitePositive(rec.length))
        fail("edge " + std::to_string(e) + " has length " + shortestDecimal(rec.length) + ", expected finite and positive");
      base_.push_back(rec.length);
    }
    if (!data_.cornerEdges.empty())
      takeCornerEdgeIds();
    else
      matchCornersToRecords();
  }

  void takeCornerEdgeIds() {
    for (int f = 0; f < nF_; ++f)
      for (int k = 0; k < 3; ++k) {
        const int e = data_.cornerEdges[f][k];
        if (e < 0 || e >= static_cast<int>(data_.edges.size()))
          fail("face " + std::to_string(f) + " corner " + std::to_string(k) + " names edge " + std::to_string(e) +
               ", expected 0.." + std::to_string(data_.edges.size() - 1));
        faceEdges_[f][k] = e;
      }
  }

  // Sorted endpoints of the side of face f that starts at corner k.
  void cornerPair(int f, int k, std::vector<int>& lo, std::vector<int>& hi, std::size_t at) const {
    const int a = data_.faces[f][k], b = data_.faces[f][(k + 1) % 3];
    lo[at] = std::min(a, b);
    hi[at] = std::max(a, b);
  }

  // Match face sides to edge records by endpoint pair: records first, then the 3F corners, in one bucket sort.
  void matchCornersToRecords() {
    const std::size_t nE = data_.edges.size();
    std::vector<int> lo(nE + 3 * static_cast<std::size_t>(nF_)), hi(lo.size());
    for (std::size_t e = 0; e < nE; ++e) {
      const int a = data_.edges[e].v0, b = data_.edges[e].v1;
      if (a < 0 || a >= nV_ || b < 0 || b >= nV_)
        fail("edge " + std::to_string(e) + " joins vertices " + std::to_string(a) + " and " + std::to_string(b) +
             ", expected 0.." + std::to_string(nV_ - 1));
      lo[e] = std::min(a, b);
      hi[e] = std::max(a, b);
    }
    for (int f = 0; f < nF_; ++f)
      for (int k = 0; k < 3; ++k) cornerPair(f, k, lo, hi, nE + 3 * f + k);
    const std::vector<int> first = firstWithSamePair(lo, hi, nV_);
    for (int f = 0; f < nF_; ++f)
      for (int k = 0; k < 3; ++k) {
        const int e = first[nE + 3 * f + k];
        if (e >= static_cast<int>(nE))
          fail("face " + std::to_string(f) + " side " + std::to_string(data_.faces[f][k]) + "-" +
               std::to_string(data_.faces[f][(k + 1) % 3]) + " has no edge record with a length");
        faceEdges_[f][k] = e;
      }
  }

  // No records: one edge per mesh edge (from `cornerEdges` or by endpoint pair), lengths from the positions; the
  // records are written to data.edges.
  void takeLengthsFromPositions() {
    if (data_.positions.size() != static_cast<std::size_t>(nV_))
      fail("no edge lengths and " + std::to_string(data_.positions.size()) + " positions for " + std::to_string(nV_) +
           " vertices: nothing to take lengths from");
    std::vector<EdgeRecord> edges = data_.cornerEdges.empty() ? edgesByEndpoints() : edgesFromCornerIds();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Eigen::Vector3d& p = data_.positions[edges[e].v0];
      const Eigen::Vector3d& q = data_.positions[edges[e].v1];
      if (!p.allFinite() || !q.allFinite())
        fail("edge " + std::to_string(edges[e].v0) + "-" + std::to_string(edges[e].v1) +
             " has a vertex with a non-finite position");
      edges[e].length = (p - q).norm();
      base_.push_back(edges[e].length);
    }
    data_.edges = std::move(edges);
  }

  std::vector<EdgeRecord> edgesFromCornerIds() {
    int nE = 0;
    for (const auto& ce : data_.cornerEdges)
      for (int e : ce) {
        if (e < 0) fail("negative edge id " + std::to_string(e) + " in cornerEdges");
        nE = std::max(nE, e + 1);
      }
    std::vector<EdgeRecord> edges(nE, EdgeRecord{-1, -1, 0});
    for (int f = 0; f < nF_; ++f)
      for (int k = 0; k < 3; ++k) {
        const int e = data_.cornerEdges[f][k];
        faceEdges_[f][k] = e;
        edges[e].v0 = data_.faces[f][k];
        edges[e].v1 = data_.faces[f][(k + 1) % 3];
      }
    for (int e = 0; e < nE; ++e)
      if (edges[e].v0 < 0) fail("edge id " + std::to_string(e) + " is used by no face");
    return edges;
  }

  std::vector<EdgeRecord> edgesByEndpoints() {
    std::vector<EdgeRecord> edges;
    std::vector<int> lo(3 * static_cast<std::size_t>(nF_)), hi(lo.size());
    for (int f = 0; f < nF_; ++f)
      for (int k = 0; k < 3; ++k) cornerPair(f, k, lo, hi, 3 * f + k);
    const std::vector<int> first = firstWithSamePair(lo, hi, nV_);
    std::vector<int> idOf(lo.size(), -1);
    for (std::size_t c = 0; c < lo.size(); ++c) {
      if (first[c] == static_cast<int>(c)) {
        idOf[c] = static_cast<int>(edges.size());
        edges.push_back({data_.faces[c / 3][c % 3], data_.faces[c / 3][(c % 3 + 1) % 3], 0});
      }
      faceEdges_[c / 3][c % 3] = idOf[first[c]];
    }
    return edges;
  }

  // The slack each face must keep, and the validity of the input.
  void computeRequiredSlack() {
    nE_ = static_cast<int>(base_.size());
    required_.resize(nF_);
    for (int f = 0; f < nF_; ++f) {
      const auto& fe = faceEdges_[f];
      const double s0 = relativeSlack(base_[fe[0]], base_[fe[1]], base_[fe[2]]);
      if (!(s0 > 0))
        fail("face " + std::to_string(f) + " violates the triangle inequality before perturbation: lengths " +
             shortestDecimal(base_[fe[0]]) + ", " + shortestDecimal(base_[fe[1]]) + ", " + shortestDecimal(base_[fe[2]]));
      required_[f] = std::min(kPerturbMinRelativeSlack, s0 / 2);
    }
  }

  void draw() {
    std::mt19937 rng(seed_);
    t_.resize(nE_);
    for (int e = 0; e < nE_; ++e) t_[e] = 2 * ((static_cast<double>(rng()) + 0.5) / 4294967296.0) - 1;  // in (−1, 1)
    length_.resize(nE_);
    for (int e = 0; e < nE_; ++e) length_[e] = base_[e] * (1 + amplitude_ * t_[e]);
  }

  // Halve the t_e of every offending face's edges (each edge at most once per pass) until every face keeps its slack.
  void shrinkOffenders(PerturbReport& report) {
    // After kMaxHalvings halvings t_e < 2⁻⁶⁰ is below round-off relative to 1; it is then set to exactly 0.
    constexpr int kMaxHalvings = 60;
    std::vector<int> halvings(nE_, 0), lastPass(nE_, -1);
    for (bool clean = false; !clean; ++report.passes) {
      clean = true;
      for (int f = 0; f < nF_; ++f) {
        const auto& fe = faceEdges_[f];
        if (relativeSlack(length_[fe[0]], length_[fe[1]], length_[fe[2]]) >= required_[f]) continue;
        clean = false;
        for (int e : fe) {
          if (lastPass[e] == report.passes) continue;
          lastPass[e] = report.passes;
          if (halvings[e]++ == 0) ++report.shrunkEdges;
          t_[e] = halvings[e] >= kMaxHalvings ? 0.0 : t_[e] / 2;
          length_[e] = base_[e] * (1 + amplitude_ * t_[e]);
        }
      }
    }
  }

  void writeBack(PerturbReport& report) {
    for (int e = 0; e < nE_; ++e) {
      data_.edges[e].length = length_[e];
      report.maxRelativeChange = std::max(report.maxRelativeChange, std::abs(length_[e] / base_[e] - 1));
    }
  }

  MeshData& data_;
  const double amplitude_;
  const unsigned seed_;
  const std::string where_;
  int nF_ = 0, nV_ = 0, nE_ = 0;
  std::vector<std::array<int, 3>> faceEdges_;
  std::vector<double> base_, required_, t_, length_;
};

}  // namespace

PerturbReport perturbLengths(MeshData& data, double amplitude, unsigned seed) {
  return LengthPerturbation(data, amplitude, seed).run();
}

}  // namespace conformesh::intrinsic
