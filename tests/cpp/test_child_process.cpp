// core/child_process.hpp: work in a forked child; its bytes, its exception, its crash or its hang as a failure.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/child_process.hpp"

using namespace hexlayer;

// The work's bytes come back; its exception, a crash (SIGSEGV by raise) and a hang become failures naming what
// happened, and this process goes on.
TEST(ChildProcess, BytesExceptionCrashAndHang) {
  const ChildResult fine = runInChildProcess([] { return std::string("hex\0layer", 9); }, 10);
  EXPECT_TRUE(fine.ok);
  EXPECT_EQ(fine.output, std::string("hex\0layer", 9));

  const ChildResult threw = runInChildProcess([]() -> std::string { throw std::runtime_error("no solid in it"); }, 10);
  EXPECT_FALSE(threw.ok);
  EXPECT_TRUE(threw.threw);
  EXPECT_NE(threw.failure.find("no solid in it"), std::string::npos) << threw.failure;

  const ChildResult crashed = runInChildProcess(
      []() -> std::string {
        std::raise(SIGSEGV);
        return "never";
      },
      10);
  EXPECT_FALSE(crashed.ok);
  EXPECT_FALSE(crashed.threw);
  EXPECT_FALSE(crashed.failure.empty());

  const ChildResult hung = runInChildProcess(
      []() -> std::string {
        std::this_thread::sleep_for(std::chrono::seconds(30));
        return "late";
      },
      0.5);
  EXPECT_FALSE(hung.ok);
  EXPECT_FALSE(hung.failure.empty());
}

// Two children side by side (the Gmsh tries run so): each result comes back whole through its own pipe, a large one
// too (the second child waits on its full pipe until it is read), and a child no longer wanted is stopped.
TEST(ChildProcess, StartedChildrenSideBySide) {
  const std::string big(1 << 20, 'q');  // far beyond a pipe's buffer
  StartedChild first = startChildProcess([] { return std::string("first"); }, 10);
  StartedChild second = startChildProcess([&] { return big; }, 10);
  StartedChild unwanted = startChildProcess(
      []() -> std::string {
        std::this_thread::sleep_for(std::chrono::seconds(30));
        return "late";
      },
      60);
  ASSERT_GT(first.pid, 0);
  ASSERT_GT(second.pid, 0);
  ASSERT_GT(unwanted.pid, 0);
  const ChildResult a = waitForChild(first);
  const ChildResult b = waitForChild(second);
  EXPECT_TRUE(a.ok);
  EXPECT_EQ(a.output, "first");
  EXPECT_TRUE(b.ok);
  EXPECT_EQ(b.output, big);
  EXPECT_EQ(first.pid, -1);
  stopChild(unwanted);
  EXPECT_EQ(unwanted.pid, -1);
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1) << "no child left";
}

namespace {

int prepared = 0;  // set in the fork server only (its `prepare`): a run that sees it ran in the server's child
void prepare() { prepared = 42; }
void prepareFails() { throw std::runtime_error("no Gmsh"); }

std::string echo(const std::string& request) { return std::to_string(prepared) + ":" + request; }
std::string fail(const std::string& request) { throw std::runtime_error("refused " + request); }
std::string crash(const std::string&) {
  std::raise(SIGSEGV);
  return "never";
}
std::string hang(const std::string&) {
  std::this_thread::sleep_for(std::chrono::seconds(30));
  return "late";
}

std::string marked(const std::function<std::string()>& run) { return "here " + run(); }

}  // namespace

// The fork server's children run plain functions on the request's bytes, after the server's preparation (not this
// process's): a large request and result whole, side by side, a child stopped; an exception, a crash (its signal
// relayed by the server) and a hang become the failures runInChildProcess gives; no child left behind.
TEST(ChildProcess, ForkServerRunsPlainFunctionsInItsChildren) {
  {
    ForkServer server(&prepare);
    const std::string big(1 << 20, 'q');
    StartedChild first = server.start(&echo, "hex", 10, marked);
    StartedChild second = server.start(&echo, big, 10, marked);
    StartedChild unwanted = server.start(&hang, "", 60, marked);
    EXPECT_EQ(first.server, &server);
    const ChildResult a = waitForChild(first), b = waitForChild(second);
    EXPECT_TRUE(a.ok);
    EXPECT_EQ(a.output, "42:hex");
    EXPECT_TRUE(b.ok);
    EXPECT_EQ(b.output, "42:" + big);
    stopChild(unwanted);
    EXPECT_EQ(unwanted.pid, -1);
    StartedChild threw = server.start(&fail, "it", 10, marked);
    const ChildResult t = waitForChild(threw);
    EXPECT_TRUE(t.threw);
    EXPECT_EQ(t.failure, "refused it");
    StartedChild crashed = server.start(&crash, "", 10, marked);
    const ChildResult c = waitForChild(crashed);
    EXPECT_FALSE(c.ok);
    EXPECT_NE(c.failure.find("crashed"), std::string::npos) << c.failure;
    StartedChild hung = server.start(&hang, "", 0.5, marked);
    const ChildResult h = waitForChild(hung);
    EXPECT_TRUE(h.timedOut) << h.failure;
  }
  EXPECT_EQ(prepared, 0);
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1) << "no child left";
}

// A server whose preparation fails ends: its runs are this process's children, `fallback` round them; so are the
// runs started without a server.
TEST(ChildProcess, RunsWithoutAForkServerAreThisProcesssChildren) {
  ForkServer failed(&prepareFails);
  StartedChild child = failed.start(&echo, "hex", 10, marked);
  EXPECT_EQ(child.server, nullptr);
  const ChildResult a = waitForChild(child);
  EXPECT_TRUE(a.ok);
  EXPECT_EQ(a.output, "here 0:hex");
  StartedChild alone = startRun(nullptr, &echo, "layer", 10, marked);
  const ChildResult b = waitForChild(alone);
  EXPECT_EQ(b.output, "here 0:layer");
}
