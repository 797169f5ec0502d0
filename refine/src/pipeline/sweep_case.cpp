// sweep_case.cpp — one case of a sweep, computed in a child process with a time limit (see sweep_case.h).
#include "conformesh/refine/pipeline/sweep_case.h"

#include <omp.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/mesh_io.h"
#include "conformesh/intrinsic/io/vtk_writer.h"
#include "conformesh/intrinsic/measure/gaussian_curvature_measure.h"
#include "conformesh/intrinsic/metric/horizon_surface.h"
#include "conformesh/intrinsic/metric/strahlkorper_io.h"
#include "conformesh/intrinsic/metric/metric_quadrature.h"
#include "conformesh/intrinsic/metric/metric_registry.h"
#include "conformesh/intrinsic/metric/sampled_field_io.h"
#include "conformesh/intrinsic/metric/sampled_metric.h"
#include "conformesh/refine/pipeline/mesh_remesh.h"
#include "conformesh/refine/pipeline/metric_remesh.h"
#include "conformesh/refine/pipeline/remesh_json.h"

namespace conformesh::refine {

namespace fs = std::filesystem;
using nlohmann::json;

std::string SweepRunOptions::validate() const {
  if (dir.empty()) return "sweep: the output folder (-o DIR) is required";
  if (!(caseTimeout >= 0) || !std::isfinite(caseTimeout))
    return "sweep: --case-timeout: expected seconds >= 0, found " + std::to_string(caseTimeout);
  if (threads < 0) return "sweep: --threads: expected >= 0, found " + std::to_string(threads);
  if (shardCount < 1 || shardIndex < 0 || shardIndex >= shardCount)
    return "sweep: --shard: expected K/N with 0 <= K < N, found " + std::to_string(shardIndex) + "/" +
           std::to_string(shardCount);
  return "";
}

namespace {

// Vertex counts scale like area / (c ε²), c ≈ 1.1 for Ruppert-quality meshes (convergence_study.cpp); one corrected
// run when the first misses the target by more than 15 %.
constexpr double kVertexConstant = 1.1, kCalibrationTolerance = 0.15;

void writeMeshFiles(const intrinsic::MeshData& data, const std::function<intrinsic::VtkMesh()>& makeVtk,
                    const SweepDir& dir, const SweepCase& c, json& record) {
  const std::string ply = (fs::path(dir.caseDir(c.id)) / "mesh.ply").string();
  const std::string tmp = temporaryNameFor(ply);
  intrinsic::writeMesh(data, tmp);
  fs::rename(tmp, ply);
  record["output"] = "mesh.ply";
  if (c.options["vtk"].get<bool>()) {
    const std::string vtk = (fs::path(dir.caseDir(c.id)) / "mesh.vtk").string();
    const std::string vtmp = temporaryNameFor(vtk);
    intrinsic::writeVtk(makeVtk(), vtmp);
    fs::rename(vtmp, vtk);
    record["vtk"] = "mesh.vtk";
  }
}

void addMeasureProperties(intrinsic::MeshData& data, const intrinsic::CurvatureMeasureResult& m) {
  std::vector<double> error(m.discrete.size());
  for (size_t v = 0; v < error.size(); ++v) error[v] = m.discrete[v] - m.smooth[v];
  data.vertexProperties["error"] = std::move(error);
  data.vertexProperties["relative_error"] = m.relativeError;
}

void applyRefinementOptions(const json& opt, RefineOptions& r) {
  r.smoothingPasses = opt["smoothing"].get<int>();
  r.smoothingRule = parseSmoothingRule(opt["smoothing-rule"].get<std::string>());
  r.segmentRule = parseSegmentRule(opt["segment-rule"].get<std::string>());
}

json computeMetricCase(const SweepCase& c, const SweepRunOptions& options,
                       const std::function<void(const std::string&)>& stage) {
  const json& opt = c.options;
  if (opt["refine-in"] != "uniformized")
    throw InputError("option refine-in " + opt["refine-in"].get<std::string>() +
                     " applies to mesh files; a smooth metric is refined uniformized");
  stage(c.kind == SweepInputKind::Field ? "reading metric field " + c.input : "building metric " + c.input);
  std::unique_ptr<intrinsic::SmoothMetric> metric;
  if (c.kind == SweepInputKind::Field)
    metric = std::make_unique<intrinsic::SampledMetric>(intrinsic::readSampledField(c.input));
  else if (c.kind == SweepInputKind::Horizon && c.horizonMetric.is_object())
    metric = intrinsic::makeHorizonMetric(c.input, c.horizonMetric["spatial_metric"].get<std::string>(),
                                          c.horizonMetric["params"].get<std::map<std::string, double>>());
  else if (c.kind == SweepInputKind::Horizon)
    metric = intrinsic::makeHorizonMetricFromFile(c.input);
  else
    metric = intrinsic::makeMetric(c.input, c.params);
  RemeshOptions o;
  o.ratioBound = opt["ratio"].get<double>();
  o.uniform = opt["uniform"].get<bool>();
  o.t0Resolution = opt["t0-resolution"].get<int>();
  o.diskTarget = parseDiskTarget(opt["disk-target"].get<std::string>());
  applyRefinementOptions(opt, o.refinement);
  o.progress = stage;
  stage("smooth area by quadrature");
  intrinsic::QuadratureOptions q;
  q.absoluteTolerance = 1e-12;
  q.relativeTolerance = 1e-12;
  const double area = intrinsic::metricArea(*metric, q).value;
  RemeshResult r;
  if (c.targetVertices > 0) {
    double k = kVertexConstant;
    for (int attempt = 0; attempt < 2; ++attempt) {
      o.epsilon = std::sqrt(area / (k * c.targetVertices));
      stage("remesh for " + std::to_string(c.targetVertices) + " vertices at eps " + std::to_string(o.epsilon));
      r = remeshMetric(*metric, o);
      const int n = r.mesh.mesh.nVertices();
      k = area / (n * o.epsilon * o.epsilon);
      if (std::abs(n - c.targetVertices) <= kCalibrationTolerance * c.targetVertices) break;
    }
  } else {
    o.epsilon = c.epsilon;
    r = remeshMetric(*metric, o);
  }
  json j = metricRemeshJson(r, *metric, o);
  j["smooth_area"] = area;
  if (c.kind == SweepInputKind::Horizon) {
    stage("horizon diagnostics");
    j["horizon"] = horizonJson(*metric, j["total_area"].get<double>());
    j["horizon"]["shape"] = horizonShapeJson(intrinsic::readHorizonShape(c.input));
    stage("approximate Killing vector on the output mesh (axis, orbits)");
    j["horizon"]["killing"] = killingJson(r.mesh, r.reference, metric->domain());  // as remesh --horizon --json
    const intrinsic::HorizonFileMetadata meta = intrinsic::readHorizonMetadata(c.input);
    j["time"] = meta.hasTime ? json(meta.time) : json(nullptr);
  }
  intrinsic::MeshData data = toMeshData(r, *metric, o.epsilon);
  if (!opt["no-check"].get<bool>()) {
    stage("checking the Gaussian curvature measure on " + std::to_string(r.mesh.mesh.nVertices()) + " balls");
    intrinsic::CurvatureMeasureOptions co;
    co.region = opt["region"] == "union" ? intrinsic::MeasureRegion::TriangleUnion : intrinsic::MeasureRegion::GeodesicBall;
    const intrinsic::CurvatureMeasureResult m = intrinsic::gaussianCurvatureMeasure(r.mesh, r.reference, *metric, co);
    j["gaussian_curvature_measure"] = curvatureMeasureJson(m, co);
    addMeasureProperties(data, m);
  }
  stage("writing the mesh");
  writeMeshFiles(data, [&] { return toVtkMesh(data, r); }, SweepDir{options.dir}, c, j);
  return j;
}

json computeMeshCase(const SweepCase& c, const SweepRunOptions& options,
                     const std::function<void(const std::string&)>& stage) {
  const json& opt = c.options;
  stage("reading mesh " + c.input);
  const MeshInput in = meshInputFromData(intrinsic::readMesh(c.input));
  MeshRemeshOptions o;
  o.ratioBound = opt["ratio"].get<double>();
  o.uniform = opt["uniform"].get<bool>();
  o.refineIn = parseRefineMetric(opt["refine-in"].get<std::string>());
  if (o.refineIn == RefineMetric::Uniformized && opt["smoothing"].get<int>() != 0)
    throw InputError("option smoothing applies to a mesh file with refine-in input; refined uniformized, a mesh is "
                     "refined unsmoothed");
  applyRefinementOptions(opt, o.refinement);
  o.progress = stage;
  MeshRemeshResult r;
  if (c.targetVertices > 0) {
    const double area = intrinsic::totalArea(in.triangulation);
    double k = kVertexConstant;
    for (int attempt = 0; attempt < 2; ++attempt) {
      o.epsilon = std::sqrt(area / (k * c.targetVertices));
      r = remeshMesh(in.triangulation, in.positions, o);
      const int n = r.mesh.mesh.nVertices();
      k = area / (n * o.epsilon * o.epsilon);
      if (std::abs(n - c.targetVertices) <= kCalibrationTolerance * c.targetVertices) break;
    }
  } else {
    o.epsilon = c.epsilon;
    r = remeshMesh(in.triangulation, in.positions, o);
  }
  json j = meshRemeshJson(r, in.triangulation, in.source, o);
  intrinsic::MeshData data = toMeshData(r, in.source, o.epsilon);
  if (!opt["no-check"].get<bool>()) {
    stage("checking the Gaussian curvature measure on " + std::to_string(r.mesh.mesh.nVertices()) + " balls");
    intrinsic::CurvatureMeasureOptions co;
    const intrinsic::CurvatureMeasureResult m = meshCurvatureMeasure(r, in.triangulation, co);
    j["gaussian_curvature_measure"] = curvatureMeasureJson(m, co);
    addMeasureProperties(data, m);
  }
  stage("writing the mesh");
  writeMeshFiles(data, [&] { return toVtkMesh(data, r); }, SweepDir{options.dir}, c, j);
  return j;
}

json baseRecord(const SweepCase& c, const SweepRunOptions& options) {
  return {{"id", c.id}, {"status", "ok"}, {"error", nullptr}, {"error_kind", nullptr}, {"where", nullptr},
          {"case", c.inputsJson()}, {"producer", options.producer}};
}

}  // namespace

json computeSweepCase(const SweepCase& c, const SweepRunOptions& options,
                      const std::function<void(const std::string&)>& stage) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string where = "start";
  auto say = [&](const std::string& s) {
    where = s;
    if (stage) stage(s);
  };
  json record = baseRecord(c, options);
  auto fail = [&](const char* kind, const std::string& what) {
    record["status"] = "failed";
    record["error_kind"] = kind;
    record["error"] = what;
    record["where"] = where;
  };
  try {
    const json result = c.kind == SweepInputKind::Mesh ? computeMeshCase(c, options, say) : computeMetricCase(c, options, say);
    for (const auto& [k, v] : result.items()) record[k] = v;
  } catch (const InputError& e) {
    fail("input", e.what());
  } catch (const ConvergenceError& e) {
    fail("convergence", e.what());
  } catch (const std::exception& e) {
    fail("internal", e.what());
  }
  record["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return record;
}

namespace {

// The child: computes the case, sends its stage lines up the pipe, writes the record, and leaves without running the
// parent's exit handlers (MPI's among them).
[[noreturn]] void runChild(const SweepCase& c, const SweepRunOptions& options, int pipeOut) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  auto stage = [pipeOut](const std::string& s) {
    const std::string line = s + "\n";
    [[maybe_unused]] const ssize_t n = ::write(pipeOut, line.data(), line.size());
  };
  try {
    const json record = computeSweepCase(c, options, stage);
    writeFileAtomically(SweepDir{options.dir}.recordPath(c.id), record.dump(1) + "\n");
  } catch (...) {
    ::_exit(3);
  }
  ::_exit(0);
}

json finishInParent(const SweepCase& c, const SweepRunOptions& options, const char* status, const char* kind,
                    const std::string& error, const std::string& where, double seconds) {
  json record = baseRecord(c, options);
  record["status"] = status;
  record["error_kind"] = kind;
  record["error"] = error;
  record["where"] = where;
  record["wall_seconds"] = seconds;
  writeFileAtomically(SweepDir{options.dir}.recordPath(c.id), record.dump(1) + "\n");
  return record;
}

}  // namespace

