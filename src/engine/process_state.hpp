#pragma once
// What the operating system says of a process on this machine, from /proc/<pid>/stat:
// the watchdog uses it to tell a rank that is stopped or gone from one that is only slow
// (a machine so loaded that the rank's threads wait seconds for a core).
namespace pdq {

enum class ProcessState {
  Alive,    // running, runnable, sleeping or in uninterruptible I/O
  Stopped,  // SIGSTOP, SIGTSTP or a debugger holds it
  Gone,     // ended: no such process, or a zombie not yet reaped
  Unknown,  // this machine has no /proc to ask
};

ProcessState processState(int pid);

}  // namespace pdq
