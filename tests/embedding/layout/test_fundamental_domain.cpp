// test_fundamental_domain.cpp — the word evaluation of fundamental_domain.h / hyperbolic_layout.h against group
// elements known in closed form:
// * evaluateWord and deckWords on the Bolza group (the genus-2 surface of the regular octagon, closed-form generators
//   g_k = [[1+√2, √(2+2√2) e^{ikπ/4}], [√(2+2√2) e^{−ikπ/4}, 1+√2]] ∈ SU(1,1), k = 0..3, relation
//   g₀ g₁⁻¹ g₂ g₃⁻¹ g₀⁻¹ g₁ g₂⁻¹ g₃ = 1): letters, inverses, concatenation, the relation, the tiles of deckWords;
// * on a flat torus of a given lattice ω₁Z + ω₂Z (makeFlatTorus): the developed generators are translations by a basis
//   of the lattice (rotated as a whole), every halfedge's deck transformation A_h is the translation by the integer
//   combination its crossing word names, and A_h glues the neighbouring tile along h;
// * on a uniformized genus-2 surface: A_h equals ± the evaluated crossing word for every halfedge, and a word times its
//   inverse is the identity.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "conformesh/embedding/layout/fundamental_domain.h"
#include "conformesh/embedding/layout/hyperbolic_layout.h"
#include "conformesh/intrinsic/flow/uniformization.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"

using namespace conformesh::embedding;
using namespace conformesh::intrinsic;

namespace {

constexpr double kEps = 2.220446049250313e-16;

// Max-entry distance of two Möbius matrices, and up to sign (PSU(1,1): m and −m are one map).
double distance(const Mobius& a, const Mobius& b) { return (a - b).cwiseAbs().maxCoeff(); }
double distanceUpToSign(const Mobius& a, const Mobius& b) { return std::min(distance(a, b), distance(a, -b)); }

std::vector<Mobius> bolzaGenerators() {
  const double a = 1 + std::sqrt(2.0), b = std::sqrt(2 + 2 * std::sqrt(2.0));
  std::vector<Mobius> g;
  for (int k = 0; k < 4; ++k) {
    const Complex beta = std::polar(b, k * M_PI / 4);
    Mobius m;
    m << a, beta, std::conj(beta), a;
    g.push_back(m);
  }
  return g;
}
// The SU(1,1) inverse of [[a, b], [b̄, ā]] is [[ā, −b], [−b̄, a]].
Mobius su11Inverse(const Mobius& m) {
  Mobius r;
  r << m(1, 1), -m(0, 1), -m(1, 0), m(0, 0);
  return r;
}
// The product of the letters, written here.
Mobius product(const std::vector<Mobius>& g, const GroupWord& w) {
  Mobius r = Mobius::Identity();
  for (int letter : w) r = r * (letter > 0 ? g[letter - 1] : su11Inverse(g[-letter - 1]));
  return r;
}
GroupWord randomReducedWord(std::mt19937& rng, int generators, int length) {
  GroupWord w;
  std::uniform_int_distribution<int> pick(1, generators);
  while (static_cast<int>(w.size()) < length) {
    const int letter = (rng() & 1 ? 1 : -1) * pick(rng);
    if (!w.empty() && w.back() == -letter) continue;
    w.push_back(letter);
  }
  return w;
}

// Round-off of a product of k matrices of 2-norm ≤ s each (Higham: ≤ k·γ₄·∏‖M‖ for complex 2×2 products, γ₄ ≈ 4ε,
// entries bounded by the 2-norm): the allowance for comparing two evaluations of one word of length k.
double productRoundOff(int k, double s) { return 8.0 * (k + 1) * kEps * std::pow(s, k); }

}  // namespace