json runSweepCase(const SweepCase& c, const SweepRunOptions& options, int rank, const std::function<void()>& tick) {
  const SweepDir dir{options.dir};
  prepareCaseDir(dir, c.id);
  logAttempt(dir, c.id, rank);
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("sweep: pipe() failed: " + std::string(std::strerror(errno)));
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("sweep: fork() failed: " + std::string(std::strerror(errno)));
  if (pid == 0) {
    ::close(fds[0]);
    runChild(c, options, fds[1]);
  }
  ::close(fds[1]);
  std::string lastStage = "start", partial;
  bool pipeOpen = true;
  int status = 0;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  for (;;) {
    if (pipeOpen) {
      pollfd p{fds[0], POLLIN, 0};
      if (::poll(&p, 1, 100) > 0) {
        char buf[4096];
        const ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n <= 0) {
          pipeOpen = false;
        } else {
          partial.append(buf, static_cast<size_t>(n));
          for (size_t nl; (nl = partial.find('\n')) != std::string::npos; partial.erase(0, nl + 1))
            if (nl > 0) lastStage = partial.substr(0, nl);
        }
      }
    } else {
      ::usleep(100000);
    }
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
    if (tick) tick();
    if (options.caseTimeout > 0 && elapsed() > options.caseTimeout) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      ::close(fds[0]);
      char limit[64];
      std::snprintf(limit, sizeof limit, "%g", options.caseTimeout);
      return finishInParent(c, options, "timeout", "timeout",
                            std::string("exceeded the case time limit (--case-timeout ") + limit +
                                " s); the case's process was killed",
                            lastStage, elapsed());
    }
  }
  ::close(fds[0]);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
    if (auto record = readRecord(dir, c.id)) return *record;
  const std::string how = WIFSIGNALED(status) ? std::string("was ended by signal ") + std::to_string(WTERMSIG(status)) +
                                                    " (" + strsignal(WTERMSIG(status)) + ")"
                                              : "exited with status " + std::to_string(WEXITSTATUS(status)) +
                                                    " without writing its record";
  return finishInParent(c, options, "failed", "crash", "the case's process " + how, lastStage, elapsed());
}

}  // namespace conformesh::refine
