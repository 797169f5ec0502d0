// fundamental_domain.cpp — development of a cut closed flat/hyperbolic triangulation along its cotree, the deck
// transformations of the cut halfedges and the residuals of the vertex and surface relations. See
// fundamental_domain.h and docs/layout.md §2.
#include "conformesh/embedding/layout/fundamental_domain.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include <Eigen/LU>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::embedding {

using intrinsic::Background;
using intrinsic::HalfedgeMesh;
using intrinsic::IntrinsicTriangulation;

Complex applyMobius(const Mobius& m, Complex z) {
  return (m(0, 0) * z + m(0, 1)) / (m(1, 0) * z + m(1, 1));
}

Mobius evaluateWord(const std::vector<Mobius>& generators, const GroupWord& word) {
  Mobius out = Mobius::Identity();
  for (int letter : word) {
    const Mobius& g = generators.at(std::abs(letter) - 1);
    out = out * (letter > 0 ? g : Mobius(g.inverse()));
  }
  return out;
}

double distanceFromIdentity(const Mobius& m) {
  const Mobius unit = m / std::sqrt(m.determinant());
  const double plus = (unit - Mobius::Identity()).cwiseAbs().maxCoeff();
  const double minus = (unit + Mobius::Identity()).cwiseAbs().maxCoeff();
  return std::min(plus, minus);
}

namespace {

// The development runs in long double (64-bit mantissa): the deck transformations of a genus-3 surface have entries up
// to ~10², and a relation of 4g of them multiplies round-off by the product of their norms, which in double would
// leave ~10⁻⁹ of pure round-off (measured on CGAL's 3torus.off). The results are rounded to double at the end.
using Real = long double;
using ComplexL = std::complex<Real>;
using MobiusL = Eigen::Matrix<ComplexL, 2, 2>;
const Real kPi = 3.141592653589793238462643383279502884L;

ComplexL applyL(const MobiusL& m, ComplexL z) {
  return (m(0, 0) * z + m(0, 1)) / (m(1, 0) * z + m(1, 1));
}

MobiusL inverseL(const MobiusL& m) {  // 2×2 adjugate over the determinant (1 up to round-off for our isometries)
  MobiusL out;
  out << m(1, 1), -m(0, 1), -m(1, 0), m(0, 0);
  return out / (m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0));
}

Real distanceFromIdentityL(const MobiusL& m) {
  const MobiusL unit = m / std::sqrt(m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0));
  const Real plus = (unit - MobiusL::Identity()).cwiseAbs().maxCoeff();
  const Real minus = (unit + MobiusL::Identity()).cwiseAbs().maxCoeff();
  return std::min(plus, minus);
}

// Translation along the real axis by (geodesic) length ℓ: z ↦ z + ℓ in the plane; in the Poincaré disk the
// hyperbolic translation [[cosh ℓ/2, sinh ℓ/2], [sinh ℓ/2, cosh ℓ/2]] taking 0 to tanh(ℓ/2).
MobiusL translation(Background bg, Real length) {
  MobiusL m;
  if (bg == Background::Euclidean)
    m << 1, length, 0, 1;
  else
    m << std::cosh(length / 2), std::sinh(length / 2), std::sinh(length / 2), std::cosh(length / 2);
  return m;
}

// Rotation about 0 by φ: z ↦ e^{iφ} z ([[e^{iφ/2}, 0], [0, e^{−iφ/2}]] in SU(1,1)).
MobiusL rotation(Background bg, Real phi) {
  MobiusL m;
  if (bg == Background::Euclidean)
    m << std::polar(Real(1), phi), 0, 0, 1;
  else
    m << std::polar(Real(1), phi / 2), 0, 0, std::polar(Real(1), -phi / 2);
  return m;
}

// The isometry of the model taking c to 0 (flat: translation; hyperbolic: T_c(z) = (z − c)/(1 − c̄z) in SU(1,1)).
MobiusL centring(Background bg, ComplexL c) {
  MobiusL m;
  if (bg == Background::Euclidean) {
    m << 1, -c, 0, 1;
  } else {
    const Real s = 1 / std::sqrt(1 - std::norm(c));
    m << s, -s * c, -s * std::conj(c), s;
  }
  return m;
}

Mobius toDouble(const MobiusL& m) {
  return m.cast<Complex>();
}

