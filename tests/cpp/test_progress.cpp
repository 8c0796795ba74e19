// Progress events (core/progress.hpp): each kind as its line, which kinds are a log's lines, reportProgress
// with and without a callback, and ProgressRelay handing a thread's events to the thread waiting for it.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "core/progress.hpp"

using namespace hexlayer;

TEST(Progress, EachKindAsItsLine) {
  EXPECT_EQ(progressStart("quad_mesh").line(), "quad_mesh");
  EXPECT_EQ(progressAdvance("quad_mesh", 3, 39).line(), "quad_mesh: 3/39");
  EXPECT_EQ(progressFinish("wall_sides", 1.234).line(), "wall_sides: 1.23 s");
  EXPECT_EQ(progressNote("quad_mesh", "Gmsh timed out").line(), "quad_mesh: Gmsh timed out");
  EXPECT_EQ(progressNote("", "solid 1 of 2").line(), "solid 1 of 2") << "a note about the run has no stage";
}

TEST(Progress, OnlyFinishedStagesAndNotesAreLines) {
  EXPECT_FALSE(progressStart("tets").isLine());
  EXPECT_FALSE(progressAdvance("tets", 1, 2).isLine());
  EXPECT_TRUE(progressFinish("tets", 0.5).isLine());
  EXPECT_TRUE(progressNote("tets", "x").isLine());
}

TEST(Progress, ReportCallsTheCallbackIfThereIsOne) {
  std::vector<std::string> lines;
  reportProgress({}, progressStart("geometry"));  // no callback: nothing happens
  reportProgress([&](const Progress& p) { lines.push_back(p.line()); }, progressFinish("geometry", 0.01));
  EXPECT_EQ(lines, std::vector<std::string>{"geometry: 0.01 s"});
}

// A worker thread's events reach the callback on the waiting thread, in their order: those queued so far without
// waiting (forward(false)), then the rest until the worker closes the relay.
TEST(ProgressRelay, HandsAThreadsEventsOnToTheWaitingThreadInOrder) {
  std::vector<std::string> lines;
  std::vector<std::thread::id> threads;
  ProgressRelay relay(
      [&](const Progress& p) { lines.push_back(p.line()), threads.push_back(std::this_thread::get_id()); });
  const ProgressCallback report = relay.callback();
  std::atomic<bool> firstQueued{false}, goOn{false};
  std::thread worker([&] {
    report(progressNote("", "piece 1 of 2"));
    firstQueued = true;
    while (!goOn) std::this_thread::yield();
    for (int k = 1; k <= 50; ++k) report(progressAdvance("tets", k, 50));
    relay.close();
  });
  while (!firstQueued) std::this_thread::yield();
  relay.forward(false);  // the one queued so far; returns without waiting for more
  EXPECT_EQ(lines, std::vector<std::string>{"piece 1 of 2"});
  goOn = true;
  relay.forward(true);
  worker.join();
  ASSERT_EQ(lines.size(), 51u);
  for (int k = 1; k <= 50; ++k) EXPECT_EQ(lines[k], "tets: " + std::to_string(k) + "/50");
  for (const auto& id : threads) EXPECT_EQ(id, std::this_thread::get_id());
}

// A callback that throws (a cancel) leaves forward() with its exception and stops the worker at its next event;
// stop() does too.
TEST(ProgressRelay, ACallbacksExceptionStopsTheWorker) {
  ProgressRelay relay([](const Progress&) { throw std::runtime_error("cancelled"); });
  const ProgressCallback report = relay.callback();
  report(progressStart("bubbles"));
  EXPECT_THROW(relay.forward(true), std::runtime_error);
  EXPECT_THROW(report(progressFinish("bubbles", 0.1)), Error) << "the worker stops at its next event";
  ProgressRelay stopped({});
  const ProgressCallback other = stopped.callback();
  other(progressStart("tets"));
  stopped.stop();
  EXPECT_THROW(other(progressFinish("tets", 0.1)), Error);
  stopped.close();
  EXPECT_NO_THROW(stopped.forward(true)) << "what was queued before stop is handed on";
}
