#include "quadmesh/chordal_patches.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <set>

#include "core/union_find.hpp"

namespace hexlayer {
namespace {

struct Triangles {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
};

// An nx x ny grid of unit cells, each split into two triangles, its node (i, j) placed at at(i, j), times scale.
Triangles grid(int nx, int ny, const std::function<Vec3(double, double)>& at, double scale = 1) {
  Triangles t;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) t.points.push_back(scale * at(i, j));
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      t.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return t;
}

// A U-channel of three flat sheets 10 wide with sharp 90-degree bends, 8 long.
Vec3 channel(double x, double y) {
  if (x <= 10) return {0, y, 10 - x};
  if (x <= 20) return {x - 10, y, 0};
  return {10, y, x - 20};
}

// Whether every patch is one piece (triangles joined across edges).
bool patchesConnected(const Triangles& t, const std::vector<int>& patch) {
  UnionFind pieces(t.triangles.size());
  std::map<std::pair<int, int>, int> first;
  for (int k = 0; k < static_cast<int>(t.triangles.size()); ++k)
    for (int j = 0; j < 3; ++j) {
      const int a = t.triangles[k][j], b = t.triangles[k][(j + 1) % 3];
      const auto [it, added] = first.emplace(std::minmax(a, b), k);
      if (!added && patch[it->second] == patch[k]) pieces.unite(it->second, k);
    }
  std::map<int, int> root;  // patch -> the root of its pieces
  for (int k = 0; k < static_cast<int>(t.triangles.size()); ++k)
    if (const auto [it, added] = root.emplace(patch[k], pieces.find(k)); !added && it->second != pieces.find(k))
      return false;
  return true;
}

TEST(ChordalPatches, AChannelsSheetsBetweenItsSharpBends) {
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const Triangles t = grid(30, 8, channel, scale);
    const std::vector<int> patch = chordalPatches(t.points, t.triangles, 60);
    ASSERT_EQ(patch.size(), t.triangles.size());
    EXPECT_EQ(std::set<int>(patch.begin(), patch.end()).size(), 3u) << "scale " << scale;
    for (std::size_t k = 0; k < t.triangles.size(); ++k) {  // each cell's triangles in its own sheet's patch
      const int cell = static_cast<int>(k / 2) % 30;
      EXPECT_EQ(patch[k], cell / 10) << "triangle " << k << ", scale " << scale;
    }
    EXPECT_EQ(pinchedPatchVertices(t.triangles, patch), 0u);
  }
}

TEST(ChordalPatches, ARoundBendCutWithinTheFeatureAngle) {
  // A half cylinder of radius 10, 24 cells round (7.5 degrees each): no edge turns 60 degrees, but no patch may
  // span more than 60 degrees of normals.
  const auto half = [](double x, double y) {
    const double a = M_PI * x / 24;
    return Vec3(10 * std::cos(a), y, 10 * std::sin(a));
  };
  const Triangles t = grid(24, 6, half);
  const std::vector<int> patch = chordalPatches(t.points, t.triangles, 60);
  const int patches = static_cast<int>(std::set<int>(patch.begin(), patch.end()).size());
  EXPECT_GE(patches, 3);
  EXPECT_LE(patches, 5);
  std::map<int, std::pair<double, double>> span;  // patch -> angles of its cells, first and last
  for (std::size_t k = 0; k < t.triangles.size(); ++k) {
    const double angle = 7.5 * ((k / 2) % 24);
    auto [it, added] = span.emplace(patch[k], std::pair{angle, angle});
    it->second.first = std::min(it->second.first, angle), it->second.second = std::max(it->second.second, angle);
  }
  for (const auto& [p, s] : span) EXPECT_LE(s.second - s.first, 60.0) << "patch " << p;
  EXPECT_TRUE(patchesConnected(t, patch));
  EXPECT_EQ(pinchedPatchVertices(t.triangles, patch), 0u);
}

TEST(ChordalPatches, NoPatchMeetsItselfAtAVertexOnANoisySheet) {
  // A bumpy sheet with noise, cut at 15 degrees: many small patches grown along jagged lines, which left as grown
  // touch themselves at vertices; none does once cleaned, every patch is one piece, at any scale the same.
  std::mt19937 random(7);
  std::vector<double> noise(41 * 41);
  for (double& n : noise) n = std::uniform_real_distribution<double>(-0.08, 0.08)(random);
  const auto bumpy = [&](double x, double y) {
    return Vec3(x, y, std::sin(0.5 * x) * std::cos(0.4 * y) + noise[static_cast<int>(y) * 41 + static_cast<int>(x)]);
  };
  std::vector<int> first;
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const Triangles t = grid(40, 40, bumpy, scale);
    const std::vector<int> patch = chordalPatches(t.points, t.triangles, 15);
    EXPECT_GT(std::set<int>(patch.begin(), patch.end()).size(), 10u);
    EXPECT_EQ(pinchedPatchVertices(t.triangles, patch), 0u) << "scale " << scale;
    EXPECT_TRUE(patchesConnected(t, patch));
    if (first.empty()) first = patch;
    EXPECT_EQ(patch, first) << "scale " << scale;
  }
}

