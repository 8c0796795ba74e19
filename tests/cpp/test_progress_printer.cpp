// The progress shown on a stream (core/progress_printer.hpp), every event drawn (interval 0, no ticker): plain
// lines without control characters, the machine's "@progress"/"@running" lines, a terminal's status line redrawn
// in place and cleared before each finished stage's line; the status line's bar.
#include <gtest/gtest.h>
#include <unistd.h>

#include <sstream>
#include <string>

#include "core/progress_printer.hpp"

using namespace hexlayer;

namespace {

// A stage run as the pipeline reports it: start, two steps of four, finish; then a note about the run.
std::string shown(ProgressStyle style) {
  std::ostringstream out;
  {
    ProgressPrinter printer(out, style, 0, false);
    printer.show(progressStart("quad_mesh"));
    printer.show(progressAdvance("quad_mesh", 1, 4));
    printer.show(progressAdvance("quad_mesh", 2, 4));
    printer.show(progressFinish("quad_mesh", 1.5));
    printer.show(progressNote("", "solid 2 of 2"));
  }
  return out.str();
}

}  // namespace

TEST(ProgressPrinter, PlainLinesHaveNoControlCharacters) {
  EXPECT_EQ(
      shown(ProgressStyle::Plain),
      "hexlayer: quad_mesh: 1/4\nhexlayer: quad_mesh: 2/4\nhexlayer: quad_mesh: 1.50 s\nhexlayer: solid 2 of 2\n");
}

TEST(ProgressPrinter, MachineLinesForTheWorkbench) {
  EXPECT_EQ(shown(ProgressStyle::Machine),
            "@running quad_mesh\n@running quad_mesh 1 4\n@running quad_mesh 2 4\n@progress quad_mesh: 1.50 s\n"
            "@progress solid 2 of 2\n");
}

TEST(ProgressPrinter, TerminalRedrawsOneStatusLineAndClearsItBeforeALine) {
  const std::string s = shown(ProgressStyle::Terminal);
  const std::string clear = "\r\033[K";
  EXPECT_NE(s.find(clear + "hexlayer: quad_mesh  0.0 s"), std::string::npos) << "started: no bar yet";
  EXPECT_NE(s.find(clear + "hexlayer: quad_mesh [######..................]  25 %"), std::string::npos) << s;
  EXPECT_NE(s.find(clear + "hexlayer: quad_mesh [############............]  50 %"), std::string::npos) << s;
  EXPECT_NE(s.find(clear + "hexlayer: quad_mesh: 1.50 s\n"), std::string::npos) << "cleared, then the line";
  EXPECT_EQ(s.find('\n'), s.find("1.50 s\n") + 6) << "no line break before the stage finished";
  EXPECT_EQ(s.substr(s.size() - std::string("hexlayer: solid 2 of 2\n").size()), "hexlayer: solid 2 of 2\n")
      << "between stages no status line is drawn again";
}

TEST(ProgressPrinter, TickRedrawsTheRunningStageOnly) {
  std::ostringstream out;
  ProgressPrinter printer(out, ProgressStyle::Terminal, 0, false);
  printer.tick();
  EXPECT_EQ(out.str(), "") << "no stage running";
  printer.show(progressStart("wall_sides"));
  const std::size_t drawn = out.str().size();
  printer.tick();
  EXPECT_GT(out.str().size(), drawn);
  EXPECT_EQ(out.str().rfind("\r\033[Khexlayer: wall_sides  "), drawn);
}

TEST(ProgressPrinter, StatusLineBar) {
  EXPECT_EQ(statusLine("sweep", 0, 0, 12.34), "sweep  12.3 s");
  EXPECT_EQ(statusLine("sweep", 3, 4, 1), "sweep [##################......]  75 %  1.0 s");
  EXPECT_EQ(statusLine("sweep", 5, 4, 1), "sweep [########################] 100 %  1.0 s") << "clamped";
}

TEST(ProgressPrinter, StyleForAPipeIsPlain) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  EXPECT_EQ(progressStyleFor(false, fds[1]), ProgressStyle::Plain);
  EXPECT_EQ(progressStyleFor(true, fds[1]), ProgressStyle::Machine);
  close(fds[0]), close(fds[1]);
}