// The steps of developFundamentalDomain over their shared state: the faces' standard frames, the developing maps
// M_f of the faces in D, the crossing maps A_h, and the domain being filled.
class Development {
 public:
  Development(const IntrinsicTriangulation& tri, const FundamentalDomainOptions& options)
      : tri_(tri), m_(tri.mesh), options_(options), bg_(tri.background), nf_(m_.nFaces()), nh_(m_.nHalfedges()) {}

  FundamentalDomain run() {
    fd_.background = tri_.background;
    fd_.basis = treeCotree(tri_);
    buildFrames();
    developAlongCotree();
    computeCrossings();
    if (options_.centre) centre();
    writeMaps();
    measureResiduals();
    return std::move(fd_);
  }

 private:
  // Standard placement of each face: corner 0 at 0, corner 1 on +x, corner 2 above (counter-clockwise). frame[f][k]
  // is the isometry taking 0 to corner k and +x to the direction of corner k+1, composed of exact translations and
  // rotations (with θ_k the angle at corner k: F_0 = I, F_1 = Tr(ℓ01) R(π − θ1), F_2 = R(θ0) Tr(ℓ20) R(π)). Building
  // the frames from lengths and angles, instead of normalizing disk points, keeps long hyperbolic edges exact: a point
  // at distance ℓ sits 4e^{−ℓ} from the unit circle, where |z| loses log10(e^ℓ/4) digits.
  void buildFrames() {
    frame_.resize(nf_);
    for (int f = 0; f < nf_; ++f) {
      const Real t0 = intrinsic::cornerAngle(tri_, 3 * f), t1 = intrinsic::cornerAngle(tri_, 3 * f + 1);
      frame_[f][0] = MobiusL::Identity();
      frame_[f][1] = translation(bg_, tri_.length(3 * f)) * rotation(bg_, kPi - t1);
      frame_[f][2] = rotation(bg_, t0) * translation(bg_, tri_.length(3 * f + 2)) * rotation(bg_, kPi);
    }
  }

  // τ_h: standard coordinates of g = face(twin h) → standard coordinates of f = face(h), gluing the two copies of the
  // edge: the frame of h in f equals the reversed frame of twin h in g, F_j Tr(ℓ) R(π).
  MobiusL transition(int h) const {
    const int f = HalfedgeMesh::face(h), k = h % 3, t = m_.twin(h), g = HalfedgeMesh::face(t), j = t % 3;
    const MobiusL reversed = frame_[g][j] * translation(bg_, tri_.length(h)) * rotation(bg_, kPi);
    return MobiusL(frame_[f][k] * inverseL(reversed));
  }

  bool isCotree(int h) const { return fd_.basis.edgeClass[m_.edge(h)] == EdgeClass::Cotree; }

