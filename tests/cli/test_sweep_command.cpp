// End-to-end tests of `conformesh sweep` (docs/sweeps.md): faults recorded while the other cases complete (a bad
// family parameter, a malformed mesh file, a case over --case-timeout), a bad spec rejected with exit 2 naming the
// file, study and key, resumption without recomputing a finished case (counted in the attempt logs), the MPI table
// equal to the serial table number for number, and a run killed with SIGKILL midway then rerun, ending with the
// uninterrupted run's table, no truncated or temporary file, and no finished case computed twice; --shard (disjoint
// shards whose union is the sweep), --table-only (the table from the records, nothing computed), --threads (bit for
// bit the one-thread outputs) and --progress-interval (how often progress lines come).
#include <catch2/catch.hpp>

#include "support/cli_runner.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformesh/intrinsic/io/mesh_io.h"

namespace fs = std::filesystem;
using conformesh::testing::runConformesh;
using conformesh::testing::slurp;
using nlohmann::json;

namespace {

json strip(const json& x) {  // the record minus its wall-clock fields
  if (x.is_object()) {
    json o = json::object();
    for (const auto& [k, v] : x.items())
      if (k != "seconds" && k != "wall_seconds") o[k] = strip(v);
    return o;
  }
  if (x.is_array()) {
    json a = json::array();
    for (const auto& v : x) a.push_back(strip(v));
    return a;
  }
  return x;
}

json readJson(const fs::path& p) {
  return json::parse(slurp(p));
}

int attempts(const fs::path& dir, const std::string& id) {
  std::ifstream in(dir / "cases" / id / "attempts.log");
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind("START ", 0) == 0;
  return n;
}

// Every file in DIR is complete: no temporary names, every JSON parses, every PLY reads.
void requireNoTruncatedFile(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    INFO(e.path());
    REQUIRE(name.find(".tmp-") == std::string::npos);
    if (e.path().extension() == ".json") REQUIRE_NOTHROW(json::parse(slurp(e.path())));
    if (e.path().extension() == ".ply") REQUIRE(conformesh::intrinsic::readMesh(e.path().string()).faces.size() > 0);
  }
}

fs::path writeSpec(const fs::path& dir, const std::string& name, const json& spec) {
  const fs::path p = dir / name;
  std::ofstream(p) << spec.dump(1);
  return p;
}

// 14 small cases (each well under a second): two ellipsoids and the sphere, three eps, smoothing 0 and 1.
json equalSpec() {
  return {{"studies",
           {{{"input", "ellipsoid"}, {"params", {{"f", {0.2, 0.3}}}}, {"eps", {0.1, 0.07, 0.05}},
             {"options", {{"t0-resolution", 4}}}},
            {{"input", "sphere"}, {"eps", {0.1, 0.07, 0.05}}, {"options", {{"t0-resolution", 4}, {"smoothing", {0, 1}}}}},
            {{"input", "torus"}, {"eps", {0.15, 0.1}}, {"options", {{"t0-resolution", 6}}}}}}};
}

std::string mpirun(int n) {
  return std::string(CONFORMESH_MPIEXEC) + " --allow-run-as-root --oversubscribe -n " + std::to_string(n) + " ";
}

}  // namespace

