// two_threads.h — splitting independent per-element work of the Ricci flow and the uniformization between two cores:
// one persistent helper thread. Private to the flow; touches only the data its callers' chunks write.
#pragma once

#include <cstddef>
#include <functional>

namespace conformesh::intrinsic {

// Below this many elements a loop runs on one thread: handing work to the second thread costs more than it saves.
constexpr std::ptrdiff_t kParallelMin = 20000;

// Runs chunk(0), …, chunk(count − 1), each exactly once, on the calling thread and on one persistent helper thread.
// Chunks are claimed one at a time; the caller waits only for chunks the helper has actually started. On a machine
// whose two cores are busy with other processes the helper may not run for a scheduling period; the caller then does
// every chunk itself, never slower than one thread (docs/ricci_flow.md §2, "Two cores elsewhere"). Results do not
// depend on which thread runs a chunk as long as chunks write disjoint data. Calls from several threads at once, or
// from inside a chunk, run serially.
// Throws: what a chunk threw — once every chunk already started has finished, the exception of the lowest-numbered
// chunk that threw, which is what the serial loop would throw; chunks not yet started when one throws are not run.
void runChunks(int count, const std::function<void(int)>& chunk);

// body(begin, end) over [0, n) in 8 fixed ranges shared by runChunks (one range below `minimum`): each index belongs to
// one range, so a body that writes only its own elements gives the same result as a serial loop.
template <class Body>
void onTwoCores(std::ptrdiff_t n, std::ptrdiff_t minimum, const Body& body) {
  if (n < minimum) {
    body(std::ptrdiff_t{0}, n);
    return;
  }
  constexpr int kChunks = 8;
  runChunks(kChunks, [&](int c) { body(n * c / kChunks, n * (c + 1) / kChunks); });
}

}  // namespace conformesh::intrinsic
