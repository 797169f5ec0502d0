// scratch_dir.h — a scratch directory of the test process, for files a test writes. Each process gets its own (CTest
// runs test cases in parallel, one process each), and it is removed with its contents when the process exits.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace conformesh::testing {

inline std::filesystem::path scratchDir() {
  struct Scratch {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("conformesh_test_" + std::to_string(::getpid()));
    Scratch() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);  // a stale folder of an earlier process with this id
      std::filesystem::create_directories(path);
    }
    ~Scratch() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Scratch scratch;
  return scratch.path;
}

}  // namespace conformesh::testing