TEST(ChordalPatches, ABendsNarrowStripsGoToTheFacesBesideThem) {
  // A U-channel (sheets 10 cells wide, 8 long) bent through 3 cells at each bend, at 20, 44 and 70 degrees (110, 136,
  // 160 at the other). Cut at 40 degrees, each bend's last two cells (44 and 70, 136 and 160) are a strip of their own
  // two cells wide, which chordalPatches keeps. facePatches gives it away a row at a time, each cell to the face of
  // its neighbour with the nearest normal among those already given: 44 to the first wall (beside its 20), 70 to the
  // floor, 136 to the floor (beside its 110), 160 to the far wall: three faces, at any scale.
  const std::vector<double> turn = {0,  0,  0,  0,  0,   0,   0,   0,   0,   0,   20,  44,  70,  90,  90,  90,  90, 90,
                                    90, 90, 90, 90, 110, 136, 160, 180, 180, 180, 180, 180, 180, 180, 180, 180, 180};
  std::vector<Vec3> profile{Vec3(0, 0, 10)};
  for (double degrees : turn) {
    const double a = degrees * M_PI / 180;
    profile.push_back(profile.back() + Vec3(std::sin(a), 0, -std::cos(a)));
  }
  const auto bent = [&](double x, double y) {
    return Vec3(profile[static_cast<int>(x)].x(), y, profile[static_cast<int>(x)].z());
  };
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const Triangles t = grid(static_cast<int>(turn.size()), 8, bent, scale);
    const std::vector<int> cut = chordalPatches(t.points, t.triangles, 40);
    EXPECT_GT(std::set<int>(cut.begin(), cut.end()).size(), 3u);  // the strips, patches of their own
    const std::vector<int> patch = facePatches(t.points, t.triangles, 40, 2 * scale);
    EXPECT_EQ(std::set<int>(patch.begin(), patch.end()).size(), 3u) << "scale " << scale;
    for (std::size_t k = 0; k < t.triangles.size(); ++k) {
      const double degrees = turn[(k / 2) % turn.size()];
      const int face = degrees <= 44 ? 0 : degrees <= 136 ? 1 : 2;
      EXPECT_EQ(patch[k], patch[face == 0 ? 0 : face == 1 ? 30 : 60]) << "cell at " << degrees << " degrees";
    }
    EXPECT_TRUE(patchesConnected(t, patch));
  }
}

// An L of two sheets 10 cells wide joined by a round of 8 cells (7 .. 85 degrees), 8 long, times scale, its triangles
// ordered so that the round's 52-degree cells come first (as a chordal surface's triangles may be); `at`: per
// triangle, its cell's turn in degrees.
struct RoundL {
  Triangles t;
  std::vector<double> at;
  int faceOf(const std::vector<int>& patch, double degrees) const {
    return patch[std::find(at.begin(), at.end(), degrees) - at.begin()];
  }
};

RoundL roundL(double scale) {
  const std::vector<double> round = {7, 18, 29, 38, 52, 63, 74, 85};
  std::vector<double> turn(10, 0.0);
  turn.insert(turn.end(), round.begin(), round.end());
  turn.insert(turn.end(), 10, 90.0);
  std::vector<Vec3> profile{Vec3(0, 0, 0)};
  for (double degrees : turn) {
    const double a = degrees * M_PI / 180;
    profile.push_back(profile.back() + Vec3(std::cos(a), 0, std::sin(a)));
  }
  const auto bent = [&](double x, double y) {
    return Vec3(profile[static_cast<int>(x)].x(), y, profile[static_cast<int>(x)].z());
  };
  const int nx = static_cast<int>(turn.size());
  const Triangles t = grid(nx, 8, bent, scale);
  std::vector<std::size_t> order(t.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_partition(order.begin(), order.end(), [&](std::size_t k) { return turn[(k / 2) % nx] == 52; });
  RoundL l{{t.points, {}}, {}};
  for (std::size_t k : order) l.t.triangles.push_back(t.triangles[k]), l.at.push_back(turn[(k / 2) % nx]);
  return l;
}

// Whether the L's round is cut in its middle: two patches, the round's cells within 40 degrees of a sheet in its patch.
void expectCutInTheRoundsMiddle(const RoundL& l, const std::vector<int>& patch, double scale) {
  EXPECT_EQ(std::set<int>(patch.begin(), patch.end()).size(), 2u) << "scale " << scale;
  for (std::size_t k = 0; k < l.at.size(); ++k)
    EXPECT_EQ(patch[k], l.faceOf(patch, l.at[k] <= 40 ? 0 : 90)) << "cell at " << l.at[k] << " degrees";
}

TEST(ChordalPatches, FlatFirstSeedsShareARoundBetweenItsFaces) {
  // Grown in index order, the first patch is seeded in the round and takes it (but its 7-degree cells) and the far
  // sheet, all within 40 degrees of 52: the cut lies where the round starts. Grown from the flat cells first, each
  // sheet takes the round's cells within 40 degrees of its own normal (7 .. 38 and 52 .. 85): the cut lies in the
  // round's middle, at any scale.
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const RoundL l = roundL(scale);
    const std::vector<int> inOrder = facePatches(l.t.points, l.t.triangles, 40, 0.5 * scale);
    EXPECT_EQ(l.faceOf(inOrder, 18), l.faceOf(inOrder, 90)) << "scale " << scale;
    EXPECT_EQ(l.faceOf(inOrder, 7), l.faceOf(inOrder, 0));
    EXPECT_NE(l.faceOf(inOrder, 0), l.faceOf(inOrder, 90));
    expectCutInTheRoundsMiddle(l, facePatches(l.t.points, l.t.triangles, 40, 0.5 * scale, PatchSeeds::FlatFirst),
                               scale);
  }
}

