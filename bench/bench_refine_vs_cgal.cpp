// bench_refine_vs_cgal.cpp — conformesh's intrinsic Delaunay refinement against CGAL 5.5's Delaunay_mesher_2 on the
// same unit-disk polygon (a regular 64-gon inscribed in the unit circle, no interior points) with the same shape bound,
// calibrated to equal vertex counts. Reported per tool: CPU time (process CPU clock: steadier than wall time on a
// shared machine), smallest angle, mean per-triangle smallest angle, peak resident memory (each measurement runs in a
// fresh process, whose high-water mark wait4() returns).
//
// Both refine the polygon (boundary edges split at their midpoints on the chord: BoundarySplit::Geodesic), with
// B = √2, i.e. CGAL's aspect bound b = sin²(20.7°) = 1/(4B²) = 0.125. CGAL's size criterion bounds the longest edge,
// conformesh's the circumradius, so each tool's size parameter is calibrated (V ∝ size⁻²) until its vertex count is
// within 1% of the target.
//
//   cmake -B build-bench -DCMAKE_BUILD_TYPE=Release -DCONFORMESH_BUILD_BENCH=ON   (CGAL: apt-get install libcgal-dev)
//   cmake --build build-bench -j2 --target bench_refine_vs_cgal
//   build-bench/bench/bench_refine_vs_cgal --table            # the table of docs/benchmarks.md
//   build-bench/bench/bench_refine_vs_cgal --scaling          # conformesh alone, 10k .. 1M vertices
//   build-bench/bench/bench_refine_vs_cgal --compare20k 7     # alternating rounds at 20k, minimum per tool
//   build-bench/bench/bench_refine_vs_cgal --below-sqrt2 1.12 # Ruppert's and Chew's rule, and CGAL, at B = 1.12
//   build-bench/bench/bench_refine_vs_cgal --peers NODE_MODULES DRIVER [ROUNDS]
//                                             # conformesh, CGAL and Triangle (wasm, bench/bench_refine_peers.sh)
//   build-bench/bench/bench_refine_vs_cgal                    # Google Benchmark timings at 20k vertices
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include "conformesh/intrinsic/mesh/mesh_data.h"
#include "conformesh/refine/delaunay/delaunay_refinement.h"
#include "conformesh/refine/delaunay/refinement_quality.h"

#ifdef CONFORMESH_HAVE_CGAL
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

constexpr int kPolygon = 64;
// The shape bound: √2 for the main table, below it for --below-sqrt2 (passed on to the child processes).
double gB = 1.4142135623730951;
constexpr double kDeg = 180 / M_PI;

// CPU time of this process in seconds.
double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct Outcome {
  double seconds = 0, minAngle = 0, meanMinAngle = 0;
  long vertices = 0;
};

// === conformesh: the polygon fan-triangulated from vertex 0 (the refinement's first Lawson pass makes it Delaunay).
conformesh::intrinsic::IntrinsicTriangulation diskPolygon() {
  conformesh::intrinsic::MeshData d;
  d.nVertices = kPolygon;
  for (int i = 0; i < kPolygon; ++i)
    d.positions.emplace_back(std::cos(2 * M_PI * i / kPolygon), std::sin(2 * M_PI * i / kPolygon), 0.0);
  for (int i = 1; i + 1 < kPolygon; ++i) d.faces.push_back({0, i, i + 1});
  return conformesh::intrinsic::toTriangulation(d);
}

Outcome runConformesh(double eps, conformesh::refine::SegmentRule rule = conformesh::refine::SegmentRule::Ruppert) {
  static const conformesh::intrinsic::IntrinsicTriangulation input = diskPolygon();
  conformesh::refine::RefineOptions o;
  o.epsilon = eps;
  o.ratioBound = gB;
  o.segmentRule = rule;
  o.boundarySplit = conformesh::refine::BoundarySplit::Geodesic;
  const double t0 = cpuSeconds();
  const conformesh::refine::RefineResult r = conformesh::refine::refineDelaunay(input, o);
  Outcome out;
  out.seconds = cpuSeconds() - t0;
  const conformesh::refine::QualityReport q = conformesh::refine::measureQuality(r.triangulation);
  out.vertices = q.vertices;
  out.minAngle = q.minAngleDeg;
  out.meanMinAngle = q.meanMinAngleDeg;
  return out;
}

