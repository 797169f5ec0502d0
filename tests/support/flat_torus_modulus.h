// flat_torus_modulus.h — the modulus of a flat torus computed from its edge lengths alone, for tests that check a
// uniformization's flat torus against a closed form: lay the faces out along a spanning tree, collect the translations
// between the two placements of each vertex across the other edges, and reduce the shortest two independent ones
// (Lagrange–Gauss). Kept independent of embedding/torus_layout.h so that the flow's tests do not rest on the layout.
#pragma once

#include <array>
#include <complex>
#include <tuple>
#include <vector>

#include "conformesh/intrinsic/mesh/intrinsic_triangulation.h"
#include "conformesh/intrinsic/mesh/mesh_generators.h"

namespace conformesh::testing {

// Returns the reduced modulus τ (|Re τ| ≤ ½, |τ| ≥ 1) as (|Re τ|, Im τ).
inline std::complex<double> flatTorusModulus(const intrinsic::IntrinsicTriangulation& tri) {
  const intrinsic::HalfedgeMesh& m = tri.mesh;
  std::vector<std::array<std::complex<double>, 3>> corner(m.nFaces());
  std::vector<char> placed(m.nFaces(), 0);
  corner[0][0] = 0;
  corner[0][1] = tri.length(0);
  corner[0][2] = std::polar(tri.length(2), intrinsic::cornerAngle(tri, 0));
  placed[0] = 1;
  std::vector<int> queue{0};
  std::vector<std::complex<double>> translations;
  for (std::size_t qi = 0; qi < queue.size(); ++qi) {
    const int f = queue[qi];
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * f + k, t = m.twin(h), g = intrinsic::HalfedgeMesh::face(t), kt = t % 3;
      const std::complex<double> a = corner[f][(k + 1) % 3], b = corner[f][k];  // t runs from tip(h) to tail(h)
      if (placed[g]) {
        translations.push_back(a - corner[g][kt]);
        continue;
      }
      corner[g][kt] = a;
      corner[g][(kt + 1) % 3] = b;
      corner[g][(kt + 2) % 3] = a + std::polar(tri.length(intrinsic::HalfedgeMesh::prev(t)),
                                               std::arg(b - a) + intrinsic::cornerAngle(tri, t));
      placed[g] = 1;
      queue.push_back(g);
    }
  }
  std::complex<double> w1 = 0, w2 = 0;
  for (auto t : translations)
    if (std::abs(t) > 1e-6 && (w1 == 0.0 || std::abs(t) < std::abs(w1))) w1 = t;
  for (auto t : translations)
    if (std::abs(t) > 1e-6 && std::abs(std::imag(t / w1)) > 1e-6 && (w2 == 0.0 || std::abs(t) < std::abs(w2))) w2 = t;
  std::tie(w1, w2) = intrinsic::reduceLatticeBasis(w1, w2);
  const std::complex<double> tau = w2 / w1;
  return {std::abs(tau.real()), std::abs(tau.imag())};
}

}  // namespace conformesh::testing
