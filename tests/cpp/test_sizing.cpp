// Sizing function of the quad mesh (§6.1): proportional to the radius function, limited by the
// curvature of the chordal surface, bounded, and graded.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "quadmesh/sizing.hpp"
#include "test_flat_surfaces.hpp"

using namespace hexlayer;

namespace {

// How wide the strips are: the gap across them (two quads across a gap) holds no size of these tests.
constexpr double kWide = 1e3;

// A flat strip of quads along x (n quads, 1 long, kWide wide) with radius r(x) and normal +z.
ChordalSurface strip(int n, double (*radius)(double)) {
  ChordalSurface s;
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= n; ++i) {
      s.vertices.emplace_back(i, j * kWide, 0);
      s.normals.push_back(Vec3::UnitZ());
      s.radius.push_back(radius(i));
    }
  for (int i = 0; i < n; ++i) s.facets.push_back({i, i + 1, n + 1 + i + 1, n + 1 + i});
  return s;
}

double wedge(double x) { return 0.5 + 0.05 * x; }     // wall 1 mm thick at x = 0, 3 mm at x = 20
double step(double x) { return x < 10 ? 0.5 : 4.0; }  // a sudden jump of the wall

}  // namespace

TEST(Sizing, FollowsTheRadiusFunction) {
  const ChordalSurface s = strip(20, wedge);
  const std::vector<double> h = adaptiveSizes(s, {2.0, 0.1, 100, 10, 0.5});  // no bound, no gradation limit
  const double medianRadius = wedge(10);
  for (size_t i = 0; i < h.size(); ++i) EXPECT_NEAR(h[i], 2.0 * s.radius[i] / medianRadius, 1e-12) << i;
}

TEST(Sizing, IsBoundedAndGraded) {
  const ChordalSurface s = strip(20, step);
  const std::vector<double> h = adaptiveSizes(s, {1.0, 0.5, 3.0, 0.3, 0.5});
  for (size_t i = 0; i < h.size(); ++i) {
    EXPECT_GE(h[i], 0.5 - 1e-12);
    EXPECT_LE(h[i], 3.0 + 1e-12);
  }
  for (int i = 0; i < 20; ++i) EXPECT_LE(std::abs(h[i + 1] - h[i]), 0.3 + 1e-12) << "gradation at x = " << i;
  // The median radius is 4 (11 of 21 columns): size 1 x 4/4 on the thick side, 1 x 0.5/4 raised to
  // the bound 0.5 on the thin side; the first thick column is held to 0.5 + 0.3.
  EXPECT_NEAR(h[0], 0.5, 1e-12);
  EXPECT_NEAR(h[20], 1.0, 1e-12);
  EXPECT_NEAR(h[10], 0.8, 1e-12);
}

TEST(Sizing, CurvatureRefines) {
  // A cylinder of radius 5 seen as a strip: normals turn by 0.1 rad per unit of arc length.
  ChordalSurface s = strip(20, wedge);
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    const double a = 0.2 * s.vertices[i].x();  // arc length x on radius 5
    s.normals[i] = Vec3(std::sin(a), 0, std::cos(a));
  }
  const std::vector<double> k = chordalCurvature(s);
  // The mean over a vertex's edges of their turn per length: 0.2 along x (two such edges inside, one at the
  // strip's ends), 0 across it (one edge).
  for (size_t v = 0; v < k.size(); ++v) {
    const int i = static_cast<int>(v) % 21, along = i == 0 || i == 20 ? 1 : 2;
    EXPECT_NEAR(k[v], 0.2 * along / (along + 1), 1e-7) << "vertex " << v;  // acos near 1: ~5e-9
  }
  const std::vector<double> h = adaptiveSizes(s, {10.0, 0.1, 100, 10, 0.5});
  for (size_t i = 0; i < h.size(); ++i) EXPECT_NEAR(h[i], 0.5 / k[i], 1e-9) << "turn of 0.5 rad per quad";
}