#ifdef CONFORMESH_HAVE_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;

Outcome runCgal(double size) {
  const double t0 = cpuSeconds();
  CDT cdt;
  std::vector<CDT::Vertex_handle> vh;
  for (int i = 0; i < kPolygon; ++i)
    vh.push_back(cdt.insert(CDT::Point(std::cos(2 * M_PI * i / kPolygon), std::sin(2 * M_PI * i / kPolygon))));
  for (int i = 0; i < kPolygon; ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % kPolygon]);
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(1 / (4 * gB * gB), size));
  Outcome out;
  out.seconds = cpuSeconds() - t0;
  out.vertices = static_cast<long>(cdt.number_of_vertices());
  double minA = 180, sum = 0;
  long faces = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    double smallest = 180;
    for (int k = 0; k < 3; ++k) {
      const K::Point_2 &a = f->vertex(k)->point(), &b = f->vertex((k + 1) % 3)->point(),
                       &c = f->vertex((k + 2) % 3)->point();
      const double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = c.x() - a.x(), vy = c.y() - a.y();
      smallest = std::min(smallest, std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * kDeg);
    }
    minA = std::min(minA, smallest);
    sum += smallest;
    ++faces;
  }
  out.minAngle = minA;
  out.meanMinAngle = sum / faces;
  return out;
}
#endif

// Scales `size` by √(V/target) (V ∝ size⁻²) until the vertex count is within 1% of the target.
double calibrate(const std::function<Outcome(double)>& run, long target, double size) {
  for (int it = 0; it < 8; ++it) {
    const Outcome o = run(size);
    const double ratio = double(o.vertices) / target;
    if (std::abs(ratio - 1) < 0.01) break;
    size *= std::sqrt(ratio);
  }
  return size;
}

