#include "core/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
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
  if (child.server)
    child.server->exitStatus(child.pid);
  else
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
  if (child.server)
    status = child.server->exitStatus(child.pid);
  else
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

namespace {

// A request to the fork server: start `run` on the `size` bytes that follow (the child's result pipe passed along),
// or wait for child `pid`.
struct Request {
  enum Kind : int { Start, Wait } kind = Start;
  int pid = -1;
  ForkServer::Run run = nullptr;
  std::uint64_t size = 0;
};

bool readExactly(int fd, void* to, std::size_t size) {
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = read(fd, static_cast<char*>(to) + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Sends the bytes, the descriptor fd (>= 0) along with the first of them.
bool sendWithFd(int socket, const void* bytes, std::size_t size, int fd) {
  iovec io{const_cast<void*>(bytes), size};
  msghdr m{};
  m.msg_iov = &io, m.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  if (fd >= 0) {
    m.msg_control = control, m.msg_controllen = sizeof control;
    cmsghdr* c = CMSG_FIRSTHDR(&m);
    c->cmsg_level = SOL_SOCKET, c->cmsg_type = SCM_RIGHTS, c->cmsg_len = CMSG_LEN(sizeof(int));
    std::memcpy(CMSG_DATA(c), &fd, sizeof(int));
  }
  ssize_t n;
  do n = sendmsg(socket, &m, MSG_NOSIGNAL);
  while (n < 0 && errno == EINTR);
  if (n < 0) return false;
  const std::size_t sent = static_cast<std::size_t>(n);
  for (std::size_t done = sent; done < size;) {  // the rest, if the socket took part of it
    const ssize_t more = send(socket, static_cast<const char*>(bytes) + done, size - done, MSG_NOSIGNAL);
    if (more < 0 && errno == EINTR) continue;
    if (more <= 0) return false;
    done += static_cast<std::size_t>(more);
  }
  return true;
}

// Receives a request's header and the descriptor sent with it (-1 if none).
bool receiveWithFd(int socket, Request& r, int& fd) {
  iovec io{&r, sizeof r};
  msghdr m{};
  m.msg_iov = &io, m.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  m.msg_control = control, m.msg_controllen = sizeof control;
  ssize_t n;
  do n = recvmsg(socket, &m, 0);
  while (n < 0 && errno == EINTR);
  if (n <= 0) return false;
  fd = -1;
  if (cmsghdr* c = CMSG_FIRSTHDR(&m); c && c->cmsg_type == SCM_RIGHTS) std::memcpy(&fd, CMSG_DATA(c), sizeof(int));
  return static_cast<std::size_t>(n) == sizeof r ||
         readExactly(socket, reinterpret_cast<char*>(&r) + n, sizeof r - static_cast<std::size_t>(n));
}

// The server: prepares, then forks a child per Start request (its reply the child's pid, or -1) and waits for a child
// per Wait request (its reply the wait status); ends when the socket closes.
[[noreturn]] void serverMain(int socket, void (*prepare)()) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // the mesher killed (Ctrl-C, a test's time-out) takes its server along
  if (const int null = open("/dev/null", O_WRONLY); null >= 0) dup2(null, 1), dup2(null, 2), close(null);
  try {
    if (prepare) prepare();
  } catch (...) {
    _exit(1);  // the mesher forks its own children then
  }
  for (;;) {
    Request r;
    int fd = -1;
    if (!receiveWithFd(socket, r, fd)) _exit(0);
    int reply = -1;
    if (r.kind == Request::Start) {
      std::string request(r.size, '\0');
      if (readExactly(socket, request.data(), request.size()) && fd >= 0) {
        const pid_t pid = fork();
        if (pid == 0) {
          close(socket);
          prctl(PR_SET_PDEATHSIG, SIGKILL);
          childMain(fd, [&] { return r.run(request); });
        }
        reply = pid;
      }
      if (fd >= 0) close(fd);
    } else {
      waitpid(r.pid, &reply, 0);
    }
    if (write(socket, &reply, sizeof reply) != sizeof reply) _exit(0);
  }
}

}  // namespace

ForkServer::ForkServer(void (*prepare)()) {
  int pair[2];
  if (socketpair(AF_UNIX, SOCK_STREAM, 0, pair) != 0) return;
  const pid_t pid = fork();
  if (pid < 0) {
    close(pair[0]), close(pair[1]);
    return;
  }
  if (pid == 0) {
    close(pair[0]);
    serverMain(pair[1], prepare);
  }
  close(pair[1]);
  socket_ = pair[0], pid_ = pid;
}

ForkServer::~ForkServer() {
  if (pid_ < 0) return;
  close(socket_);
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
}

bool ForkServer::exchange(const void* header, std::size_t size, const std::string& payload, int fd, int& reply) {
  if (pid_ < 0) return false;
  const bool done = sendWithFd(socket_, header, size, fd) &&
                    (payload.empty() || sendWithFd(socket_, payload.data(), payload.size(), -1)) &&
                    readExactly(socket_, &reply, sizeof reply);
  if (!done) {  // the server is gone: its children are this process's to fork from now on
    close(socket_), kill(pid_, SIGKILL), waitpid(pid_, nullptr, 0);
    socket_ = pid_ = -1;
  }
  return done;
}

StartedChild ForkServer::start(Run run, const std::string& request, double timeoutSeconds, const Fallback& fallback) {
  int fds[2];
  if (pipe(fds) == 0) {
    const std::lock_guard<std::mutex> lock(mutex_);
    Request r;
    r.kind = Request::Start, r.run = run, r.size = request.size();
    int pid = -1;
    const bool sent = exchange(&r, sizeof r, request, fds[1], pid);
    close(fds[1]);
    if (sent && pid > 0) {
      StartedChild child;
      child.pid = pid, child.fd = fds[0], child.server = this, child.timeoutSeconds = timeoutSeconds;
      child.deadline = std::chrono::time_point_cast<std::chrono::steady_clock::duration>(
          std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds));
      return child;
    }
    close(fds[0]);
  }
  return startRun(nullptr, run, request, timeoutSeconds, fallback);
}

StartedChild startRun(ForkServer* server, ForkServer::Run run, const std::string& request, double timeoutSeconds,
                      const ForkServer::Fallback& fallback) {
  if (server) return server->start(run, request, timeoutSeconds, fallback);
  return startChildProcess([&] { return fallback([&] { return run(request); }); }, timeoutSeconds);
}

int ForkServer::exitStatus(int pid) {
  const std::lock_guard<std::mutex> lock(mutex_);
  Request r;
  r.kind = Request::Wait, r.pid = pid;
  int status = 0;
  if (!exchange(&r, sizeof r, {}, -1, status)) status = SIGKILL;  // as WIFSIGNALED reads a killed child's
  return status;
}

ChildResult runInChildProcess(const std::function<std::string()>& work, double timeoutSeconds) {
  StartedChild child = startChildProcess(work, timeoutSeconds);
  return waitForChild(child);
}

}  // namespace hexlayer