TEST_CASE("sweep: a bad input and a timeout are recorded while every other case completes, and a rerun skips them") {
  const fs::path dir = conformesh::testing::scratchDir() / "faults";
  fs::create_directories(dir);
  std::ofstream(dir / "broken.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n";  // truncated: 2 of 3 vertices, no face
  const json spec = {{"studies",
                      {{{"input", "ellipsoid"}, {"params", {{"f", {0.3, 2.0}}}}, {"eps", {0.1, 0.07}},
                        {"options", {{"t0-resolution", 4}}}},
                       {{"input", "broken.off"}, {"eps", 0.1}},
                       {{"input", "sphere"}, {"eps", 0.003}, {"options", {{"no-check", true}}}}}}};
  const fs::path specPath = writeSpec(dir, "faults.json", spec), out = dir / "out";
  const std::string cmd = "-q sweep " + specPath.string() + " -o " + out.string() + " --case-timeout 2 --no-plot";
  auto r = runConformesh(cmd);
  INFO(r.err);
  CHECK(r.status == 1);  // a case failed: the table is written and the status says so
  const json table = readJson(out / "table.json");
  REQUIRE(table.size() == 6);
  std::map<std::string, int> byStatus;
  for (const json& rec : table) ++byStatus[rec["status"]];
  CHECK(byStatus["ok"] == 2);
  CHECK(byStatus["failed"] == 3);  // f = 2.0 twice, the broken mesh once
  CHECK(byStatus["timeout"] == 1);
  for (const json& rec : table) {
    const std::string status = rec["status"];
    if (status == "ok") {
      CHECK(rec["quality"]["min_angle_deg"].get<double>() > 20.7);  // the shape bound B = sqrt 2 in the metric
      CHECK(rec["gaussian_curvature_measure"]["mean_abs_error"].get<double>() < 0.05);
      CHECK(fs::exists(out / "cases" / rec["id"].get<std::string>() / "mesh.ply"));
    } else if (rec["case"]["kind"] == "mesh") {
      CHECK(rec["error_kind"] == "input");
      CHECK(rec["error"].get<std::string>().find("broken.off") != std::string::npos);
    } else if (status == "failed") {
      CHECK(rec["error"].get<std::string>().find("flattening") != std::string::npos);
      CHECK(rec["where"] == "building metric ellipsoid");
    } else {
      CHECK(rec["error"].get<std::string>().find("--case-timeout 2") != std::string::npos);
      CHECK(rec["wall_seconds"].get<double>() < 10);
      CHECK(rec["where"].get<std::string>().find("refin") != std::string::npos);  // killed while refining
    }
  }
  // The CSV has a header and one row per case.
  const std::string csv = slurp(out / "table.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 7);
  requireNoTruncatedFile(out);

  // A rerun computes nothing: every case has its record (failed and timeout ones too, without --retry-failed).
  r = runConformesh(cmd + " --json");
  CHECK(r.status == 1);
  const auto j = json::parse(r.out.substr(0, r.out.rfind('}') + 1));
  CHECK(j["ran"] == 0);
  CHECK(j["skipped"] == 6);
  for (const json& rec : table) CHECK(attempts(out, rec["id"]) == 1);
  CHECK(strip(readJson(out / "table.json")) == strip(table));
}

TEST_CASE("sweep: case ids are stable and a bad spec is rejected with exit 2 naming the file, study and key") {
  const fs::path dir = conformesh::testing::scratchDir() / "spec";
  fs::create_directories(dir);
  const fs::path good = writeSpec(dir, "good.json", equalSpec());
  auto a = runConformesh("-q sweep " + good.string() + " -o " + (dir / "o").string() + " --list");
  REQUIRE(a.status == 0);
  // The same cases written in another order of keys and with the default options spelt out give the same ids.
  json other = equalSpec();
  other["studies"][0]["options"]["segment_rule"] = "ruppert";
  other["studies"][0]["options"]["smoothing"] = 0;
  auto b = runConformesh("-q sweep " + writeSpec(dir, "other.json", other).string() + " -o " + (dir / "o").string() +
                         " --list");
  REQUIRE(b.status == 0);
  const json ca = json::parse(a.out), cb = json::parse(b.out);
  REQUIRE(ca.size() == 14);
  std::set<std::string> ids;
  for (size_t i = 0; i < ca.size(); ++i) {
    CHECK(ca[i]["id"] == cb[i]["id"]);
    ids.insert(ca[i]["id"].get<std::string>());
  }
  CHECK(ids.size() == 14);

  json bad = equalSpec();
  bad["studies"][1]["options"]["smoothnig"] = 1;
  auto r = runConformesh("-q sweep " + writeSpec(dir, "bad.json", bad).string() + " -o " + (dir / "o").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("bad.json: studies[1].options.smoothnig: unknown option") != std::string::npos);
  bad = equalSpec();
  bad["studies"][2]["eps"] = {0.1, -1};
  r = runConformesh("-q sweep " + writeSpec(dir, "bad2.json", bad).string() + " -o " + (dir / "o").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("bad2.json: studies[2].eps[1]: expected a positive number") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "o"));  // nothing run, nothing written
}

TEST_CASE("sweep: refine-in defaults as on remesh: input for a mesh file, uniformized for a metric") {
  // A mesh case without refine-in is the one `remesh MESH` runs (the input route, docs/cli.md#remesh-meshfile); the
  // uniformized route stays selectable and is another case (another id).
  const fs::path dir = conformesh::testing::scratchDir() / "spec_route";
  fs::create_directories(dir);
  const std::string eight = std::string(CONFORMESH_TEST_DATA_DIR) + "/eight.off";
  const json spec = {{"studies",
                      {{{"input", eight}, {"eps", 0.05}},
                       {{"input", eight}, {"eps", 0.05}, {"options", {{"refine-in", "uniformized"}}}},
                       {{"input", "sphere"}, {"eps", 0.1}}}}};
  const auto r = runConformesh("-q sweep " + writeSpec(dir, "route.json", spec).string() + " -o " +
                               (dir / "o").string() + " --list");
  REQUIRE(r.status == 0);
  const json cases = json::parse(r.out);
  REQUIRE(cases.size() == 3);
  CHECK(cases[0]["options"]["refine-in"] == "input");
  CHECK(cases[1]["options"]["refine-in"] == "uniformized");
  CHECK(cases[2]["options"]["refine-in"] == "uniformized");
  CHECK(cases[0]["id"] != cases[1]["id"]);
}

#ifdef CONFORMESH_MPIEXEC
TEST_CASE("sweep: under mpirun -n 3 the table equals the serial table number for number") {
  const fs::path dir = conformesh::testing::scratchDir() / "mpi";
  fs::create_directories(dir);
  const fs::path spec = writeSpec(dir, "equal.json", equalSpec());
  auto s = runConformesh("-q sweep " + spec.string() + " -o " + (dir / "serial").string() + " --no-plot");
  INFO(s.err);
  REQUIRE(s.status == 0);
  const std::string cmd = "timeout 120 " + mpirun(3) + CONFORMESH_CLI + " -q sweep " + spec.string() + " -o " +
                          (dir / "mpi").string() + " --no-plot > " + (dir / "mpi.out").string() + " 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const json serial = readJson(dir / "serial" / "table.json"), mpi = readJson(dir / "mpi" / "table.json");
  REQUIRE(serial.size() == 14);
  REQUIRE(mpi.size() == 14);
  for (size_t i = 0; i < serial.size(); ++i) {
    INFO(serial[i]["id"]);
    CHECK(strip(mpi[i]) == strip(serial[i]));
  }
  CHECK(strip(readJson(dir / "mpi" / "orders.json")) == strip(readJson(dir / "serial" / "orders.json")));
  // Both workers took cases (rank 0 computes none).
  std::set<std::string> ranks;
  for (const json& rec : mpi) {
    const std::string log = slurp(dir / "mpi" / "cases" / rec["id"].get<std::string>() / "attempts.log");
    ranks.insert(log.substr(log.find("rank=")));
  }
  CHECK(ranks == std::set<std::string>{"rank=1\n", "rank=2\n"});
}

namespace {
// SIGKILL to every process of session `sid` (mpirun started by setsid, its ranks and their case processes).
int killSession(pid_t sid) {
  int killed = 0;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(e.path() / "stat");
    std::string s((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    const auto close = s.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(s.substr(close + 2));
    std::string state;
    long ppid, pgrp, session;
    rest >> state >> ppid >> pgrp >> session;
    if (session == sid && ::kill(std::stoi(name), SIGKILL) == 0) ++killed;
  }
  return killed;
}
}  // namespace

TEST_CASE("sweep: killed with SIGKILL midway under MPI, then rerun, ends with the uninterrupted table") {
  const fs::path dir = conformesh::testing::scratchDir() / "kill";
  fs::create_directories(dir);
  json spec = equalSpec();
  spec["studies"][0]["eps"] = {0.07, 0.05, 0.035};  // a little longer, so that the kill lands midway
  const fs::path specPath = writeSpec(dir, "kill.json", spec), out = dir / "out";
  auto ref = runConformesh("-q sweep " + specPath.string() + " -o " + (dir / "reference").string() + " --no-plot");
  REQUIRE(ref.status == 0);
  const json reference = readJson(dir / "reference" / "table.json");

  const pid_t child = ::fork();
  if (child == 0) {
    ::setsid();
    const std::string cmd = mpirun(3) + CONFORMESH_CLI + " -q sweep " + specPath.string() + " -o " + out.string() +
                            " --no-plot > " + (dir / "killed.out").string() + " 2>&1";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait until some cases have their records, then kill the whole job at once.
  auto records = [&] {
    int n = 0;
    if (fs::exists(out / "cases"))
      for (const auto& e : fs::directory_iterator(out / "cases")) n += fs::exists(e.path() / "record.json");
    return n;
  };
  const auto t0 = std::chrono::steady_clock::now();
  while (records() < 4 && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK(killSession(child) >= 3);  // sh / mpirun, two or three ranks, a case process
  int status = 0;
  ::waitpid(child, &status, 0);
  std::set<std::string> finishedBeforeKill;
  for (const auto& e : fs::directory_iterator(out / "cases"))
    if (fs::exists(e.path() / "record.json")) finishedBeforeKill.insert(e.path().filename().string());
  INFO(finishedBeforeKill.size() << " of 14 cases finished before the kill");
  REQUIRE(finishedBeforeKill.size() >= 4);
  REQUIRE(finishedBeforeKill.size() < 14);
  CHECK_FALSE(fs::exists(out / "table.json"));

  const std::string rerun = "timeout 120 " + mpirun(3) + CONFORMESH_CLI + " -q sweep " + specPath.string() + " -o " +
                            out.string() + " --no-plot > " + (dir / "rerun.out").string() + " 2>&1";
  REQUIRE(std::system(rerun.c_str()) == 0);
  const json table = readJson(out / "table.json");
  REQUIRE(table.size() == reference.size());
  for (size_t i = 0; i < table.size(); ++i) CHECK(strip(table[i]) == strip(reference[i]));
  requireNoTruncatedFile(out);
  for (const json& rec : table) {
    const std::string id = rec["id"];
    if (finishedBeforeKill.count(id))
      CHECK(attempts(out, id) == 1);  // not computed again
    else
      CHECK(attempts(out, id) >= 1);
  }
}
#endif

namespace {
// 5 cases of a few thousand vertices each (well under a second): the sphere at three eps, an ellipsoid at two.
json shardSpec() {
  return {{"studies",
           {{{"input", "sphere"}, {"eps", {0.1, 0.07, 0.05}}, {"options", {{"t0-resolution", 4}}}},
            {{"input", "ellipsoid"},
             {"params", {{"f", {0.3}}}},
             {"eps", {0.1, 0.07}},
             {"options", {{"t0-resolution", 4}}}}}}};
}
// The ids of the cases a run in DIR computed: those whose attempt log has a START line (each at most one).
std::set<std::string> computedIds(const fs::path& dir) {
  std::set<std::string> ids;
  if (!fs::exists(dir / "cases")) return ids;
  for (const auto& e : fs::directory_iterator(dir / "cases")) {
    const int n = attempts(dir, e.path().filename().string());
    REQUIRE(n <= 1);  // no case computed twice
    if (n == 1) ids.insert(e.path().filename().string());
  }
  return ids;
}
// Progress lines ("sweep: K/N done ...") on stderr.
std::vector<std::string> progressLines(const std::string& err) {
  std::vector<std::string> out;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    if (line.find("conformesh: sweep: ") == 0 && line.find(" done (") != std::string::npos) out.push_back(line);
  return out;
}
}  // namespace

TEST_CASE("sweep --shard K/N: disjoint shards whose union is the sweep; --table-only computes nothing") {
  const fs::path dir = conformesh::testing::scratchDir() / "shards";
  fs::create_directories(dir);
  const std::string spec = writeSpec(dir, "spec.json", shardSpec()).string();
  const auto whole = runConformesh("-q sweep " + spec + " -o " + (dir / "whole").string() + " --no-plot");
  INFO(whole.err);
  REQUIRE(whole.status == 0);
  const json all = readJson(dir / "whole" / "table.json");
  REQUIRE(all.size() == 5);
  // Two jobs sharing one DIR, one after the other: shard 0/2 runs the cases of even index in spec order, 1/2 the odd.
  const fs::path shared = dir / "shared";
  REQUIRE(runConformesh("-q sweep " + spec + " -o " + shared.string() + " --shard 0/2 --no-plot").status == 0);
  const std::set<std::string> first = computedIds(shared);
  REQUIRE(runConformesh("-q sweep " + spec + " -o " + shared.string() + " --shard 1/2 --no-plot").status == 0);
  std::set<std::string> second = computedIds(shared);
  for (const auto& id : first) second.erase(id);
  std::set<std::string> even, odd;
  for (size_t i = 0; i < all.size(); ++i) (i % 2 ? odd : even).insert(all[i]["id"].get<std::string>());
  CHECK(first == even);  // 3 cases
  CHECK(second == odd);  // 2 cases: disjoint from the first, and together every case exactly once
  // Each record is the unsharded run's, number for number; the last job's table is the whole table.
  const json sharded = readJson(shared / "table.json");
  REQUIRE(sharded.size() == all.size());
  for (size_t i = 0; i < all.size(); ++i) CHECK(strip(sharded[i]) == strip(all[i]));
  // --table-only rebuilds the table from the records alone: remove it, rebuild, compare; no case is started again.
  fs::remove(shared / "table.json");
  fs::remove(shared / "table.csv");
  const auto rebuilt = runConformesh("sweep " + spec + " -o " + shared.string() + " --table-only --no-plot --json");
  INFO(rebuilt.err);
  REQUIRE(rebuilt.status == 0);
  const json rt = readJson(shared / "table.json");
  REQUIRE(rt.size() == all.size());
  for (size_t i = 0; i < all.size(); ++i) CHECK(strip(rt[i]) == strip(all[i]));
  const std::string csv = slurp(shared / "table.csv");   // (its seconds columns differ from the whole run's)
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 6);  // a header and the 5 cases
  for (const json& rec : all) CHECK(attempts(shared, rec["id"].get<std::string>()) == 1);
  CHECK(progressLines(rebuilt.err).empty());  // nothing ran
  // On a folder with no records it computes nothing either: every case is listed as missing.
  const auto empty =
      runConformesh("-q sweep " + spec + " -o " + (dir / "empty").string() + " --table-only --no-plot --json");
  CHECK(json::parse(empty.out)["missing"] == 5);
  CHECK(computedIds(dir / "empty").empty());
}

TEST_CASE("sweep --threads: 2 OpenMP threads per case give the 1-thread records and meshes bit for bit") {
  // The only parallel loop of a case measures each output edge's length independently (metric_remesh.cpp), so the
  // thread count must not change one bit of any output.
  const fs::path dir = conformesh::testing::scratchDir() / "threads";
  fs::create_directories(dir);
  const std::string spec = writeSpec(dir, "spec.json", shardSpec()).string();
  for (const char* n : {"1", "2"})
    REQUIRE(runConformesh("-q sweep " + spec + " -o " + (dir / n).string() + " --threads " + n + " --no-plot").status ==
            0);
  const json one = readJson(dir / "1" / "table.json"), two = readJson(dir / "2" / "table.json");
  REQUIRE(one.size() == 5);
  REQUIRE(two.size() == 5);
  for (size_t i = 0; i < one.size(); ++i) {
    const std::string id = one[i]["id"];
    INFO(id);
    CHECK(strip(two[i]) == strip(one[i]));
    CHECK(slurp(dir / "2" / "cases" / id / "mesh.ply") == slurp(dir / "1" / "cases" / id / "mesh.ply"));
  }
}

TEST_CASE("sweep --progress-interval: 0 prints a line at every poll of a running case, a long one only the last") {
  // The serial sweep polls each running case every 0.1 s or on each stage message from it, and prints a progress line
  // when --progress-interval seconds have passed since the last one, plus a final line when all are done.
  const fs::path dir = conformesh::testing::scratchDir() / "progress";
  fs::create_directories(dir);
  const std::string spec = writeSpec(dir, "spec.json", shardSpec()).string();
  const auto often =
      runConformesh("sweep " + spec + " -o " + (dir / "a").string() + " --no-plot --progress-interval 0");
  const auto rarely =
      runConformesh("sweep " + spec + " -o " + (dir / "b").string() + " --no-plot --progress-interval 1e6");
  REQUIRE(often.status == 0);
  REQUIRE(rarely.status == 0);
  const auto a = progressLines(often.err), b = progressLines(rarely.err);
  INFO(often.err);
  // At least one line while each case ran (each sends several stage messages), and the final one.
  CHECK(a.size() >= 6);
  CHECK(std::count_if(a.begin(), a.end(),
                      [](const std::string& l) { return l.find(" 1 running") != std::string::npos; }) >= 5);
  REQUIRE(b.size() == 1);
  CHECK(b[0].find("5/5 done (5 ok, 0 failed, 0 timeout), 0 running") != std::string::npos);
}
