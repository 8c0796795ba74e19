// The chordal surface's rim between the walls' rim edges (chordal/chordal_rim.hpp), on flat surfaces made by
// hand, whose rim should lie on the line y = 0: a zigzag rim straightened, a spike that would turn over dropped,
// a narrow spike dropped.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "chordal/chordal_rim.hpp"
#include "chordal/chordal_surface.hpp"

using namespace hexlayer;

namespace {

// Rows j = 0..rows of points (i, y_j) for i = 0..columns, row 0 at the heights `rim` (one per column), quads
// between rows turning counter-clockwise seen from +z.
ChordalSurface strip(const std::vector<double>& rim, int rows) {
  ChordalSurface s;
  const int n = static_cast<int>(rim.size());
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < n; ++i) s.vertices.emplace_back(i, j == 0 ? rim[i] : j, 0);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i + 1 < n; ++i)
      s.facets.push_back({j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i}), ++s.quads;
  s.tetEdge.assign(s.vertices.size(), {0, 0});
  return s;
}

// The rim of the surfaces here: the line y = 0 (for points below y = 0.5, as the rim's profile would be).
std::optional<Vec3> onLine(const Vec3& p) {
  if (p.y() > 0.5) return std::nullopt;
  return Vec3(p.x(), 0, p.z());
}

// A strip 8 x 6 (rim y = 0) without the unit quads whose first corners are `gone`.
ChordalSurface stripWithout(const std::vector<Vec3>& gone) {
  ChordalSurface s = strip(std::vector<double>(9, 0.0), 6);
  s.facets.erase(std::remove_if(s.facets.begin(), s.facets.end(),
                                [&](const std::array<int, 4>& f) {
                                  return std::find(gone.begin(), gone.end(), s.vertices[f[0]]) != gone.end();
                                }),
                 s.facets.end());
  return s;
}

// A strip 8 x 6 (rim y = 0) without the quads at (3, 3) (a tear) and (6, 1) (a hole beside the rim).
ChordalSurface stripWithTearAndHole() { return stripWithout({Vec3(3, 3, 0), Vec3(6, 1, 0)}); }

}  // namespace

// A strip 6 x 2 whose rim zigzags by +-0.3 about y = 0 (a concave rim's tet cuts): the 5 vertices of that rim
// off the line go onto it (its ends are on it already; the other rim vertices, at y >= 1, have no place on it)
// and no other vertex moves.
TEST(ChordalRim, ZigzagRimGoesOntoTheLineMidwayBetweenTheWalls) {
  ChordalSurface s = strip({0, 0.3, -0.3, 0.3, -0.3, 0.3, 0}, 2);
  const std::vector<Vec3> before = s.vertices;
  const RimSnapStats stats = snapRimBetweenWallEdges(s, onLine, 1.0);
  EXPECT_EQ(stats.rimVertices, 7u + 7u + 2u);  // the rim row, the top row and the short sides' middle vertices
  EXPECT_EQ(stats.moved, 5u);
  EXPECT_NEAR(stats.largestMove, 0.3, 1e-12);
  EXPECT_EQ(stats.spikesDropped, 0u);
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(s.vertices[i].y(), 0, 1e-12);
  for (std::size_t v = 7; v < s.vertices.size(); ++v) EXPECT_EQ(s.vertices[v], before[v]);
}

// A straight strip with a triangle hanging below its rim, its tip at (2.5, -0.8): put on the line y = 0 the tip
// would lie on the triangle's base, the triangle flat (below half its area): a spike of the rim that the move
// spoils, so it is dropped, and its tip with it.
TEST(ChordalRim, ASpikeTheMoveWouldTurnOverIsDropped) {
  ChordalSurface s = strip({0, 0, 0, 0, 0, 0}, 2);
  const int tip = static_cast<int>(s.vertices.size());
  s.vertices.emplace_back(2.5, -0.8, 0), s.tetEdge.push_back({0, 0});
  s.facets.push_back({2, tip, 3, -1}), ++s.triangles;
  const std::size_t facets = s.facets.size();
  const RimSnapStats stats = snapRimBetweenWallEdges(s, onLine, 1.0);
  EXPECT_EQ(stats.spikesDropped, 1u);
  EXPECT_EQ(s.facets.size(), facets - 1);
  EXPECT_EQ(s.vertices.size(), static_cast<std::size_t>(tip)) << "the tip is no vertex of the surface any more";
}

