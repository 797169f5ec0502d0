// End-to-end tests of `conformesh info` on bad input: every kind of malformed file or mesh gets exactly one line on
// stderr naming the file and the element, exit status 1, and never a crash (signal), a hang or a partial output file;
// malformed command lines exit 2.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.h"

namespace fs = std::filesystem;

namespace {

using Run = conformesh::testing::CliRun;
using conformesh::testing::slurp;

Run cli(const std::string& args) {
  return conformesh::testing::runConformesh(args);
}

fs::path writeFile(const std::string& name, const std::string& bytes) {
  const fs::path p = conformesh::testing::scratchDir() / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

// The error is one line ("conformesh: error: ...\n") after any progress lines, and names `what`.
void requireCleanError(const Run& r, const std::string& file, const std::string& what) {
  INFO("stderr: " << r.err);
  CHECK(r.status == 1);
  const auto pos = r.err.find("conformesh: error: ");
  REQUIRE(pos != std::string::npos);
  const std::string line = r.err.substr(pos);
  CHECK(line.find('\n') == line.size() - 1);  // exactly one line
  CHECK(line.find(file) != std::string::npos);
  CHECK(line.find(what) != std::string::npos);
}

const char* kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nelement face 1\nproperty list uchar int vertex_indices\n"
    "element edge 3\nproperty int vertex1\nproperty int vertex2\nproperty double length\nend_header\n";

}  // namespace

TEST_CASE("conformesh info: bad files") {
  SECTION("missing file") {
    requireCleanError(cli("info /nonexistent/mesh.obj"), "/nonexistent/mesh.obj", "cannot open");
  }
  SECTION("empty file") {
    const auto p = writeFile("empty.off", "");
    requireCleanError(cli("info " + p.string()), "empty.off", "");
  }
  SECTION("truncated ASCII OFF") {
    const auto p = writeFile("trunc.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n");
    requireCleanError(cli("info " + p.string()), "trunc.off", "");
  }
  SECTION("truncated binary PLY") {
    std::string bytes =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
        "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    bytes += std::string(40, '\0');  // 3 vertices need 72 bytes
    const auto p = writeFile("trunc.ply", bytes);
    requireCleanError(cli("info " + p.string()), "trunc.ply", "");
  }
  SECTION("garbage tokens") {
    const auto p = writeFile("garbage.obj", "v 0 0 0\nv 1 0 zero\nv 0 1 0\nf 1 2 3\n");
    requireCleanError(cli("info " + p.string()), "garbage.obj:2", "");
  }
  SECTION("OBJ index zero and out of range") {
    const auto p0 = writeFile("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    requireCleanError(cli("info " + p0.string()), "zero.obj:4", "");
    const auto p9 = writeFile("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    requireCleanError(cli("info " + p9.string()), "range.obj:4", "9");
  }
}

TEST_CASE("conformesh info: bad meshes") {
  SECTION("face with a repeated vertex") {
    const auto p = writeFile("rep.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n");
    requireCleanError(cli("info " + p.string()), "rep.off", "repeats vertex");
  }
  SECTION("non-manifold edge") {
    const auto p = writeFile("fin.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    requireCleanError(cli("info " + p.string()), "fin.off", "non-manifold edge (0, 1)");
  }
  SECTION("pinched vertex") {
    const auto p = writeFile("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n");
    requireCleanError(cli("info " + p.string()), "bowtie.off", "pinched vertex 0");
  }
  SECTION("Möbius strip") {
    std::ostringstream off;
    const int n = 6;
    off << "OFF\n" << 2 * n << " " << 2 * n << " 0\n";
    for (int i = 0; i < n; ++i) off << std::cos(M_PI * i / n) << " " << std::sin(M_PI * i / n) << " 0.3\n";
    for (int i = 0; i < n; ++i) off << std::cos(M_PI * i / n) << " " << std::sin(M_PI * i / n) << " -0.3\n";
    for (int i = 0; i < n - 1; ++i)
      off << "3 " << i << " " << i + 1 << " " << n + i + 1 << "\n3 " << i << " " << n + i + 1 << " " << n + i << "\n";
    off << "3 " << n - 1 << " " << n << " 0\n3 " << n - 1 << " 0 " << 2 * n - 1 << "\n";
    const auto p = writeFile("moebius.off", off.str());
    requireCleanError(cli("info " + p.string()), "moebius.off", "not orientable");
  }
  SECTION("NaN coordinate") {
    const auto p = writeFile("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
    requireCleanError(cli("info " + p.string()), "nan.off", "");
  }
  SECTION("zero, negative and NaN lengths, triangle inequality") {
    for (const auto& [name, lengths, what] :
         {std::tuple<std::string, std::string, std::string>{"zero.ply", "0 1 0\n1 2 1\n2 0 0\n", "edge 0"},
          {"negative.ply", "0 1 -1\n1 2 1\n2 0 1\n", "edge 0"},
          {"nanlen.ply", "0 1 nan\n1 2 1\n2 0 1\n", "edge 0"},
          {"inequality.ply", "0 1 3\n1 2 1\n2 0 1\n", "triangle inequality"}}) {
      const auto p = writeFile(name, std::string(kPlyHeader) + "\n\n\n3 0 1 2\n" + lengths);
      INFO(name);
      requireCleanError(cli("info " + p.string()), name, what);
    }
  }
  SECTION("degenerate (zero-area) triangle from positions") {
    const auto p = writeFile("flat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
    requireCleanError(cli("info " + p.string()), "flat.off", "triangle inequality");
  }
}

TEST_CASE("conformesh info: a good file, and --delaunay never clobbers on failure") {
  const auto good = writeFile("good.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  const Run r = cli("info " + good.string() + " --json");
  CHECK(r.status == 0);
  CHECK(r.out.find("\"genus\": 0") != std::string::npos);
  CHECK(r.out.find("\"boundary_loops\": 1") != std::string::npos);
  // A bad input with --delaunay: the existing output file must survive untouched.
  const auto out = writeFile("keep.ply", "precious");
  const auto bad = writeFile("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n");
  const Run rb = cli("info " + bad.string() + " --delaunay " + out.string());
  CHECK(rb.status == 1);
  CHECK(slurp(out) == "precious");
}

TEST_CASE("malformed command lines exit 2 whatever CLI11's kind of mistake, --help exits 0") {
  // CLI11's own codes differ per kind (104 conversion, 105 validation, 106 required, 109 extras, ...); docs/cli.md
  // promises one status for all of them.
  for (const char* args :
       {"", "bogus", "refine x.ply --eps abc -o y.ply", "refine x.ply --eps 0.1 --segment-rule none -o y.ply",
        "refine x.ply -o y.ply", "remesh sphere --eps 0.1 --disk-target foo -o y.ply", "info x.ply --no-such-flag"}) {
    const Run r = cli(args);
    INFO("conformesh " << args << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK_FALSE(r.err.empty());
  }
  for (const char* args : {"--help", "refine --help", "remesh --help"}) {
    const Run r = cli(args);
    INFO("conformesh " << args);
    CHECK(r.status == 0);
    CHECK(r.out.find("Usage") != std::string::npos);
  }
}

namespace {
// A malformed command line: status 2, the first stderr line "conformesh: error: COMMAND: ..." naming `what`, and a
// "conformesh: hint:" line containing `hint` ("" for only the --help pointer).
void requireUsageError(const std::string& args, const std::string& what, const std::string& hint) {
  const Run r = cli(args);
  INFO("conformesh " << args << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.rfind("conformesh: error: ", 0) == 0);  // the first line, no CLI11 text before it
  const std::string first = r.err.substr(0, r.err.find('\n'));
  CHECK(first.find(what) != std::string::npos);
  CHECK(r.err.find("Run with --help") == std::string::npos);  // CLI11's own wording is replaced
  CHECK(r.err.find("conformesh: hint: ") != std::string::npos);
  CHECK(r.err.find(hint) != std::string::npos);
  CHECK(r.err.find("details: docs/cli.md") != std::string::npos);
}
}  // namespace

TEST_CASE("command-line errors are in the documented style with hints for the common mistakes") {
  SECTION("convergence --eps: use --vertices or --levels") {
    requireUsageError("convergence sphere --eps 0.05", "convergence: ", "use --vertices 1k,2k");
  }
  SECTION("a missing required option (CLI11's RequiredError)") {
    requireUsageError("remesh sphere --eps 0.1", "remesh: --output is required", "-o OUT names the output");
    requireUsageError("info", "info: file is required", "conformesh info --help");
  }
  SECTION("remesh without --eps or --eps-rel") {
    requireUsageError("remesh sphere -o never.ply", "--eps E or --eps-rel F is required", "--eps-rel F sets eps");
  }
  SECTION("an unexpected argument (CLI11's ExtrasError)") {
    requireUsageError("info x.ply --no-such-flag", "info: The following argument was not expected: --no-such-flag",
                      "docs/cli.md#info");
  }
  SECTION("-q after the command, a long option with one dash") {
    requireUsageError("remesh -q sphere --eps 0.1 -o never.ply", "not expected: -q", "goes before the command");
    requireUsageError("remesh sphere -eps 0.1 -o never.ply", "-eps", "two dashes: --eps");
  }
  SECTION("no command, a misspelt command, an unknown one") {
    requireUsageError("", "A subcommand is required", "give a command: info");
    requireUsageError("remsh sphere", "unknown command 'remsh'", "did you mean `conformesh remesh`?");
    requireUsageError("bogus", "unknown command 'bogus'", "the commands are info");
  }
  SECTION("a bad value (conversion) and a command's own check (UsageError)") {
    requireUsageError("refine x.ply --eps abc -o y.ply", "refine: Could not convert: --eps = abc", "refine --help");
    requireUsageError("convergence sphere --levels 1", "convergence: --levels: expected 3 to 11, found 1",
                      "docs/cli.md#convergence");
    requireUsageError("convergence sphere --vertices 1k,2k", "convergence: give at least three target vertex counts",
                      "docs/cli.md#convergence");
    requireUsageError("convergence sphere --vertices 1k,1k,2k",
                      "convergence: target vertex counts must increase: level 2's 1000 follows 1000",
                      "docs/cli.md#convergence");
  }
  CHECK_FALSE(std::filesystem::exists("never.ply"));
}