TEST_CASE("evaluateWord on the Bolza group: letters, inverses, concatenation and the octagon relation") {
  const std::vector<Mobius> g = bolzaGenerators();
  // ‖g_k‖₂ = |a| + |b| = e^{d/2} (d the translation length, cosh(d/2) = 1 + √2).
  const double s = 1 + std::sqrt(2.0) + std::sqrt(2 + 2 * std::sqrt(2.0));
  for (const Mobius& m : g) CHECK(std::abs(m.determinant() - 1.0) < 16 * kEps * s * s);
  CHECK(distance(evaluateWord(g, {}), Mobius::Identity()) == 0);
  for (int i = 0; i < 4; ++i) {
    CHECK(distance(evaluateWord(g, {i + 1}), g[i]) == 0);
    // A general 2×2 inverse divides by the computed determinant, 1 to ≈ 4ε‖g‖² (cancellation in |a|² − |b|²):
    // entries of size ‖g‖ then differ by ≈ 4ε‖g‖³.
    CHECK(distance(evaluateWord(g, {-(i + 1)}), su11Inverse(g[i])) <= 8 * kEps * s * s * s);
  }
  // The surface relation of the regular octagon with opposite sides paired: ±I to the round-off of 8 products.
  const GroupWord relation = {1, -2, 3, -4, -1, 2, -3, 4};
  const double relationTolerance = productRoundOff(8, s);
  INFO("relation tolerance " << relationTolerance);
  CHECK(distanceUpToSign(evaluateWord(g, relation), Mobius::Identity()) <= relationTolerance);
  CHECK(distanceFromIdentity(evaluateWord(g, relation)) <= relationTolerance);
  // Every cyclic permutation of the relation and its inverse word are relations too.
  for (int shift = 1; shift < 8; ++shift) {
    GroupWord w(relation.begin() + shift, relation.end());
    w.insert(w.end(), relation.begin(), relation.begin() + shift);
    CHECK(distanceFromIdentity(evaluateWord(g, w)) <= relationTolerance);
  }
  CHECK(distanceFromIdentity(evaluateWord(g, inverse(relation))) <= relationTolerance);
  // A non-relation of the same letters (the commutators of the first pair and second pair, g₀g₁g₀⁻¹g₁⁻¹g₂g₃g₂⁻¹g₃⁻¹)
  // is a non-trivial element: |trace| > 2 (hyperbolic) and far from ±I.
  const Mobius c = evaluateWord(g, {1, 2, -1, -2, 3, 4, -3, -4});
  CHECK(std::abs(c.trace()) > 2);
  CHECK(distanceFromIdentity(c) > 1);

  // Random reduced words: evaluateWord = the product written here; w·w⁻¹ = I; evaluateWord(uv) = evaluateWord(u)
  // evaluateWord(v); every value stays in SU(1,1) (d = ā, c = b̄).
  std::mt19937 rng(19);
  int checked = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const int length = 1 + trial % 6;
    const GroupWord u = randomReducedWord(rng, 4, length), v = randomReducedWord(rng, 4, 3);
    const Mobius U = evaluateWord(g, u);
    const double tol = productRoundOff(length, s), tol2 = productRoundOff(2 * length, s);
    CAPTURE(toString(u));
    CHECK(distance(U, product(g, u)) <= tol);
    CHECK(distance(U * evaluateWord(g, inverse(u)), Mobius::Identity()) <= tol2);
    GroupWord uv = u;
    uv.insert(uv.end(), v.begin(), v.end());
    CHECK(distance(evaluateWord(g, uv), U * evaluateWord(g, v)) <= productRoundOff(length + 3, s));
    CHECK(std::abs(U(1, 1) - std::conj(U(0, 0))) <= tol);
    CHECK(std::abs(U(1, 0) - std::conj(U(0, 1))) <= tol);
    ++checked;
  }
  CHECK(checked == 50);
}