// Runs one tool in a fresh process (fork + exec of this program with --run), so that its peak resident memory, which
// wait4() returns, is its own and not inherited from the calibration runs. Returns the outcome and the peak (MiB).
std::pair<Outcome, double> measure(const char* tool, double size, int repeats) {
  int fd[2];
  if (pipe(fd) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    dup2(fd[1], 1);
    char sz[32], bound[32];
    std::snprintf(sz, sizeof sz, "%.17g", size);
    std::snprintf(bound, sizeof bound, "%.17g", gB);
    const std::string rep = std::to_string(repeats);
    execl("/proc/self/exe", "bench_refine_vs_cgal", "--run", tool, sz, rep.c_str(), bound, static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fd[1]);
  Outcome o;
  const ssize_t got = read(fd[0], &o, sizeof o);
  close(fd[0]);
  int status = 0;
  struct rusage ru;
  wait4(pid, &status, 0, &ru);
  if (got != sizeof o) std::fprintf(stderr, "bench_refine_vs_cgal: the %s run failed\n", tool);
  return {o, ru.ru_maxrss / 1024.0};
}

// The child side of measure(): best time of `repeats` runs, written to stdout as raw bytes.
int runChild(const std::string& tool, double size, int repeats) {
  Outcome best;
  for (int i = 0; i < repeats; ++i) {
    const conformesh::refine::SegmentRule rule =
        tool == "conformesh-chew" ? conformesh::refine::SegmentRule::Chew : conformesh::refine::SegmentRule::Ruppert;
#ifdef CONFORMESH_HAVE_CGAL
    const Outcome o = tool == "cgal" ? runCgal(size) : runConformesh(size, rule);
#else
    const Outcome o = runConformesh(size, rule);
#endif
    if (i == 0 || o.seconds < best.seconds) best = o;
  }
  return fwrite(&best, sizeof best, 1, stdout) == 1 ? 0 : 1;
}

void printRow(const char* tool, long target, const std::pair<Outcome, double>& m) {
  std::printf("| %-10s | %8ld | %9ld | %9.3f | %8.2f | %8.2f | %8.1f |\n", tool, target, m.first.vertices,
              m.first.seconds, m.first.minAngle, m.first.meanMinAngle, m.second);
}

int table() {
  std::printf("| tool       |   target |  vertices | CPU s     | min ang° | mean min° |  peak MiB |\n");
  std::printf("|------------|---------:|----------:|----------:|---------:|----------:|----------:|\n");
  for (long target : {1000L, 20000L, 200000L}) {
    const int repeats = target <= 20000 ? 5 : 1;
    const double eps = calibrate([](double e) { return runConformesh(e); }, target, std::sqrt(3.0 / target));
    printRow("conformesh", target, measure("conformesh", eps, repeats));
#ifdef CONFORMESH_HAVE_CGAL
    const double size = calibrate(runCgal, target, std::sqrt(6.0 / target));
    printRow("CGAL 5.5", target, measure("cgal", size, repeats));
#else
    std::printf("| CGAL 5.5   | %8ld | (not built: install libcgal-dev and reconfigure) |\n", target);
#endif
  }
  return 0;
}

// Alternating rounds at 20k vertices (the sizes calibrated once), each tool in a fresh process taking its best of 5:
// on a shared machine the minimum over rounds is the figure least disturbed by other jobs.
int compare20k(int rounds) {
  const double eps = calibrate([](double e) { return runConformesh(e); }, 20000, std::sqrt(1.75 / 20000));
#ifdef CONFORMESH_HAVE_CGAL
  const double size = calibrate(runCgal, 20000, std::sqrt(6.0 / 20000));
#endif
  double best[2] = {INFINITY, INFINITY};
  for (int i = 0; i < rounds; ++i) {
    const double a = measure("conformesh", eps, 5).first.seconds;
    best[0] = std::min(best[0], a);
#ifdef CONFORMESH_HAVE_CGAL
    const double b = measure("cgal", size, 5).first.seconds;
    best[1] = std::min(best[1], b);
    std::printf("round %d: conformesh %.4f s, CGAL %.4f s\n", i + 1, a, b);
#else
    std::printf("round %d: conformesh %.4f s\n", i + 1, a);
#endif
  }
  std::printf("minimum over %d rounds: conformesh %.4f s, CGAL %.4f s, ratio CGAL/conformesh %.2f\n", rounds, best[0],
              best[1], best[1] / best[0]);
  return 0;
}

// Below √2 (default B = 1.12, 26.5°): conformesh with Ruppert's and with Chew's segment rule at the same ε (calibrated
// for Ruppert's rule), and CGAL at the same angle bound calibrated to Ruppert's vertex count. Best of 5 runs each.
int belowSqrt2(double B) {
  gB = B;
  std::printf("B = %.4f (smallest angle >= %.2f°)\n", B, std::asin(1 / (2 * B)) * kDeg);
  std::printf("| tool       |   target |  vertices | CPU s     | min ang° | mean min° |  peak MiB |\n");
  std::printf("|------------|---------:|----------:|----------:|---------:|----------:|----------:|\n");
  for (long target : {1000L, 20000L}) {
    const double eps = calibrate([](double e) { return runConformesh(e); }, target, std::sqrt(3.0 / target));
    printRow("Ruppert", target, measure("conformesh", eps, 5));
    printRow("Chew", target, measure("conformesh-chew", eps, 5));
#ifdef CONFORMESH_HAVE_CGAL
    const double size = calibrate(runCgal, target, std::sqrt(6.0 / target));
    printRow("CGAL 5.5", target, measure("cgal", size, 5));
#endif
  }
  return 0;
}

// Growth of each tool's CPU time with the vertex count, one fresh process per row. CGAL's rows (when built with it)
// use its size bound sqrt(6/V), which lands near V vertices without calibration: a peer on the same machine, to tell
// the machine's memory hierarchy from the algorithm's growth.
int scaling() {
  std::printf("| tool | vertices | CPU s    | µs per vertex | µs per (vertex·log2 V) | peak MiB |\n");
  std::printf("|------|---------:|---------:|--------------:|-----------------------:|---------:|\n");
  auto row = [](const char* name, const std::pair<Outcome, double>& m) {
    const double us = 1e6 * m.first.seconds / m.first.vertices;
    std::printf("| %s | %8ld | %8.3f | %13.3f | %22.4f | %8.1f |\n", name, static_cast<long>(m.first.vertices),
                m.first.seconds, us, us / std::log2(double(m.first.vertices)), m.second);
    std::fflush(stdout);
  };
  for (long target : {10000L, 100000L, 1000000L}) {
    row("conformesh", measure("conformesh", std::sqrt(1.75 / target), 1));  // V ≈ 1.75/ε² for this disk (measured)
#ifdef CONFORMESH_HAVE_CGAL
    row("CGAL 5.5", measure("cgal", std::sqrt(6.0 / target), 1));
#endif
  }
  return 0;
}

// === Triangle (npm triangle-wasm in node, driven by bench/triangle_driver.mjs): one JSON line per call.
struct TriangleOutcome {
  Outcome o;
  double area = 0;
  std::string error;  // non-empty when the wasm module aborted (its fixed 16 MiB heap)
};

// The number after "key": in a one-line JSON object, or NaN.
double jsonNumber(const std::string& line, const char* key) {
  const std::string k = std::string("\"") + key + "\":";
  const size_t at = line.find(k);
  return at == std::string::npos ? NAN : std::atof(line.c_str() + at + k.size());
}

TriangleOutcome runTriangle(const std::string& nodeModules, const std::string& driver, const std::string& args) {
  const std::string cmd = "node '" + driver + "' '" + nodeModules + "' " + args + " 2>/dev/null";
  TriangleOutcome t;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return t.error = "popen failed", t;
  std::string line;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p) != nullptr) line += buf;
  pclose(p);
  const size_t err = line.find("\"error\":");
  if (err != std::string::npos || line.empty()) return t.error = line.empty() ? "no output" : line, t;
  t.area = jsonNumber(line, "area");
  t.o.vertices = static_cast<long>(jsonNumber(line, "vertices"));
  t.o.seconds = jsonNumber(line, "seconds");
  t.o.minAngle = jsonNumber(line, "minAngle");
  t.o.meanMinAngle = jsonNumber(line, "meanMinAngle");
  return t;
}