TEST(Sizing, ABendTighterThanItsWallIsACreaseTheCurvatureTermLeaves) {
  // The radius-5 cylinder of CurvatureRefines under a wall 8 thick (r = 4): its radius of curvature is below the
  // wall's thickness, a crease (the inside of a sharp bend): the sizes are the radius term's alone.
  ChordalSurface s = strip(20, [](double) { return 4.0; });
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    const double a = 0.2 * s.vertices[i].x();
    s.normals[i] = Vec3(std::sin(a), 0, std::cos(a));
  }
  const std::vector<double> k = chordalCurvature(s);
  const std::vector<double> h = adaptiveSizes(s, {5.2, 0.1, 100, 10, 0.5});  // under the strip's rim cap 42 / 8
  for (size_t i = 0; i < h.size(); ++i) {
    if (k[i] * 2 * s.radius[i] > 1) EXPECT_NEAR(h[i], 5.2, 1e-12) << "a crease at vertex " << i;
    if (k[i] * 2 * s.radius[i] <= 1) EXPECT_NEAR(h[i], 0.5 / k[i], 1e-9) << "the strip's ends: " << i;
  }
  EXPECT_GT(std::count_if(k.begin(), k.end(), [](double c) { return c * 8 > 1; }), 30);
}

TEST(Sizing, ASharpFoldKeepsTheRadiusSizeWithOrWithoutTheCurvatureTerm) {
  // The strip folded by 90 degrees at x = 10: the fold is a crease (isCrease: a turn of 45 degrees per unit edge
  // on a wall 2 thick there), with the curvature term or without it (the own-patch tries' sizes, quad_stage.hpp:
  // the fold is a patch curve there) its vertices keep the radius term's size.
  ChordalSurface s = strip(20, wedge);
  for (size_t i = 0; i < s.vertices.size(); ++i) {
    const double x = s.vertices[i].x();
    if (x > 10) s.vertices[i] = Vec3(10, s.vertices[i].y(), x - 10), s.normals[i] = -Vec3::UnitX();
    if (x == 10) s.normals[i] = Vec3(-1, 0, 1).normalized();
  }
  SizingOptions o{2.0, 0.1, 100, 10, 0.5};
  const std::vector<double> withCurvature = adaptiveSizes(s, o);
  o.turnPerQuad = std::numeric_limits<double>::infinity();
  const std::vector<double> h = adaptiveSizes(s, o);
  const std::vector<double> k = chordalCurvature(s);
  const double medianRadius = wedge(10);
  for (size_t i = 0; i < h.size(); ++i) {
    EXPECT_NEAR(h[i], 2.0 * s.radius[i] / medianRadius, 1e-12) << i;
    if (s.vertices[i].x() != 10 || s.vertices[i].z() != 0) continue;
    EXPECT_GT(k[i] * 2 * s.radius[i], 1) << "the fold is a crease";
    EXPECT_NEAR(withCurvature[i], h[i], 1e-12) << i;
  }
}

// A 10 x 10 plate of unit quads with a 2 x 2 hole in its middle (rim loop 8 long), a wall of constant radius asking
// for quads of 4: the hole's rim is held to 8 / 8 = 1 (eight quad edges round it; at 4 the quad mesh closes the
// hole) and the rest graded from there; the outer rim (40 long) asks no less than 4. At scales 1e-3, 1 and 1e3.
TEST(Sizing, AHolesRimKeepsEightQuadEdgesRoundIt) {
  for (const double scale : {1e-3, 1.0, 1e3}) {
    ChordalSurface s = test_flat_surfaces::rectangle(10, 10, {{4, 6, 4, 6}});
    for (Vec3& v : s.vertices) v *= scale;
    s.radius.assign(s.vertices.size(), 0.5 * scale);
    const std::vector<double> h = adaptiveSizes(s, {4.0 * scale, 0.25 * scale, 16 * scale, 0.3, 0.5});
    for (size_t i = 0; i < h.size(); ++i) {
      const Vec3 p = s.vertices[i] / scale;
      const Vec3 off = p - Vec3(std::clamp(p.x(), 4.0, 6.0), std::clamp(p.y(), 4.0, 6.0), 0);
      const double fromHole = off.norm(), alongEdges = off.lpNorm<1>();
      const bool onHoleRim = p.x() >= 4 && p.x() <= 6 && p.y() >= 4 && p.y() <= 6;
      if (onHoleRim) EXPECT_NEAR(h[i], scale, 1e-9 * scale) << "vertex " << i << " at scale " << scale;
      EXPECT_LE(h[i], scale * (1 + 0.3 * alongEdges) + 1e-9 * scale) << "graded from the hole's rim";
      EXPECT_GT(h[i], scale * (0.99 + 0.3 * std::max(0.0, fromHole - 1.5))) << "no smaller than the grading asks";
    }
  }
}