TEST_CASE("deckWords on the Bolza group: the 65 tiles of the reduced words of length ≤ 2, all distinct") {
  const std::vector<Mobius> g = bolzaGenerators();
  const std::vector<Mobius> tiles = deckWords(g, 2);
  REQUIRE(tiles.size() == 1u + 8u + 56u);
  CHECK(distance(tiles[0], Mobius::Identity()) == 0);
  // The reduced words of length ≤ 2, evaluated here: each must be among the tiles.
  std::vector<GroupWord> words = {{}};
  for (int a = -4; a <= 4; ++a) {
    if (a == 0) continue;
    words.push_back({a});
    for (int b = -4; b <= 4; ++b)
      if (b != 0 && b != -a) words.push_back({a, b});
  }
  REQUIRE(words.size() == tiles.size());
  const double s = 1 + std::sqrt(2.0) + std::sqrt(2 + 2 * std::sqrt(2.0));
  int found = 0;
  for (const GroupWord& w : words) {
    const Mobius m = product(g, w);
    int matches = 0;
    for (const Mobius& t : tiles) matches += distanceUpToSign(t, m) <= productRoundOff(2, s);
    CAPTURE(toString(w));
    CHECK(matches == 1);
    found += matches == 1;
  }
  CHECK(found == static_cast<int>(words.size()));
  // Distinct tiles: w₁ ≠ w₂ of length ≤ 2 differ by the reduced word w₁w₂⁻¹ of length ≤ 4, which is not the identity
  // in a surface group whose relator has length 8 (Dehn's algorithm: a trivial word holds more than half a relator).
  // The images of the disk's centre are then distinct points, by more than round-off: the group acts freely.
  for (size_t i = 0; i < tiles.size(); ++i) {
    const Complex zi = applyMobius(tiles[i], 0.0);
    CHECK(std::abs(zi) < 1);
    for (size_t j = 0; j < i; ++j) CHECK(std::abs(zi - applyMobius(tiles[j], 0.0)) > 1e-3);
  }
}

TEST_CASE("a flat torus: the deck transformations are the translations by the lattice's integer combinations") {
  // The lattice of test_torus_layout's skewed case, given by a non-reduced basis; the mesh is built on the reduced one.
  const Complex w1 = std::polar(2.0, 0.4), w2 = w1 * Complex(0.3, 1.1) + 2.0 * w1;
  FlatTorusOptions o;
  o.omega1 = w1;
  o.omega2 = w2;
  o.n = 7;
  const IntrinsicTriangulation tri = toTriangulation(makeFlatTorus(o));
  const FundamentalDomain d = developFundamentalDomain(tri);
  REQUIRE(d.generators.size() == 2u);
  // Round-off: coordinates are O(|ω|) ≈ 5 after up to 2n² = 98 composed long-double transitions (10⁻¹⁹ each), then
  // rounded to double: a few ulps of 5, well below 1e-13.
  const double tol = 1e-13;
  // Translations: [[α, β], [0, 1]] with α = 1 (no rotation in the holonomy of a flat torus).
  for (const Mobius& m : d.generators) {
    CHECK(std::abs(m(0, 0) - 1.0) < tol);
    CHECK(std::abs(m(1, 0)) == 0);
    CHECK(std::abs(m(1, 1) - 1.0) == 0);
  }
  const Complex b1 = d.generators[0](0, 1), b2 = d.generators[1](0, 1);
  // The developed plane is the lattice's plane rotated by some φ: find (p, q) with |pω₁ + qω₂| = |β₁| and check that
  // e^{−iφ}β₂ then has integer coordinates (r, s) in (ω₁, ω₂), with ps − qr = ±1 (the two generators are a basis).
  auto coordinates = [&](Complex z) {  // real (x, y) with z = xω₁ + yω₂
    const double det = std::imag(std::conj(w1) * w2);
    return std::pair<double, double>{std::imag(std::conj(z) * w2) / det, std::imag(std::conj(w1) * z) / det};
  };
  int bases = 0;
  for (int p = -8; p <= 8; ++p) {
    for (int q = -8; q <= 8; ++q) {
      const Complex v = double(p) * w1 + double(q) * w2;
      if (std::abs(std::abs(v) - std::abs(b1)) > tol || std::abs(v) == 0) continue;
      const Complex rotation = v / b1;  // e^{−iφ}
      const auto [x, y] = coordinates(rotation * b2);
      const double r = std::round(x), sy = std::round(y);
      if (std::abs(x - r) > 1e-12 || std::abs(y - sy) > 1e-12) continue;
      if (std::abs(p * sy - q * r) != 1) continue;
      ++bases;
      // Every halfedge's deck transformation: the translation by Σ_i (exponent sum of letter i) β_i, as evaluateWord
      // gives it and as the domain stores it; the identity for cotree halfedges.
      const HalfedgeMesh& m = tri.mesh;
      int crossings = 0;
      for (int h = 0; h < m.nHalfedges(); ++h) {
        const GroupWord& w = d.basis.crossingWord[h];
        int e1 = 0, e2 = 0;
        for (int letter : w) (std::abs(letter) == 1 ? e1 : e2) += letter > 0 ? 1 : -1;
        Mobius expected = Mobius::Identity();
        expected(0, 1) = double(e1) * b1 + double(e2) * b2;
        CAPTURE(h, toString(w));
        CHECK(distance(evaluateWord(d.generators, w), expected) < tol * (1 + w.size()));
        CHECK(distance(d.crossing[h], expected) < tol * (1 + w.size()));
        // The translation is a lattice vector: rotated back, integer coordinates.
        const auto [cx, cy] = coordinates(rotation * expected(0, 1));
        CHECK(std::abs(cx - std::round(cx)) < 1e-12);
        CHECK(std::abs(cy - std::round(cy)) < 1e-12);
        // The tile A_h D is glued to D along h: A_h maps the edge's corners in face(twin h) onto those in face(h),
        // swapped.
        const int t = m.twin(h);
        const Complex a = d.corners[h / 3][h % 3], b = d.corners[h / 3][(h + 1) % 3];
        CHECK(std::abs(applyMobius(d.crossing[h], d.corners[t / 3][(t + 1) % 3]) - a) < tol);
        CHECK(std::abs(applyMobius(d.crossing[h], d.corners[t / 3][t % 3]) - b) < tol);
        crossings += !w.empty();
      }
      // Non-cotree edges: the 2g = 2 generators and the V − 1 tree edges (E − (F − 1) = V + 1), both halfedges each.
      CHECK(crossings <= 2 * (m.nVertices() + 1));
      CHECK(crossings >= 4);
    }
  }
  // Exactly the rotations that carry a lattice basis onto (β₁, β₂): the lattice's own symmetries (±1 for this
  // generic lattice) times the choices of (p, q) — at least one, and every one consistent.
  CHECK(bases >= 1);
  CHECK(distanceFromIdentity(evaluateWord(d.generators, d.basis.relation)) < tol);
}

