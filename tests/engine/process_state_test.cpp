#include "engine/process_state.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace pdq {
namespace {

// Waits up to a few seconds for the kernel to show `pid` in `wanted`.
bool becomes(int pid, ProcessState wanted) {
  for (int i = 0; i < 500; ++i) {
    if (processState(pid) == wanted) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(ProcessState, TellsAliveStoppedAndGoneApart) {
  EXPECT_EQ(processState(static_cast<int>(getpid())), ProcessState::Alive);

  pid_t child = 0;
  char sleep[] = "sleep", seconds[] = "60";
  char* argv[] = {sleep, seconds, nullptr};
  ASSERT_EQ(posix_spawnp(&child, "sleep", nullptr, nullptr, argv, environ), 0);
  EXPECT_TRUE(becomes(child, ProcessState::Alive));
  ASSERT_EQ(kill(child, SIGSTOP), 0);
  EXPECT_TRUE(becomes(child, ProcessState::Stopped));
  ASSERT_EQ(kill(child, SIGCONT), 0);
  EXPECT_TRUE(becomes(child, ProcessState::Alive));
  // Killed but not yet reaped: a zombie is gone as far as a job is concerned.
  ASSERT_EQ(kill(child, SIGKILL), 0);
  EXPECT_TRUE(becomes(child, ProcessState::Gone));
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_EQ(processState(child), ProcessState::Gone);
}

}  // namespace
}  // namespace pdq