// A 30 x 12 plate of unit quads with a 4 x 2 hole 1 above its rim y = 0 (x 10..14, y 1..3), a wall asking for quads
// of 4: across the ligament 1 wide between the hole and the rim, two quads (0.5: the hole's rim alone holds 12 / 8 =
// 1.5, 1.8 a quad below it); a convex corner of the plate, whose rims meet but do not face each other, is held by the
// grading only. The same plate and another one 1 above it (two sheets across the air: the rims face each other along
// the normal, not across a surface): the sizes of one plate alone. At scales 1e-3, 1 and 1e3.
TEST(Sizing, AGapAcrossTheSurfaceHoldsTwoQuadsAcrossIt) {
  for (const double scale : {1e-3, 1.0, 1e3}) {
    ChordalSurface s = test_flat_surfaces::rectangle(30, 12, {{10, 14, 1, 3}});
    for (Vec3& v : s.vertices) v *= scale;
    s.radius.assign(s.vertices.size(), 0.5 * scale);
    const SizingOptions o{4.0 * scale, 0.25 * scale, 16 * scale, 0.3, 0.5};
    const std::vector<double> h = adaptiveSizes(s, o);
    for (size_t i = 0; i < h.size(); ++i) {
      const Vec3 p = s.vertices[i] / scale;
      if (p.x() >= 11 && p.x() <= 13 && (p.y() == 0 || p.y() == 1))
        EXPECT_NEAR(h[i], 0.5 * scale, 1e-9 * scale) << "x " << p.x() << " y " << p.y() << " scale " << scale;
      if (p.x() == 0 && p.y() == 0) EXPECT_NEAR(h[i], (0.5 + 0.3 * 11) * scale, 1e-9 * scale) << "graded only";
    }
    ChordalSurface two = s;
    const int n = static_cast<int>(s.vertices.size());
    for (int v = 0; v < n; ++v)
      two.vertices.push_back(s.vertices[v] + Vec3(0, 0, scale)), two.normals.push_back(s.normals[v]),
          two.radius.push_back(s.radius[v]);
    for (auto f : s.facets) {
      for (int& v : f) v += v >= 0 ? n : 0;
      two.facets.push_back(f);
    }
    const std::vector<double> both = adaptiveSizes(two, o);
    for (int v = 0; v < 2 * n; ++v) EXPECT_NEAR(both[v], h[v % n], 1e-9 * scale) << "vertex " << v;
  }
}

