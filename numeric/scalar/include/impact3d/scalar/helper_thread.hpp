// A thread kept for many tasks and handed one at a time (ParallelChunks's helpers, batch's writer): no
// thread is made per task, and a thread keeps its warm thread-local state (the CSV reader's cells and
// tree, the result pick, the JSON writer's reserve hint) from one task to the next.
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

#include "impact3d/scalar/thread_caches.hpp"

namespace impact3d {

class HelperThread {
 public:
  HelperThread() : thread_([this] { serve(); }) {}
  // A task still running is finished first: what it reads must outlive the helper.
  ~HelperThread() {
    {
      const std::lock_guard lock(mutex_);
      quit_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

  // The task started last must have been waited for.
  void start(std::function<void()> task) {
    {
      const std::lock_guard lock(mutex_);
      task_ = std::move(task);
      busy_ = true;
    }
    wake_.notify_one();
  }
  // Until the task started last is done (at once when there is none); what it threw is thrown here.
  void wait() {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return !busy_; });
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }

 private:
  void serve() {
    const ThreadCaches freed_at_exit;  // a 100-digit row leaves MPFR's caches in this thread
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return busy_ || quit_; });
      if (!busy_) return;
      std::function<void()> task = std::move(task_);
      lock.unlock();
      std::exception_ptr error;
      try {
        task();
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      error_ = error;
      busy_ = false;
      done_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::function<void()> task_;
  std::exception_ptr error_;
  bool busy_ = false, quit_ = false;
  std::thread thread_;  // last: it starts once the members above exist
};

}  // namespace impact3d