// One target of --peers: each tool calibrated to the target vertex count, then `rounds` alternating rounds
// (conformesh, CGAL, Triangle; each a fresh process taking its best of 5), the minimum per tool printed with the
// ratios to conformesh's.
void peersRow(long target, int rounds, const std::string& nodeModules, const std::string& driver) {
  const double angle = std::asin(1 / (2 * gB)) * kDeg;
  char angleArg[32];
  std::snprintf(angleArg, sizeof angleArg, "%.4f", angle);
  const double eps = calibrate([](double e) { return runConformesh(e); }, target, std::sqrt(1.75 / target));
#ifdef CONFORMESH_HAVE_CGAL
  const double size = calibrate(runCgal, target, std::sqrt(6.0 / target));
#endif
  const TriangleOutcome cal =
      runTriangle(nodeModules, driver, "calibrate " + std::to_string(target) + " " + angleArg);
  Outcome best[3];
  best[0].seconds = best[1].seconds = best[2].seconds = INFINITY;
  std::string triangleError = cal.error;
  for (int r = 0; r < rounds; ++r) {
    const Outcome a = measure("conformesh", eps, 5).first;
    if (a.seconds < best[0].seconds) best[0] = a;
#ifdef CONFORMESH_HAVE_CGAL
    const Outcome b = measure("cgal", size, 5).first;
    if (b.seconds < best[1].seconds) best[1] = b;
#endif
    if (!triangleError.empty()) continue;
    char areaArg[40];
    std::snprintf(areaArg, sizeof areaArg, "%.17g", cal.area);
    const TriangleOutcome c = runTriangle(nodeModules, driver, std::string("run ") + areaArg + " 5 " + angleArg);
    if (!c.error.empty()) triangleError = c.error;
    else if (c.o.seconds < best[2].seconds) best[2] = c.o;
  }
  const char* names[3] = {"conformesh", "CGAL 5.5", "Triangle (wasm)"};
  for (int k = 0; k < 3; ++k) {
    if (k == 2 && !triangleError.empty()) {
      std::printf("| %-15s | %8ld | stopped: %s", names[k], target, triangleError.c_str());
      if (triangleError.back() != '\n') std::printf("\n");
      continue;
    }
    if (std::isinf(best[k].seconds)) continue;  // CGAL not built
    std::printf("| %-15s | %8ld | %9ld | %9.4f | %6.2f | %8.2f | %9.2f |\n", names[k], target, best[k].vertices,
                best[k].seconds, best[k].seconds / best[0].seconds, best[k].minAngle, best[k].meanMinAngle);
  }
  std::fflush(stdout);
}