TEST(ChordalPatches, RimsFittedToTheNormalsShareARoundBetweenItsFaces) {
  // The L grown in index order (its cut where the round starts, as above), its rims then fitted to the patches' mean
  // normals: the round's cells at 18 .. 38 degrees, nearer the first sheet's mean normal than the other patch's, go to
  // the first sheet a row at a time, those at 52 stay (more than 40 degrees from the first sheet): the cut lies in the
  // round's middle, as from flat seeds, at any scale.
  for (const double scale : {1.0, 1e-3, 1e3}) {
    const RoundL l = roundL(scale);
    const std::vector<int> fitted =
        facePatches(l.t.points, l.t.triangles, 40, 0.5 * scale, PatchSeeds::InOrder, PatchRims::FittedToNormals);
    expectCutInTheRoundsMiddle(l, fitted, scale);
    EXPECT_TRUE(patchesConnected(l.t, fitted));
  }
}

TEST(ChordalPatches, TopologyOfAChannel) {
  // Four corners where the bends meet the rim; six curves: the two bends, the rim of each side sheet in one piece
  // and of the middle sheet in two; each curve a chain of its vertices from corner to corner.
  const Triangles t = grid(30, 8, channel);
  const std::vector<int> patch = chordalPatches(t.points, t.triangles, 60);
  const PatchTopology topology = patchTopology(t.triangles, patch);
  auto id = [](int i, int j) { return j * 31 + i; };
  EXPECT_EQ(topology.corners, (std::vector<int>{id(10, 0), id(20, 0), id(10, 8), id(20, 8)}));
  ASSERT_EQ(topology.curves.size(), 6u);
  std::map<std::array<int, 2>, std::size_t> edges;  // patches either side -> edges of their curves
  for (const PatchCurve& c : topology.curves) {
    EXPECT_TRUE(std::count(topology.corners.begin(), topology.corners.end(), c.vertices.front()));
    EXPECT_TRUE(std::count(topology.corners.begin(), topology.corners.end(), c.vertices.back()));
    edges[c.patches] += c.vertices.size() - 1;
  }
  const std::map<std::array<int, 2>, std::size_t> expected{
      {{-1, 0}, 8 + 10 + 10}, {{-1, 1}, 10 + 10}, {{-1, 2}, 8 + 10 + 10}, {{0, 1}, 8}, {{1, 2}, 8}};
  EXPECT_EQ(edges, expected);
  ASSERT_EQ(topology.bounding.size(), 3u);
  EXPECT_EQ(topology.bounding[0].size(), 2u);
  EXPECT_EQ(topology.bounding[1].size(), 4u);
  EXPECT_EQ(topology.bounding[2].size(), 2u);
}

TEST(ChordalPatches, TopologyOfAFlatSheetIsOneLoop) {
  const Triangles t = grid(5, 3, [](double x, double y) { return Vec3(x, y, 0); });
  const PatchTopology topology = patchTopology(t.triangles, std::vector<int>(t.triangles.size(), 0));
  EXPECT_EQ(topology.corners, std::vector<int>{0}) << "a loop without corners starts at its lowest vertex";
  ASSERT_EQ(topology.curves.size(), 1u);
  EXPECT_EQ(topology.curves[0].vertices.size(), 2u * (5 + 3) + 1);
  EXPECT_EQ(topology.curves[0].vertices.front(), topology.curves[0].vertices.back());
}

TEST(ChordalPatches, PinchedVerticesOfAChequerboard) {
  // Four squares round a vertex, the diagonal ones in one patch: each patch meets itself at the centre.
  const Triangles t = grid(2, 2, [](double x, double y) { return Vec3(x, y, 0); });
  const std::vector<int> patch = {0, 0, 1, 1, 1, 1, 0, 0};
  EXPECT_EQ(pinchedPatchVertices(t.triangles, patch), 2u);
  EXPECT_EQ(pinchedPatchVertices(t.triangles, std::vector<int>(8, 0)), 0u);
}

}  // namespace
}  // namespace hexlayer
