// Runs a piece of work in a forked child process, so that a crash or a hang of a third-party
// library (Gmsh's reparametrization can do both) becomes an error the caller can handle.
#pragma once
#include <chrono>
#include <functional>
#include <string>

namespace hexlayer {

struct ChildResult {
  bool ok = false;
  std::string output;     // the bytes the work returned, if ok
  std::string failure;    // why not: the work's exception message, the signal that ended it, or the time-out
  bool threw = false;     // the failure is the message of an exception the work threw
  bool timedOut = false;  // the work ran out of its time and was killed
};

// Calls work() in a child process and returns its bytes. The child ends with _exit, so nothing of
// it leaks into this process; it is killed after timeoutSeconds (a failure with timedOut set).
// [in] work: runs in the child; [in] timeoutSeconds: its time budget (> 0). Returns the result or why not.
ChildResult runInChildProcess(const std::function<std::string()>& work, double timeoutSeconds);

// runInChildProcess in two steps, so that two children can run side by side: the child started, then its result
// waited for (or the child killed, if its result is no longer wanted). A started child must be waited for or stopped.
struct StartedChild {
  int pid = -1;  // -1: none (fork or pipe failed: `failure` says why)
  int fd = -1;   // the pipe its result comes through
  double timeoutSeconds = 0;
  std::chrono::steady_clock::time_point deadline;
  std::string failure;
};
// [in] work, timeoutSeconds: as runInChildProcess. Returns the running child.
StartedChild startChildProcess(const std::function<std::string()>& work, double timeoutSeconds);
// [in,out] child: waited for and closed. Returns its result, as runInChildProcess.
ChildResult waitForChild(StartedChild& child);
// [in,out] child: killed and closed.
void stopChild(StartedChild& child);

}  // namespace hexlayer