int peers(const std::string& nodeModules, const std::string& driver, int rounds) {
  std::printf("B = %.4f: conformesh eps, CGAL aspect bound %.4f, Triangle -q%.4f; %d alternating rounds, best of 5 each\n",
              gB, 1 / (4 * gB * gB), std::asin(1 / (2 * gB)) * kDeg, rounds);
  std::printf("| tool            |   target |  vertices | CPU s     | ×conf. | min ang° | mean min° |\n");
  std::printf("|-----------------|---------:|----------:|----------:|-------:|---------:|----------:|\n");
  for (long target : {20000L, 40000L, 200000L}) peersRow(target, target > 100000 ? 1 : rounds, nodeModules, driver);
  return 0;
}

void BM_conformesh_20k(benchmark::State& state) {
  const double eps = std::sqrt(1.75 / 20000);
  for (auto _ : state) benchmark::DoNotOptimize(runConformesh(eps).vertices);
}
BENCHMARK(BM_conformesh_20k)->Unit(benchmark::kMillisecond);
#ifdef CONFORMESH_HAVE_CGAL
void BM_cgal_20k(benchmark::State& state) {
  const double size = std::sqrt(6.0 / 20000);
  for (auto _ : state) benchmark::DoNotOptimize(runCgal(size).vertices);
}
BENCHMARK(BM_cgal_20k)->Unit(benchmark::kMillisecond);
#endif

}  // namespace

int main(int argc, char** argv) {
  // --run TOOL SIZE REPEATS [B]: one measurement, in the child process of measure() (B defaults to √2).
  if ((argc == 5 || argc == 6) && std::strcmp(argv[1], "--run") == 0) {
    if (argc == 6) gB = std::atof(argv[5]);
    return runChild(argv[2], std::atof(argv[3]), std::atoi(argv[4]));
  }
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--table") == 0) return table();
    if (std::strcmp(argv[i], "--scaling") == 0) return scaling();
    if (std::strcmp(argv[i], "--below-sqrt2") == 0) return belowSqrt2(i + 1 < argc ? std::atof(argv[i + 1]) : 1.12);
    if (std::strcmp(argv[i], "--peers") == 0 && i + 2 < argc)
      return peers(argv[i + 1], argv[i + 2], i + 3 < argc ? std::atoi(argv[i + 3]) : 5);
    if (std::strcmp(argv[i], "--compare20k") == 0) return compare20k(i + 1 < argc ? std::atoi(argv[i + 1]) : 7);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
