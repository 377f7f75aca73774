#pragma once
// A second thread for work cut in two (the supernodal factorisation and solves of the
// quasi-static solver's stiffness): it sleeps between jobs, and may run on any core of the
// node (MPI binds each rank to one core; the other ranks sleep while rank 0 factorises and
// solves).
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace pdq {

class HelperThread {
 public:
  HelperThread();
  ~HelperThread();
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;
  // Runs `other` on the helper and `one` on the calling thread; returns when both are done,
  // rethrowing what either threw (the calling thread's first).
  void together(const std::function<void()>& one, const std::function<void()>& other);

 private:
  void loop();
  std::mutex m_;
  std::condition_variable cv_;
  const std::function<void()>* job_ = nullptr;
  std::exception_ptr failed_;  // what the helper's last job threw
  bool quit_ = false;
  std::thread thread_;  // last: started once the rest is made
};

// `one` then `other` without a helper, at once with one.
inline void inTwo(HelperThread* helper, const std::function<void()>& one,
                  const std::function<void()>& other) {
  if (!helper) {
    one();
    other();
  } else {
    helper->together(one, other);
  }
}

}  // namespace pdq
