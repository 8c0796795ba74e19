// Progress events (core/progress.hpp): each kind as its line, which kinds are a log's lines, and reportProgress
// with and without a callback.
#include <gtest/gtest.h>

#include <vector>

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
