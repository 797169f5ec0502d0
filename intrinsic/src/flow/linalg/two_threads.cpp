// two_threads.cpp — the helper thread of runChunks (two_threads.h).
#include "flow/linalg/two_threads.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace conformesh::intrinsic {

namespace {

// One helper thread for the process, started at the first parallel loop and joined at exit. Under `mutex_`: the
// current loop, its next unclaimed chunk and how many chunks the helper is running.
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
    lock.unlock();
    wake_.notify_one();
    lock.lock();
    while (next_ < count_) {
      const int c = next_++;
      lock.unlock();
      chunk(c);
      lock.lock();
    }
    idle_.wait(lock, [this] { return running_ == 0; });
    chunk_ = nullptr;
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
        (*chunk)(c);
        lock.lock();
        if (--running_ == 0) idle_.notify_one();
      }
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  const std::function<void(int)>* chunk_ = nullptr;
  int count_ = 0, next_ = 0, running_ = 0;
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
  helper.run(count, chunk);
  busy.store(false);
}

}  // namespace conformesh::intrinsic
