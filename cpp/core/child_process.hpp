// Runs a piece of work in a forked child process, so that a crash or a hang of a third-party
// library (Gmsh's reparametrization can do both) becomes an error the caller can handle.
#pragma once
#include <chrono>
#include <functional>
#include <mutex>
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
class ForkServer;
struct StartedChild {
  int pid = -1;                  // -1: none (fork or pipe failed: `failure` says why)
  int fd = -1;                   // the pipe its result comes through
  ForkServer* server = nullptr;  // the server that forked it (it is the server's child), or null: this process's
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

// A small process forked before the mesher has grown, which forks the children on request: a child of it pays
// neither the fork of the large mesher process (its page tables, then its pages copied as the child writes them)
// nor, with `prepare` run once in the server (Gmsh's start-up), the library's start-up (a gap's Gmsh run on the
// L-bracket, from its start to its quads: 35 -> 27 ms, medians of 45 on one thread). The work crosses as a plain
// function (the server is a fork of this program: the same code at the same place) and its bytes. Gone (it failed to
// start, or died), children are forked from this process as startChildProcess's. One request at a time (a mutex); the
// server ends with this object or with the thread that made it.
class ForkServer {
 public:
  using Run = std::string (*)(const std::string& request);
  using Fallback = std::function<std::string(const std::function<std::string()>& run)>;
  // [in] prepare: run once in the server before its first child; null: nothing.
  explicit ForkServer(void (*prepare)() = nullptr);
  ~ForkServer();
  ForkServer(const ForkServer&) = delete;
  ForkServer& operator=(const ForkServer&) = delete;
  // Starts run(request) in a child of the server (of this process, with `fallback` around it, if the server is gone):
  // as startChildProcess, waited for or stopped by waitForChild and stopChild. [in] run, request, timeoutSeconds;
  // [in] fallback: how this process's child calls run (a Gmsh session opened round it).
  StartedChild start(Run run, const std::string& request, double timeoutSeconds, const Fallback& fallback);
  // Waits for the server's child pid to end. Returns its wait status (waitpid's); a killed one's if the server is gone.
  int exitStatus(int pid);

 private:
  bool exchange(const void* header, std::size_t size, const std::string& payload, int fd, int& reply);
  int socket_ = -1;  // to the server
  int pid_ = -1;     // the server
  std::mutex mutex_;
};

// run(request) in a child: the server's (ForkServer::start), or this process's (startChildProcess, `fallback` round
// it) if server is null. [in] server, run, request, timeoutSeconds, fallback. Returns the running child.
StartedChild startRun(ForkServer* server, ForkServer::Run run, const std::string& request, double timeoutSeconds,
                      const ForkServer::Fallback& fallback);

}  // namespace hexlayer