// A straight strip with a long thin triangle hanging below its rim, its tip at (2.5, -5) (11.4 degrees there),
// too far from the line to be moved: a narrow spike of the rim, dropped all the same; the rim is straight again.
TEST(ChordalRim, ANarrowSpikeIsDropped) {
  ChordalSurface s = strip({0, 0, 0, 0, 0, 0}, 2);
  const ChordalSurface straight = s;
  s.vertices.emplace_back(2.5, -5, 0), s.tetEdge.push_back({0, 0});
  s.facets.push_back({2, static_cast<int>(s.vertices.size()) - 1, 3, -1}), ++s.triangles;
  const RimSnapStats stats = snapRimBetweenWallEdges(s, onLine, 1.0);
  EXPECT_EQ(stats.moved, 0u);
  EXPECT_EQ(stats.spikesDropped, 1u);
  EXPECT_EQ(s.facets, straight.facets);
  EXPECT_EQ(s.vertices, straight.vertices);
}

// No point inside the part's material: fillTears' loops along lateral faces are all the part's rims or holes.
const auto noMaterial = [](const Vec3&) { return false; };

// The part's material on the strip of stripWithTearAndHole but in its hole's square (6, 1)-(7, 2).
const auto materialBesideTheHole = [](const Vec3& p) {
  const bool hole = p.x() > 6 && p.x() < 7 && p.y() > 1 && p.y() < 2;
  return !hole && p.x() > 0 && p.x() < 8 && p.y() > 0 && p.y() < 6;
};

// A strip 8 x 6 of unit quads (all rows at integer heights) without the square at (3, 3) and without the one at
// (6, 1): two rim loops 4 long besides the outer rim (28 long). Of the lateral faces only the outer rim's line
// y = 0 is "near" (nearRim: y < 1.5): the tear in the middle is filled with two triangles facing +z like the quads,
// the hole beside the rim stays (a hole of the part runs along its lateral faces), and so does everything with a
// bound shorter than the tear.
TEST(ChordalRim, ATearAwayFromTheLateralFacesIsFilled) {
  ChordalSurface s = stripWithTearAndHole();
  const auto nearRim = [](const Vec3& p) { return p.y() < 1.5; };
  ChordalSurface unchanged = s;
  EXPECT_EQ(fillTears(unchanged, nearRim, noMaterial, 3.9), 0u) << "the tear is 4 long";
  EXPECT_EQ(unchanged.facets.size(), s.facets.size());
  const std::size_t facets = s.facets.size();
  EXPECT_EQ(fillTears(s, nearRim, noMaterial, 5), 1u);
  ASSERT_EQ(s.facets.size(), facets + 2);
  EXPECT_EQ(rimLoops(s).length.size(), 2u) << "the outer rim and the hole beside it";
  for (const auto& [edge, uses] : facetEdgeUses(s)) EXPECT_LE(uses, 2) << edge.first << " " << edge.second;
  for (std::size_t f = facets; f < s.facets.size(); ++f) {
    const auto& t = s.facets[f];
    EXPECT_EQ(t[3], -1);
    const Vec3 n = (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]);
    EXPECT_GT(n.z(), 0) << "facing +z as the quads";
  }
}

// The same tear one of whose four vertices is near a lateral face (a tear in a wall three walls high reaches within
// a wall of its rim): still a tear, filled; the hole beside the rim (two of four near) stays.
TEST(ChordalRim, ATearWithAVertexNearTheRimIsFilled) {
  ChordalSurface s = stripWithTearAndHole();
  const auto nearRim = [](const Vec3& p) { return p.y() < 1.5 || (p - Vec3(3, 3, 0)).norm() < 0.1; };
  const std::size_t facets = s.facets.size();
  EXPECT_EQ(fillTears(s, nearRim, noMaterial, 5), 1u);
  EXPECT_EQ(s.facets.size(), facets + 2);
  EXPECT_EQ(rimLoops(s).length.size(), 2u) << "the outer rim and the hole beside it";
}

