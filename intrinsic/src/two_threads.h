// two_threads.h — splitting independent per-element work of the Ricci flow and the uniformization between two cores.
#pragma once

#include <cstddef>
#include <thread>

namespace conformesh::intrinsic {

// Below this many elements a loop runs on one thread: starting a thread costs more than it saves.
constexpr std::ptrdiff_t kParallelMin = 20000;

// body(begin, end) over [0, n) in two halves, the upper one on a second thread that is joined before returning (one
// thread below `minimum`). Each index belongs to one half and the halves do not depend on the timing, so a body that
// writes only its own elements gives the same result as a serial loop. A joined thread rather than OpenMP: the two
// cores are often shared with other processes, and a waiting thread then sleeps instead of spinning.
template <class Body>
void inTwoHalves(std::ptrdiff_t n, std::ptrdiff_t minimum, const Body& body) {
  if (n < minimum || std::thread::hardware_concurrency() < 2) {
    body(std::ptrdiff_t{0}, n);
    return;
  }
  const std::ptrdiff_t middle = n / 2;
  std::thread upper([&] { body(middle, n); });
  body(std::ptrdiff_t{0}, middle);
  upper.join();
}

}  // namespace conformesh::intrinsic
