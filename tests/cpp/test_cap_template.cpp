// The cross-sections of rim caps (sweep/cap_template.hpp): each template tiles the region between the column and
// the half circle's chords with quads of one orientation whose sweep edges go up, at the quality it claims; the
// inside nodes' weights put them back where they are drawn, at any scale.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "sweep/cap_template.hpp"

using namespace hexlayer;

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Signed area of a polygon of template nodes (negative: clockwise).
double area(const CapTemplate& t, const std::vector<int>& nodes) {
  double a = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    a += 0.5 * cross(templatePosition(t, nodes[i]), templatePosition(t, nodes[(i + 1) % nodes.size()]));
  return a;
}

// The smallest sine of a quad's corners (its scaled Jacobian, as a hex extruded from it has).
double quadQuality(const CapTemplate& t, const std::array<int, 4>& q) {
  double worst = 1;
  for (int i = 0; i < 4; ++i) {
    const Vec2 x = templatePosition(t, q[i]);
    const Vec2 next = templatePosition(t, q[(i + 1) % 4]) - x, prev = templatePosition(t, q[(i + 3) % 4]) - x;
    worst = std::min(worst, cross(prev, next) / (prev.norm() * next.norm()));  // clockwise: prev x next > 0
  }
  return worst;
}

std::vector<CapTemplate> allTemplates() {
  std::vector<CapTemplate> all{*drawnCap(2), *drawnCap(3)};
  for (int layers = 1; layers <= 5; ++layers)
    for (int rows = 1; rows <= 2; ++rows) all.push_back(structuredCap(layers, rows));
  return all;
}

}  // namespace

TEST(CapTemplate, QuadsTileTheCapClockwiseWithSweepEdgesUp) {
  for (const CapTemplate& t : allTemplates()) {
    SCOPED_TRACE(testing::Message() << t.layers << " layers, " << t.quads.size() << " quads");
    double quads = 0;
    std::map<std::pair<int, int>, int> edges;  // directed edges of the quads
    for (const auto& q : t.quads) {
      const double a = area(t, {q[0], q[1], q[2], q[3]});
      EXPECT_LT(a, 0) << "clockwise";
      quads += a;
      EXPECT_GT(templatePosition(t, q[1]).y(), templatePosition(t, q[0]).y());
      EXPECT_GT(templatePosition(t, q[2]).y(), templatePosition(t, q[3]).y());
      for (int i = 0; i < 4; ++i) ++edges[{q[i], q[(i + 1) % 4]}];
    }
    const std::vector<int> boundary = templateBoundary(t);
    EXPECT_NEAR(quads, area(t, boundary), 1e-12) << "the quads cover the cap once";
    // Every edge is used once each way inside and once along the boundary (conformal, no hanging node).
    std::map<std::pair<int, int>, int> onBoundary;
    for (std::size_t i = 0; i < boundary.size(); ++i) ++onBoundary[{boundary[i], boundary[(i + 1) % boundary.size()]}];
    for (const auto& [e, n] : edges) {
      EXPECT_EQ(n, 1);
      const bool outer = onBoundary.count(e) > 0;
      EXPECT_EQ(edges.count({e.second, e.first}) > 0, !outer) << e.first << "-" << e.second;
    }
    EXPECT_EQ(static_cast<int>(boundary.size()), t.layers + 1 + static_cast<int>(t.onProfile.size()));
  }
}

TEST(CapTemplate, DrawnTemplatesBeatTheStructuredCap) {
  // In the half disc: the worst quad of the drawn caps against the structured cap's of one column.
  for (const auto& [layers, floor] : {std::pair{2, 0.73}, std::pair{3, 0.81}}) {
    const CapTemplate drawn = *drawnCap(layers), structured = structuredCap(layers, 1);
    double worstDrawn = 1, worstStructured = 1;
    for (const auto& q : drawn.quads) worstDrawn = std::min(worstDrawn, quadQuality(drawn, q));
    for (const auto& q : structured.quads) worstStructured = std::min(worstStructured, quadQuality(structured, q));
    EXPECT_GE(worstDrawn, floor) << layers;
    EXPECT_LT(worstStructured, 0.71) << layers;  // a corner of 135 (4 chords) or 144 degrees (5) on the profile
    // The half disc's lens the chords leave out: less than the structured cap's 4 chords with 2 layers (6 chords),
    // about as much as its 5 chords with 3 (5 chords, not even).
    const double lostDrawn = M_PI / 2 + area(drawn, templateBoundary(drawn));
    const double lostStructured = M_PI / 2 + area(structured, templateBoundary(structured));
    EXPECT_LT(lostDrawn, (layers == 2 ? 0.75 : 1.1) * lostStructured) << layers;
  }
}

TEST(CapTemplate, InsideWeightsPlaceTheInsideNodesAtAnyScale) {
  for (const CapTemplate& t : allTemplates()) {
    const std::vector<int> boundary = templateBoundary(t);
    const std::vector<std::vector<double>> weights = insideWeights(t);
    ASSERT_EQ(weights.size(), t.inside.size());
    for (const double scale : {1.0, 1e-3, 1e3}) {
      const Vec2 shift(3 * scale, -7 * scale);
      for (std::size_t j = 0; j < weights.size(); ++j) {
        Vec2 x = Vec2::Zero();
        double sum = 0;
        for (std::size_t i = 0; i < boundary.size(); ++i) {
          EXPECT_GT(weights[j][i], -1e-12) << "inside a convex polygon the weights are not negative";
          x += weights[j][i] * (scale * templatePosition(t, boundary[i]) + shift);
          sum += weights[j][i];
        }
        EXPECT_NEAR(sum, 1, 1e-12);
        EXPECT_LT((x - (scale * t.inside[j] + shift)).norm(), 1e-12 * scale);
      }
    }
  }
}
