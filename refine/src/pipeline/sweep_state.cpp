// sweep_state.cpp — atomic writes and the layout of a sweep's folder (see sweep_state.h).
#include "conformesh/refine/pipeline/sweep_state.h"


#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "conformesh/intrinsic/errors.h"
#include "conformesh/intrinsic/io/file_write.h"

namespace conformesh::refine {

namespace fs = std::filesystem;

namespace {
std::string hostName() {
  char h[256] = {0};
  gethostname(h, sizeof h - 1);
  return h[0] ? h : "host";
}
}  // namespace

std::string temporaryNameFor(const std::string& path) {
  const fs::path p(path);
  return (p.parent_path() / (p.stem().string() + ".tmp-" + hostName() + "-" + std::to_string(getpid()) +
                             p.extension().string()))
      .string();
}

bool isTemporaryName(const std::string& filename) {
  return filename.find(".tmp-") != std::string::npos;
}

void writeFileAtomically(const std::string& path, const std::string& content) {
  intrinsic::writeFileAtomically(path, content, /*sync=*/true);  // a rerun trusts what is there
}

std::string SweepDir::caseDir(const std::string& id) const {
  return (fs::path(root) / "cases" / id).string();
}
std::string SweepDir::recordPath(const std::string& id) const {
  return (fs::path(caseDir(id)) / "record.json").string();
}
std::string SweepDir::attemptsPath(const std::string& id) const {
  return (fs::path(caseDir(id)) / "attempts.log").string();
}

std::optional<nlohmann::json> readRecord(const SweepDir& dir, const std::string& id) {
  std::ifstream in(dir.recordPath(id));
  if (!in) return std::nullopt;
  try {
    nlohmann::json j = nlohmann::json::parse(in);
    if (j.is_object() && j.value("id", "") == id && j.contains("status")) return j;
  } catch (const nlohmann::json::exception&) {
  }
  return std::nullopt;  // not a complete record: the case is redone
}

void prepareCaseDir(const SweepDir& dir, const std::string& id) {
  const fs::path d = dir.caseDir(id);
  std::error_code ec;
  fs::create_directories(d, ec);
  if (ec) throw InputError(d.string() + ": cannot create (" + ec.message() + ")");
  for (const auto& e : fs::directory_iterator(d, ec))
    if (isTemporaryName(e.path().filename().string())) fs::remove(e.path(), ec);
}

void logAttempt(const SweepDir& dir, const std::string& id, int rank) {
  char when[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  const std::string line = std::string("START ") + when + " host=" + hostName() + " pid=" + std::to_string(getpid()) +
                           " rank=" + std::to_string(rank) + "\n";
  const int fd = ::open(dir.attemptsPath(id).c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) return;  // the log is diagnostic; the record is what counts
  [[maybe_unused]] const ssize_t n = ::write(fd, line.data(), line.size());
  ::close(fd);
}

}  // namespace conformesh::refine
