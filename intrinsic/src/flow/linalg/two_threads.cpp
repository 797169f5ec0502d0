// two_threads.cpp — the helper thread of runChunks (two_threads.h).
#include "flow/linalg/two_threads.h"

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace conformesh::intrinsic {

namespace {

// One helper thread for the process, started at the first parallel loop and joined at exit. Under `mutex_`: the
// current loop, its next unclaimed chunk, how many chunks the helper is running, and the lowest chunk that threw.
//
// A chunk that throws (on either thread) stops further chunks from being claimed; the chunks already claimed finish,
// and run() rethrows the exception of the lowest chunk that threw. Chunks are claimed in index order, so every chunk
// below a thrower has been claimed: the exception rethrown is the one a serial loop would have thrown first. Without
// the catch, an exception escaping the helper thread would call std::terminate.
class Helper {
 public:
  Helper() : thread_([this] { work(); }) {}
  ~Helper() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

  void run(int count, const std::function<void(int)>& chunk) {
    std::unique_lock<std::mutex> lock(mutex_);
    chunk_ = &chunk;
    count_ = count;
    next_ = 0;
    failedChunk_ = count;
    failure_ = nullptr;
    lock.unlock();
    wake_.notify_one();
    lock.lock();
    while (next_ < count_) {
      const int c = next_++;
      lock.unlock();
      std::exception_ptr e = runOne(chunk, c);
      lock.lock();
      if (e) recordFailure(c, e);
    }
    idle_.wait(lock, [this] { return running_ == 0; });
    chunk_ = nullptr;
    if (failure_) {
      std::exception_ptr e = failure_;
      failure_ = nullptr;
      std::rethrow_exception(e);
    }
  }

 private:
  void work() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      wake_.wait(lock, [this] { return stop_ || (chunk_ != nullptr && next_ < count_); });
      if (stop_) return;
      while (chunk_ != nullptr && next_ < count_) {
        const int c = next_++;
        const std::function<void(int)>* chunk = chunk_;
        ++running_;
        lock.unlock();
        std::exception_ptr e = runOne(*chunk, c);
        lock.lock();
        if (e) recordFailure(c, e);
        if (--running_ == 0) idle_.notify_one();
      }
    }
  }

  static std::exception_ptr runOne(const std::function<void(int)>& chunk, int c) {
    try {
      chunk(c);
    } catch (...) {
      return std::current_exception();
    }
    return nullptr;
  }

  // Under mutex_: keeps the lowest thrower's exception and stops the claiming of further chunks.
  void recordFailure(int c, std::exception_ptr e) {
    if (c < failedChunk_) {
      failedChunk_ = c;
      failure_ = std::move(e);
    }
    next_ = count_;
  }

  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  const std::function<void(int)>* chunk_ = nullptr;
  int count_ = 0, next_ = 0, running_ = 0, failedChunk_ = 0;
  std::exception_ptr failure_;
  bool stop_ = false;
  std::thread thread_;  // last: started once the state above exists
};

std::atomic<bool> busy{false};

}  // namespace

void runChunks(int count, const std::function<void(int)>& chunk) {
  bool expected = false;
  if (count < 2 || std::thread::hardware_concurrency() < 2 || !busy.compare_exchange_strong(expected, true)) {
    for (int c = 0; c < count; ++c) chunk(c);
    return;
  }
  static Helper helper;
  struct Release {  // `busy` is released however run() leaves, by return or by a chunk's exception
    ~Release() { busy.store(false); }
  } release;
  helper.run(count, chunk);
}

}  // namespace conformesh::intrinsic
