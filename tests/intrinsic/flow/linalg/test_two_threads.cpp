// test_two_threads.cpp — runChunks (flow/linalg/two_threads.h): every chunk exactly once, and a chunk's exception
// carried back to the caller from either thread — the lowest-numbered thrower's, as a serial loop would throw.
#include <catch2/catch.hpp>

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "flow/linalg/two_threads.h"

using namespace conformesh::intrinsic;

namespace {

// Busy work of a few microseconds, so that the helper thread has time to claim chunks while the caller works.
double spin(int c) {
  double x = c;
  for (int i = 0; i < 20000; ++i) x = x * 0.999 + 1.0;
  return x;
}

}  // namespace

TEST_CASE("runChunks runs every chunk exactly once") {
  for (int repeat = 0; repeat < 20; ++repeat) {
    std::vector<std::atomic<int>> runs(64);
    std::atomic<double> sink{0};
    runChunks(64, [&](int c) {
      sink.store(spin(c));
      runs[c].fetch_add(1);
    });
    for (int c = 0; c < 64; ++c) REQUIRE(runs[c].load() == 1);
  }
}

TEST_CASE("runChunks rethrows the lowest throwing chunk's exception, from either thread, and stays usable") {
  // Chunks 3 and 5 throw; chunks are claimed in index order, so 0–3 have always started when 3 throws. Which thread
  // runs chunk 3 depends on scheduling: the repeats let both happen (without the catch inside runChunks an exception
  // on the helper thread called std::terminate, which ends this test program).
  const std::thread::id caller = std::this_thread::get_id();
  int onHelper = 0;
  for (int repeat = 0; repeat < 50; ++repeat) {
    std::vector<std::atomic<int>> runs(16);
    std::atomic<bool> threwOnHelper{false};
    std::atomic<double> sink{0};
    try {
      runChunks(16, [&](int c) {
        runs[c].fetch_add(1);
        sink.store(spin(c));
        if (c == 3 || c == 5) {
          if (std::this_thread::get_id() != caller) threwOnHelper.store(true);
          throw std::runtime_error("chunk " + std::to_string(c));
        }
      });
      FAIL("runChunks returned normally although chunks 3 and 5 threw");
    } catch (const std::runtime_error& e) {
      REQUIRE(std::string(e.what()) == "chunk 3");
    }
    onHelper += threwOnHelper.load() ? 1 : 0;
    for (int c = 0; c <= 3; ++c) REQUIRE(runs[c].load() == 1);  // every chunk up to the thrower ran, once
    for (int c = 4; c < 16; ++c) REQUIRE(runs[c].load() <= 1);  // later chunks at most once (claimed before the throw)
  }
  INFO("repeats in which a chunk threw on the helper thread: " << onHelper << " of 50");
  // After the exceptions the next call runs on two threads again (the busy flag was released): all chunks run.
  std::vector<std::atomic<int>> runs(8);
  runChunks(8, [&](int c) { runs[c].fetch_add(1); });
  for (int c = 0; c < 8; ++c) CHECK(runs[c].load() == 1);
}

TEST_CASE("onTwoCores passes exceptions through, on both the serial and the two-thread path") {
  for (const std::ptrdiff_t n : {std::ptrdiff_t{100}, std::ptrdiff_t{100000}}) {
    INFO("n = " << n << " (minimum 1000)");
    CHECK_THROWS_WITH(onTwoCores(n, 1000,
                                 [&](std::ptrdiff_t begin, std::ptrdiff_t end) {
                                   if (begin <= n / 2 && n / 2 < end) throw std::runtime_error("middle");
                                 }),
                      "middle");
  }
}
