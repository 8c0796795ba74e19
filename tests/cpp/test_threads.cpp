// OpenMP loops whose bodies may throw (core/threads.hpp ParallelErrors): the exception, OpenCASCADE's too, reaches
// the caller after the loop instead of terminating the process; the bodies that do not throw all run.
#include <gtest/gtest.h>

#include <Standard_NullObject.hxx>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/threads.hpp"

using namespace hexlayer;

namespace {

// A parallel loop over n items whose body throws `thrown` at item `bad`, marking the others done.
template <class Thrown>
void loopThrowingAt(long n, long bad, const Thrown& thrown, std::vector<char>& done) {
  ParallelErrors errors;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    errors.run([&] {
      if (i == bad) throw thrown;
      done[i] = 1;
    });
  errors.rethrow();
}

}  // namespace

TEST(ParallelErrors, OpenCascadeFailureReachesTheCallerAfterTheLoop) {
  std::vector<char> done(1000, 0);
  bool caught = false;
  try {
    loopThrowingAt(1000, 617, Standard_NullObject("no surface"), done);
  } catch (const Standard_Failure& e) {
    caught = true;
    EXPECT_STREQ(e.GetMessageString(), "no surface");
  }
  EXPECT_TRUE(caught);
  EXPECT_EQ(std::count(done.begin(), done.end(), 1), 999);
  EXPECT_EQ(done[617], 0);
}

TEST(ParallelErrors, StandardExceptionReachesTheCallerAndNoneMeansNoThrow) {
  std::vector<char> done(100, 0);
  EXPECT_THROW(loopThrowingAt(100, 0, std::runtime_error("first item"), done), std::runtime_error);
  std::vector<char> all(100, 0);
  EXPECT_NO_THROW(loopThrowingAt(100, -1, std::runtime_error("never"), all));
  EXPECT_EQ(std::count(all.begin(), all.end(), 1), 100);
}

// Jobs side by side (sideBySide), outside a parallel region and as tasks inside one (the quad stage's patch grids
// beside its maps, the patch grids' even and graded grids beside each other): every job runs once, a job's own
// sideBySide inside runs too, and the exception thrown is the first job's in their order, whichever threw first.
TEST(SideBySide, EveryJobRunsOnceAndTheFirstJobsExceptionIsThrown) {
  for (bool inRegion : {false, true}) {
    std::vector<int> runs(4, 0);
    auto jobs = [&] {
      sideBySide({[&] { ++runs[0]; },
                  [&] {
                    sideBySide({[&] { ++runs[1]; }, [&] { ++runs[2]; }});
                  },
                  [&] { ++runs[3]; }});
    };
    if (inRegion) {
#pragma omp parallel
#pragma omp single
      jobs();
    } else {
      jobs();
    }
    EXPECT_EQ(runs, std::vector<int>(4, 1)) << (inRegion ? "inside a parallel region" : "outside");
  }
  std::vector<char> done(3, 0);
  try {
    sideBySide({[&] { done[0] = 1; },
                [&] {
                  done[1] = 1;
                  throw std::runtime_error("second");
                },
                [&] {
                  done[2] = 1;
                  throw Standard_NullObject("third");
                }});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "second");
  }
  EXPECT_EQ(done, std::vector<char>(3, 1));
}

// joinedInOrder: each item's vector joined in the items' order whatever thread made it (item i gives i copies of i);
// an item's exception reaches the caller.
TEST(JoinedInOrder, ItemsJoinInTheirOrderAndAnExceptionReachesTheCaller) {
  const std::vector<int> all = joinedInOrder(50, [](int i) { return std::vector<int>(i, i); });
  std::vector<int> expected;
  for (int i = 0; i < 50; ++i) expected.insert(expected.end(), i, i);
  EXPECT_EQ(all, expected);
  EXPECT_TRUE(joinedInOrder(0, [](int i) { return std::vector<int>{i}; }).empty());
  EXPECT_THROW(joinedInOrder(20,
                             [](int i) {
                               if (i == 13) throw Standard_NullObject("thirteen");
                               return std::vector<int>{i};
                             }),
               Standard_Failure);
}