  // Develop along the cotree (breadth first from the root face): M_g = M_f τ_h.
  void developAlongCotree() {
    faceMap_.assign(nf_, MobiusL::Identity());
    std::vector<char> placed(nf_, 0);
    std::queue<int> queue;
    const int root = fd_.basis.rootFace;
    placed[root] = 1;
    queue.push(root);
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      for (int k = 0; k < 3; ++k) {
        const int h = 3 * f + k;
        if (!isCotree(h)) continue;
        const int g = HalfedgeMesh::face(m_.twin(h));
        if (placed[g]) continue;
        faceMap_[g] = faceMap_[f] * transition(h);
        placed[g] = 1;
        queue.push(g);
      }
    }
  }

  // A_h = M_f τ_h M_g⁻¹ maps D's copy of g = face(twin h) onto the copy glued to f across h.
  void computeCrossings() {
    crossing_.assign(nh_, MobiusL::Identity());
    for (int h = 0; h < nh_; ++h) {
      if (isCotree(h)) continue;
      const int f = HalfedgeMesh::face(h), g = HalfedgeMesh::face(m_.twin(h));
      crossing_[h] = faceMap_[f] * transition(h) * inverseL(faceMap_[g]);
    }
  }

  // Centre D: flat — area-weighted centroid of the corners; hyperbolic — normalized area-weighted mean of the corners
  // on the hyperboloid (back to the disk by z = (X₁ + iX₂)/(1 + X₀)); then rotate about 0 so that corner 0 of the root
  // face lies on +x.
  void centre() {
    Real w = 0, x0 = 0;
    ComplexL centroid = 0, x12 = 0;
    for (int f = 0; f < nf_; ++f) {
      const Real area = intrinsic::faceArea(tri_, f);
      for (int k = 0; k < 3; ++k) {
        const ComplexL z = applyL(faceMap_[f] * frame_[f][k], 0);
        centroid += area * z;
        const Real d = 1 - std::norm(z);
        x0 += area * (1 + std::norm(z)) / d;
        x12 += area * Real(2) * z / d;
      }
      w += 3 * area;
    }
    ComplexL c = centroid / w;
    if (bg_ == Background::Hyperbolic) {
      const Real scale = std::sqrt(x0 * x0 - std::norm(x12));
      c = (x12 / scale) / (1 + x0 / scale);
    }
    MobiusL move = centring(bg_, c);
    move = rotation(bg_, -std::arg(applyL(move * faceMap_[fd_.basis.rootFace], 0))) * move;
    const MobiusL moveInv = inverseL(move);
    for (auto& mf : faceMap_) mf = move * mf;
    for (int h = 0; h < nh_; ++h)
      if (!isCotree(h)) crossing_[h] = move * crossing_[h] * moveInv;
  }

  // Corners, face maps, crossings and generators in double precision.
  void writeMaps() {
    fd_.corners.resize(nf_);
    fd_.minSignedArea = std::numeric_limits<double>::infinity();
    for (int f = 0; f < nf_; ++f) {
      for (int k = 0; k < 3; ++k) fd_.corners[f][k] = Complex(applyL(faceMap_[f] * frame_[f][k], 0));
      const Complex a = fd_.corners[f][1] - fd_.corners[f][0], b = fd_.corners[f][2] - fd_.corners[f][0];
      fd_.minSignedArea = std::min(fd_.minSignedArea, 0.5 * std::imag(std::conj(a) * b));
    }
    fd_.faceMap.reserve(nf_);
    for (const auto& mf : faceMap_) fd_.faceMap.push_back(toDouble(mf));
    fd_.crossing.reserve(nh_);
    for (const auto& a : crossing_) fd_.crossing.push_back(toDouble(a));
    for (int e : fd_.basis.generatorEdges) {
      generators_.push_back(crossing_[m_.edgeHalfedge(e)]);
      fd_.generators.push_back(toDouble(generators_.back()));
    }
  }

  // Vertex: the transitions around v compose to the identity in v's own frame (its angle sum is 2π) — measured there,
  // since conjugating into D's frame multiplies it by |M_f|². Relation: the word left at the root, evaluated on the
  // generators in D's (centred) frame.
  void measureResiduals() {
    for (int v = 0; v < m_.nVertices(); ++v) {
      MobiusL product = MobiusL::Identity();
      const int h0 = m_.vertexHalfedge(v);
      int h = h0;
      do {
        product = product * transition(HalfedgeMesh::prev(h));
        h = m_.nextOutgoing(h);
      } while (h != h0);
      fd_.maxVertexResidual = std::max(fd_.maxVertexResidual, double(distanceFromIdentityL(product)));
    }
    MobiusL relation = MobiusL::Identity();
    for (int letter : fd_.basis.relation) {
      const MobiusL& g = generators_[std::abs(letter) - 1];
      relation = relation * (letter > 0 ? g : inverseL(g));
    }
    fd_.relationResidual = double(distanceFromIdentityL(relation));
  }

  const IntrinsicTriangulation& tri_;
  const HalfedgeMesh& m_;
  const FundamentalDomainOptions& options_;
  const Background bg_;
  const int nf_, nh_;
  FundamentalDomain fd_;
  std::vector<std::array<MobiusL, 3>> frame_;
  std::vector<MobiusL> faceMap_, crossing_, generators_;
};

}  // namespace

FundamentalDomain developFundamentalDomain(const IntrinsicTriangulation& tri, const FundamentalDomainOptions& options) {
  if (tri.background == Background::Spherical)
    throw InputError("developFundamentalDomain: a spherical triangulation has no flat or hyperbolic development");
  intrinsic::validateLengths(tri, "developFundamentalDomain");
  return Development(tri, options).run();
}

}  // namespace conformesh::embedding
