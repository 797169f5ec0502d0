// End-to-end tests of `conformesh refine --segment-rule`: a generated Euclidean disk refined below B = √2 with Chew's
// second algorithm and with Ruppert's rules; every angle of the written file, computed here from its edge lengths by
// the law of cosines, is at least arcsin(1/(2B)); the interior angle sums are 2π and the boundary turning closes
// Gauss–Bonnet; Chew's run deletes vertices; a bad rule name is a one-line error.
#include <catch2/catch.hpp>

#include "support/cli_runner.h"
#include "support/gauss_bonnet_bound.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"

namespace fs = std::filesystem;
using namespace conformesh::intrinsic;

namespace {

struct AngleFigures {
  double smallest = INFINITY;   // radians
  double worstInteriorSum = 0;  // max |Σθ − 2π| over interior vertices
  double gaussBonnet = 0;       // Σ(2π − Σθ) interior + Σ(π − Σθ) boundary − 2π χ, χ = 1
};

// Corner angles from the file's own lengths (faces as vertex triples: the disk's output is simplicial); a vertex is on
// the boundary when one of its edges has a single face.
AngleFigures anglesOf(const MeshData& d) {
  std::map<std::pair<int, int>, double> length;
  std::map<std::pair<int, int>, int> faceCount;
  for (const EdgeRecord& e : d.edges) length[{std::min(e.v0, e.v1), std::max(e.v0, e.v1)}] = e.length;
  auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  std::vector<double> sum(d.nVertices, 0.0);
  AngleFigures out;
  for (const auto& f : d.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3], c = f[(k + 2) % 3];
      ++faceCount[key(a, b)];
      const double lab = length.at(key(a, b)), lac = length.at(key(a, c)), lbc = length.at(key(b, c));
      const double angle = std::acos(std::clamp((lab * lab + lac * lac - lbc * lbc) / (2 * lab * lac), -1.0, 1.0));
      sum[a] += angle;
      out.smallest = std::min(out.smallest, angle);
    }
  std::vector<bool> boundary(d.nVertices, false);
  for (const auto& [e, n] : faceCount)
    if (n == 1) boundary[e.first] = boundary[e.second] = true;
  double total = 0;
  for (int v = 0; v < d.nVertices; ++v) {
    total += (boundary[v] ? M_PI : 2 * M_PI) - sum[v];
    if (!boundary[v]) out.worstInteriorSum = std::max(out.worstInteriorSum, std::abs(sum[v] - 2 * M_PI));
  }
  out.gaussBonnet = total - 2 * M_PI;
  return out;
}

}  // namespace

TEST_CASE("refine --segment-rule chew|ruppert below sqrt(2): a disk, every angle of the file above arcsin(1/(2B))") {
  const fs::path dir = conformesh::testing::scratchDir(), disk = dir / "chew_disk.ply";
  conformesh::testing::CliRun r = conformesh::testing::runConformesh("-q generate disk --rings 3 -o " + disk.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  const double B = 1.12;
  for (const std::string rule : {"chew", "ruppert"}) {
    const fs::path out = dir / ("chew_disk_" + rule + ".ply");
    r = conformesh::testing::runConformesh("-q refine " + disk.string() + " --eps 0.05 --ratio 1.12 --segment-rule " +
                                           rule + " --json -o " + out.string());
    INFO(rule << ": " << r.err);
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["statistics"]["segment_rule"] == rule);
    if (rule == "chew") CHECK(j["statistics"]["deleted_vertices"].get<int>() > 0);  // the rule is not inert here
    if (rule == "ruppert") CHECK(j["statistics"]["deleted_vertices"] == 0);
    const MeshData d = readMesh(out.string());
    const AngleFigures a = anglesOf(d);
    // Shape bound R/ℓ_min ≤ B ⇔ smallest angle ≥ arcsin(1/(2B)) = 26.51°; 1e-9 rad for the file's 17-digit lengths
    // through acos.
    CHECK(a.smallest >= std::asin(1 / (2 * B)) - 1e-9);
    CHECK(a.worstInteriorSum < 1e-9);  // inserted and input interior vertices are flat
    CHECK(std::abs(a.gaussBonnet) <= conformesh::testing::gaussBonnetRoundoff(d.faces.size()));  // acos: c_θ as the half-angle formula's (angles ≥ 26°)
    CHECK(j["quality"]["vertices"] == d.nVertices);
  }
  r = conformesh::testing::runConformesh("-q refine " + disk.string() + " --eps 0.05 --segment-rule shewchuk -o " +
                                         (dir / "x.ply").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("--segment-rule") != std::string::npos);
}
