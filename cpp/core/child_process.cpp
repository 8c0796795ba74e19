#include "core/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <exception>
#include <iomanip>
#include <sstream>

namespace hexlayer {
namespace {

void writeAll(int fd, const std::string& bytes) {
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

// The child: first byte '1' and the output, or '0' and the error message.
[[noreturn]] void childMain(int fd, const std::function<std::string()>& work) {
  // A crash ends the child by its signal, whatever handler the parent installed (a sanitizer's, libFuzzer's,
  // FreeCAD's), so that the parent can name it.
  for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) signal(sig, SIG_DFL);
  // The library's own chatter (Gmsh's solver warnings) is not for the user: the result says it all.
  if (const int null = open("/dev/null", O_WRONLY); null >= 0) dup2(null, 1), dup2(null, 2), close(null);
  std::string message;
  try {
    message = "1" + work();
  } catch (const std::exception& e) {
    message = std::string("0") + e.what();
  } catch (...) {
    message = "0unknown error";
  }
  writeAll(fd, message);
  close(fd);
  _exit(0);
}

// Reads until the child closes the pipe or the deadline passes; false on time-out.
bool readAll(int fd, std::string& bytes, std::chrono::steady_clock::time_point deadline) {
  char buffer[1 << 16];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) return true;
    if (ready <= 0) continue;
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n <= 0) return true;
    bytes.append(buffer, static_cast<size_t>(n));
  }
}

}  // namespace

StartedChild startChildProcess(const std::function<std::string()>& work, double timeoutSeconds) {
  StartedChild child;
  child.timeoutSeconds = timeoutSeconds;
  int fds[2];
  if (pipe(fds) != 0) {
    child.failure = std::string("cannot create a pipe: ") + std::strerror(errno);
    return child;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]), close(fds[1]);
    child.failure = std::string("cannot fork: ") + std::strerror(errno);
    return child;
  }
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // a killed parent (Ctrl-C, a test's time-out) takes its Gmsh child along
    close(fds[0]);
    childMain(fds[1], work);
  }
  close(fds[1]);
  child.pid = pid, child.fd = fds[0];
  child.deadline = std::chrono::time_point_cast<std::chrono::steady_clock::duration>(
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds));
  return child;
}

void stopChild(StartedChild& child) {
  if (child.pid < 0) return;
  close(child.fd);
  kill(child.pid, SIGKILL);
  waitpid(child.pid, nullptr, 0);
  child.pid = -1, child.fd = -1;
}

ChildResult waitForChild(StartedChild& child) {
  ChildResult result;
  if (child.pid < 0) {
    result.failure = child.failure;
    return result;
  }
  std::string bytes;
  const bool finished = readAll(child.fd, bytes, child.deadline);
  close(child.fd);
  if (!finished) kill(child.pid, SIGKILL);
  int status = 0;
  waitpid(child.pid, &status, 0);
  child.pid = -1, child.fd = -1;
  const double timeoutSeconds = child.timeoutSeconds;
  if (!finished) {
    std::ostringstream after;  // whole seconds, or a test's budget below one
    if (timeoutSeconds >= 1)
      after << static_cast<long>(timeoutSeconds);
    else
      after << std::setprecision(2) << timeoutSeconds;
    result.failure = "timed out after " + after.str() + " s";
    result.timedOut = true;
  } else if (WIFSIGNALED(status)) {
    result.failure = std::string("crashed (") + strsignal(WTERMSIG(status)) + ")";
  } else if (bytes.empty()) {
    result.failure = "ended without a result";
  } else if (bytes[0] == '1') {
    result.ok = true;
    result.output = bytes.substr(1);
  } else {
    result.failure = bytes.substr(1);
    result.threw = true;
  }
  return result;
}

ChildResult runInChildProcess(const std::function<std::string()>& work, double timeoutSeconds) {
  StartedChild child = startChildProcess(work, timeoutSeconds);
  return waitForChild(child);
}

}  // namespace hexlayer