// The same strip, every vertex near a lateral face (a wall 1 to 2 walls high: a lip), the part's material everywhere
// but in the square (6, 1)-(7, 2) and beyond the strip: the tear at (3, 3) has material all round it and is filled; the
// hole at (6, 1) has air in its middle and stays; the outer rim, though within the bound and round material, turns
// with the facets (no hole of the surface) and stays.
TEST(ChordalRim, ALoopAlongTheRimWithMaterialAllRoundIsATear) {
  ChordalSurface s = stripWithTearAndHole();
  const auto nearRim = [](const Vec3&) { return true; };
  ChordalSurface unchanged = s;
  EXPECT_EQ(fillTears(unchanged, nearRim, noMaterial, 100), 0u) << "no material: every loop is the part's";
  const std::size_t facets = s.facets.size();
  EXPECT_EQ(fillTears(s, nearRim, materialBesideTheHole, 100), 1u);
  ASSERT_EQ(s.facets.size(), facets + 2);
  EXPECT_EQ(rimLoops(s).length.size(), 2u) << "the outer rim and the hole beside it";
  for (std::size_t f = facets; f < s.facets.size(); ++f) {
    Vec3 middle = Vec3::Zero();
    for (int k = 0; k < 3; ++k) middle += s.vertices[s.facets[f][k]] / 3;
    EXPECT_NEAR(middle.x(), 3.5, 0.5);
    EXPECT_NEAR(middle.y(), 3.5, 0.5);
  }
}

// The same strip: the tear at (3, 3), 4 long, is longer than a bound of 3, so it is filled only if the part's material
// is all round it (a hole of the part is air in its middle), and not beyond 3 times the bound (a bound of 1): a tear
// several walls long where facets of a thin lip are missing above its step.
TEST(ChordalRim, ALongerLoopIsATearOnlyWithMaterialAllRound) {
  const auto nearRim = [](const Vec3& p) { return p.y() < 1.5; };
  ChordalSurface s = stripWithTearAndHole();
  EXPECT_EQ(fillTears(s, nearRim, noMaterial, 3), 0u) << "longer than the bound, no material round it";
  EXPECT_EQ(fillTears(s, nearRim, materialBesideTheHole, 1), 0u) << "longer than 3 times the bound";
  const std::size_t facets = s.facets.size();
  EXPECT_EQ(fillTears(s, nearRim, materialBesideTheHole, 3), 1u);
  EXPECT_EQ(s.facets.size(), facets + 2);
  EXPECT_EQ(rimLoops(s).length.size(), 2u) << "the outer rim and the hole beside it";
}

// A tear whose loop passes a vertex on each side of an edge the surface has: the strip without the squares at (3, 3)
// and (4, 3), a triangle standing in the gap on the edge from (3, 3) to (4, 3) (its tip (3.5, 3.5) on the loop). A fan
// from (3, 3), the loop's first vertex, would join it to (4, 3) again (that edge in four facets, which Gmsh refuses:
// `one edge is incident to 4 triangles`); the fan starts at another vertex, every edge is in two facets at most.
TEST(ChordalRim, AFanDoesNotRepeatAnEdgeTheSurfaceHas) {
  ChordalSurface s = stripWithout({Vec3(3, 3, 0), Vec3(4, 3, 0)});
  const int tip = static_cast<int>(s.vertices.size());
  s.vertices.emplace_back(3.5, 3.5, 0);
  s.facets.push_back({3 * 9 + 3, 3 * 9 + 4, tip, -1}), ++s.triangles;
  s.tetEdge.push_back({0, 0});
  const std::size_t facets = s.facets.size();
  EXPECT_EQ(fillTears(
                s, [](const Vec3& p) { return p.y() < 1.5; }, noMaterial, 7),
            1u);
  EXPECT_EQ(s.facets.size(), facets + 5) << "7 vertices round the tear";
  for (const auto& [edge, uses] : facetEdgeUses(s)) EXPECT_LE(uses, 2) << edge.first << " " << edge.second;
  EXPECT_EQ(rimLoops(s).length.size(), 1u) << "the outer rim alone";
}
