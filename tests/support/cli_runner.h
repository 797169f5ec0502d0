// cli_runner.h — runs the `conformesh` executable from an end-to-end test (path in CONFORMESH_CLI) and captures its
// exit status and output, in the test process's own scratch folder (scratch_dir.h): CTest runs test cases in parallel.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/scratch_dir.h"

namespace conformesh::testing {

struct CliRun {
  int status = -1;  // exit status, or −signal
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `conformesh ARGS` with a 60 s timeout, so that a hang fails the test instead of stalling the suite.
inline CliRun runConformesh(const std::string& args) {
  const auto dir = scratchDir();
  const std::string cmd = "timeout 60 " + std::string(CONFORMESH_CLI) + " " + args + " >" + (dir / "out").string() +
                          " 2>" + (dir / "err").string();
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  return r;
}

}  // namespace conformesh::testing