// A wedge 10 long whose sides meet at 45 degrees (a gusset's tip): its sides face each other across it by their
// direction into it (22.5 degrees), but the rim between two points across it, round the tip, is only 2.6 times their
// gap: the tip is not a gap, and every size is the loop's (its length over eight), as without the gap term.
TEST(Sizing, AWedgesTipIsNoGap) {
  for (const double scale : {1e-3, 1.0, 1e3}) {
    ChordalSurface s;
    const double half = M_PI / 8;
    s.vertices.push_back(Vec3::Zero());
    for (int k = 1; k <= 10; ++k)
      s.vertices.push_back(k * scale * Vec3(std::cos(half), -std::sin(half), 0)),
          s.vertices.push_back(k * scale * Vec3(std::cos(half), std::sin(half), 0));
    s.facets.push_back({0, 1, 2, -1});
    for (int k = 1; k < 10; ++k) s.facets.push_back({2 * k - 1, 2 * k + 1, 2 * k + 2, 2 * k});
    s.normals.assign(s.vertices.size(), Vec3::UnitZ());
    s.radius.assign(s.vertices.size(), 0.5 * scale);
    const std::vector<double> h = adaptiveSizes(s, {4.0 * scale, 1.0 * scale, 16 * scale, 0.3, 0.5});
    const double loop = (20 + 20 * std::sin(half)) * scale;
    for (size_t i = 0; i < h.size(); ++i) EXPECT_NEAR(h[i], loop / 8, 1e-9 * scale) << "vertex " << i;
  }
}

// A hole whose rim loop is shorter than the smallest quad edge is a pinhole between facets (closed by
// buildChordalSurface's closePinholes, or too small for any quad): the sizes are not held down round it.
TEST(Sizing, ALoopShorterThanTheSmallestQuadEdgeIsLeftAlone) {
  ChordalSurface s = test_flat_surfaces::rectangle(10, 10, {{4, 5, 4, 5}});
  s.radius.assign(s.vertices.size(), 0.5);
  const std::vector<double> h = adaptiveSizes(s, {4.0, 5.0, 16, 0.3, 0.5});  // the loop is 4 long
  for (size_t i = 0; i < h.size(); ++i) EXPECT_NEAR(h[i], 5.0, 1e-12) << "the radius size 4, raised to the bound";
}

// The size field Gmsh asks (§6.1): on the strip, the size interpolated linearly along it (the sizes at its vertices
// grow linearly), at x1, 1e-3 and 1e3; a point far beyond the surface (Gmsh's (1e21, 1e21, 1e21) where its
// parametrization has no point) takes the mean size of the facet found before, or the largest size before any.
TEST(Sizing, TheSizeFieldInterpolatesOnTheSurfaceAndKeepsTheFacetBeforeForAFarPoint) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    ChordalSurface chordal = strip(20, wedge);
    for (Vec3& v : chordal.vertices) v *= s;
    std::vector<double> size;
    for (const Vec3& v : chordal.vertices) size.push_back((1 + 0.1 * v.x() / s) * s);  // h = (1 + x / 10) s
    const ChordalLocator locator(chordal);
    ChordalSizeField field(locator, size);
    const Vec3 far = Vec3::Constant(1e21);
    EXPECT_DOUBLE_EQ(field(far), 3 * s);  // before any point: the largest size (x = 20)
    for (double x : {0.3, 7.25, 19.9}) EXPECT_NEAR(field(Vec3(x, 0.4, 0.01) * s), (1 + 0.1 * x) * s, 1e-12 * s) << x;
    // after x = 19.9 (on the facet [19, 20]): that facet's corners' mean, whatever the far point
    EXPECT_NEAR(field(far), 2.95 * s, 1e-12 * s);
    EXPECT_NEAR(field(Vec3(-1e30, 5e29, 0)), 2.95 * s, 1e-12 * s);
    EXPECT_NEAR(field(Vec3(NAN, 0, 0)), 2.95 * s, 1e-12 * s);
    // a point beside the strip but within its grown box: the nearest facet's size, not the one before
    EXPECT_NEAR(field(Vec3(2.5, 3, 4) * s), 1.25 * s, 1e-12 * s);
    int facet = -1;  // the thread-safe form, from no facet: the same
    EXPECT_DOUBLE_EQ(field.at(far, facet), 3 * s);
    EXPECT_NEAR(field.at(Vec3(7.25, 0.5, 0) * s, facet), 1.725 * s, 1e-12 * s);
    EXPECT_EQ(facet, 7);
  }
}