TEST_CASE("a uniformized genus-2 surface: every A_h is its evaluated crossing word, and words invert") {
  const IntrinsicTriangulation input = toTriangulation(readMesh(std::string(CONFORMESH_TEST_DATA_DIR) + "/eight.off"));
  // As test_hyperbolic_layout: the flow to 1e-13, so that the vertex relations, which make A_h a word in the
  // generators, hold to ~1e-12 (each vertex's angle-sum error times generator norms).
  UniformizationOptions uo;
  uo.flow.tolerance = 1e-13;
  uo.flow.relativeFloor = 1e-15;
  const IntrinsicTriangulation uniform = uniformize(input, uo).uniform;
  const HyperbolicLayout layout = layoutHyperbolic(uniform);
  const FundamentalDomain& d = layout.domain;
  const HalfedgeMesh& m = uniform.mesh;
  double worst = 0, worstInverse = 0, maxEntry = 0;
  int words = 0;
  size_t longest = 0;
  for (int h = 0; h < m.nHalfedges(); ++h) {
    const GroupWord& w = d.basis.crossingWord[h];
    longest = std::max(longest, w.size());
    const Mobius a = evaluateWord(d.generators, w);
    maxEntry = std::max(maxEntry, a.cwiseAbs().maxCoeff());
    worst = std::max(worst, distanceUpToSign(a, d.crossing[h]) / (1 + a.cwiseAbs().maxCoeff()));
    worstInverse = std::max(worstInverse, distance(a * evaluateWord(d.generators, inverse(w)), Mobius::Identity()));
    words += !w.empty();
  }
  INFO("max |A_h − ±word| / (1 + |A_h|) " << worst << ", max |w w⁻¹ − I| " << worstInverse << ", max entry "
                                             << maxEntry << ", " << words << " crossing words of up to " << longest << " letters");
  CHECK(words >= 8);
  // A_h and the word differ by the vertex relations' residuals along the tree path: each the flow's angle-sum error
  // (≤ 1e-13) amplified by the norms of the face maps along the path (entries ≤ 15 here): ≲ 1e-11, held to 1e-10
  // (measured 2e-14). w·w⁻¹ (words of ≤ 3 letters here): ≤ 6 products of matrices of entries ≤ 15, whose a-priori
  // round-off bound productRoundOff(6, 15) ≈ 6e-7 is loose; held to 1e-10 as a regression bound (measured 2e-13).
  CHECK(worst < 1e-10);
  CHECK(worstInverse < 1e-10);
}
