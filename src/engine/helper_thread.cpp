#include "engine/helper_thread.hpp"

#include <pthread.h>
#include <sched.h>
#include <unistd.h>

namespace pdq {

HelperThread::HelperThread() : thread_([this] { loop(); }) {
  cpu_set_t all;
  CPU_ZERO(&all);
  const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
  for (long c = 0; c < cpus && c < CPU_SETSIZE; ++c) CPU_SET(c, &all);
  pthread_setaffinity_np(thread_.native_handle(), sizeof all, &all);  // best effort
}

HelperThread::~HelperThread() {
  {
    std::lock_guard<std::mutex> lock(m_);
    quit_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void HelperThread::together(const std::function<void()>& one, const std::function<void()>& other) {
  {
    std::lock_guard<std::mutex> lock(m_);
    job_ = &other;
    failed_ = nullptr;
  }
  cv_.notify_all();
  // The helper is waited for whatever `one` does: `other` may refer to the caller's state.
  std::exception_ptr mine;
  try {
    one();
  } catch (...) {
    mine = std::current_exception();
  }
  std::unique_lock<std::mutex> lock(m_);
  cv_.wait(lock, [this] { return job_ == nullptr; });
  if (mine) std::rethrow_exception(mine);
  if (failed_) std::rethrow_exception(failed_);
}

void HelperThread::loop() {
  std::unique_lock<std::mutex> lock(m_);
  for (;;) {
    cv_.wait(lock, [this] { return quit_ || job_; });
    if (quit_) return;
    const std::function<void()>* job = job_;
    lock.unlock();
    std::exception_ptr failed;
    try {
      (*job)();
    } catch (...) {
      failed = std::current_exception();
    }
    lock.lock();
    failed_ = failed;
    job_ = nullptr;
    cv_.notify_all();
  }
}

}  // namespace pdq
