// A sheet's quads made to carry the footprints of walls standing on it (quadmesh/footprint_insert.hpp): a strip
// inside the sheet, one running to its rim, two strips, a ring, feet on both sides (ribs crossing: merged), feet all
// round a boss's tube (the gap a ring), and a foot off the sheet (refused); on a 60 x 40 grid of 2 mm quads in the
// plane z = 1 and on copies scaled by 1e-3 and 1e3.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "chordal/chordal_locator.hpp"
#include "core/error.hpp"
#include "quadmesh/footprint_insert.hpp"
#include "quadmesh/quad_smoothing.hpp"

using namespace hexlayer;

namespace {

constexpr double kL = 60, kW = 40, kQuad = 2;

// The sheet: nx x ny quads over [0, L] x [0, W] at z = 1, scaled by s; its chordal surface the same grid's
// triangles.
struct Sheet {
  QuadMesh quads;
  ChordalSurface chordal;
};

Sheet gridSheet(double s) {
  Sheet g;
  const int nx = static_cast<int>(kL / kQuad), ny = static_cast<int>(kW / kQuad);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) g.quads.nodes.push_back(s * Vec3(i * kQuad, j * kQuad, 1));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      g.quads.quads.push_back({a, a + 1, a + nx + 2, a + nx + 1});
      g.chordal.facets.push_back({a, a + 1, a + nx + 2, -1});
      g.chordal.facets.push_back({a, a + nx + 2, a + nx + 1, -1});
    }
  g.chordal.vertices = g.quads.nodes;
  g.chordal.normals.assign(g.chordal.vertices.size(), Vec3::UnitZ());
  g.chordal.radius.assign(g.chordal.vertices.size(), s);
  return g;
}

// A strip from (x0, y) to (x1, y), `rows` quads across its width w and `columns` along, at z = 1, scaled by s.
void addStrip(FootprintQuads& f, double x0, double x1, double y, double w, int rows, int columns, double s) {
  const int first = static_cast<int>(f.nodes.size());
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j <= columns; ++j)
      f.nodes.push_back(s * Vec3(x0 + (x1 - x0) * j / columns, y - w / 2 + w * i / rows, 1));
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      const int a = first + i * (columns + 1) + j;
      f.quads.push_back({a, a + 1, a + columns + 2, a + columns + 1});
    }
}

// A strip standing on the far side of the strip addStrip put first in f (sideRows x sideColumns quads): its end the
// side's nodes from .. from + rows, `columns` quads of length l along the direction at `angle` degrees to the side
// (parallelograms), scaled by s.
void addObliqueStrip(FootprintQuads& f, int sideColumns, int sideRows, int from, int rows, int columns, double l,
                     double angle, double s) {
  const int first = static_cast<int>(f.nodes.size()), side = sideRows * (sideColumns + 1) + from;
  const Vec3 along = s * l * Vec3(std::cos(angle * M_PI / 180), std::sin(angle * M_PI / 180), 0);
  for (int j = 1; j <= columns; ++j)
    for (int i = 0; i <= rows; ++i) f.nodes.push_back(f.nodes[side + i] + j * along);
  auto node = [&](int i, int j) { return j == 0 ? side + i : first + (j - 1) * (rows + 1) + i; };
  for (int j = 0; j < columns; ++j)
    for (int i = 0; i < rows; ++i) f.quads.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
}

// A ring round (cx, cy): radii r0..r1 in `rows` quads, `around` quads round it.
void addRing(FootprintQuads& f, double cx, double cy, double r0, double r1, int rows, int around, double s) {
  const int first = static_cast<int>(f.nodes.size());
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j < around; ++j) {
      const double r = r0 + (r1 - r0) * i / rows, a = 2 * M_PI * j / around;
      f.nodes.push_back(s * Vec3(cx + r * std::cos(a), cy + r * std::sin(a), 1));
    }
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < around; ++j)
      f.quads.push_back({first + i * around + j, first + i * around + (j + 1) % around,
                         first + (i + 1) * around + (j + 1) % around, first + (i + 1) * around + j});
}

// Every footprint node is a node of the quads where it was, and every footprint quad is one of them.
void expectFootprintIn(const FootprintInsertion& in, const FootprintQuads& f) {
  ASSERT_EQ(in.node.size(), f.nodes.size());
  for (std::size_t n = 0; n < f.nodes.size(); ++n) EXPECT_NEAR((in.quads.nodes[in.node[n]] - f.nodes[n]).norm(), 0, 0);
  std::map<std::array<int, 4>, int> quads;
  for (auto q : in.quads.quads) std::sort(q.begin(), q.end()), ++quads[q];
  for (const auto& q : f.quads) {
    std::array<int, 4> mapped{in.node[q[0]], in.node[q[1]], in.node[q[2]], in.node[q[3]]};
    std::sort(mapped.begin(), mapped.end());
    EXPECT_EQ(quads[mapped], 1);
  }
}

// The quads tile the sheet's rectangle once, conformal: every edge in one or two quads, the edges in one its
// perimeter, the quads' area its area, each quad's scaled Jacobian (turned the sheet's way) at least `worst`; the
// footprint in them (expectFootprintIn).
void expectCarried(const FootprintInsertion& in, const FootprintQuads& f, double s, double worst) {
  std::map<std::pair<int, int>, int> uses;
  double area = 0, least = 1;
  for (const auto& q : in.quads.quads) {
    std::array<Vec3, 4> c;
    for (int k = 0; k < 4; ++k) c[k] = in.quads.nodes[q[k]], ++uses[std::minmax(q[k], q[(k + 1) % 4])];
    const Vec3 normal = (c[2] - c[0]).cross(c[3] - c[1]);
    area += 0.5 * std::abs(normal.z());
    if (normal.z() < 0) std::swap(c[1], c[3]);
    least = std::min(least, quadScaledJacobian(c));
  }
  double perimeter = 0;
  for (const auto& [e, n] : uses) {
    EXPECT_LE(n, 2);
    if (n == 1) perimeter += (in.quads.nodes[e.first] - in.quads.nodes[e.second]).norm();
  }
  EXPECT_NEAR(perimeter, 2 * (kL + kW) * s, 1e-9 * s);
  EXPECT_NEAR(area, kL * kW * s * s, 1e-9 * s * s);
  EXPECT_GE(least, worst);
  expectFootprintIn(in, f);
  EXPECT_GT(in.quadsRemoved, 0u);
  EXPECT_GT(in.quadsMeshed, 0u);
}

template <class Add>
void expectInserted(Add add, double worst) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const Sheet g = gridSheet(s);
    const ChordalLocator locator(g.chordal);
    FootprintQuads f;
    add(f, s);
    expectCarried(insertFootprints(g.quads, f, locator, kQuad * s), f, s, worst);
  }
}

}  // namespace

// A rib's foot inside the sheet: 2 rows across its 2 mm, 17 quads along 10..44 (off the sheet's grid lines).
TEST(FootprintInsert, AStripInsideTheSheet) {
  expectInserted([](FootprintQuads& f, double s) { addStrip(f, 10.3, 44.3, 20.5, 2, 2, 17, s); }, 0.3);
}

// A rib running to the sheet's rim at both ends, thinner than the quads (1 mm in 3 rows).
TEST(FootprintInsert, AStripFromRimToRim) {
  expectInserted([](FootprintQuads& f, double s) { addStrip(f, 0, kL, 13.7, 1, 3, 40, s); }, 0.3);
}

// A rib to the rim whose sides lie on the sheet's grid lines: the sheet's rim nodes there are the foot's corners.
TEST(FootprintInsert, AStripOnTheSheetsGridLines) {
  expectInserted([](FootprintQuads& f, double s) { addStrip(f, 0, kL, 21, 2, 2, 20, s); }, 0.3);
}

// Two ribs, one to the rim, near enough that their gaps merge.
TEST(FootprintInsert, TwoStripsShareAGap) {
  expectInserted(
      [](FootprintQuads& f, double s) {
        addStrip(f, 0, 40, 10, 2, 2, 20, s);
        addStrip(f, 20, 50, 13.5, 2, 2, 15, s);
      },
      0.2);
}

// A boss's foot: a ring of 2 rows, 24 quads round; the sheet's quads inside it are meshed again too.
TEST(FootprintInsert, ARing) {
  expectInserted([](FootprintQuads& f, double s) { addRing(f, 30, 20, 4, 6, 2, 24, s); }, 0.3);
}

// Ribs crossing at 45 degrees: a strip standing on another's side at 45 degrees, its end three of that side's nodes
// (2 mm across, 2.83 mm along the side), its quads 2.33 mm long. In the 45-degree wedge between the two, Blossom left
// two triangles (the wedge's tip and the next one along the side) that were paired into a quad with three boundary
// nodes in a line (folded, every try): the wedge gets a quad of its own, and a poor quad is split anew with a
// neighbour.
TEST(FootprintInsert, AStripAt45DegreesOnAnother) {
  constexpr double kAlong = M_SQRT2;  // the first strip's quads' length: the second's end is two of them
  expectInserted(
      [](FootprintQuads& f, double s) {
        addStrip(f, 10.3, 10.3 + 30 * kAlong, 20.5, 2, 2, 30, s);
        addObliqueStrip(f, 30, 2, 7, 2, 6, 2.33, 45, s);
      },
      0.3);
}

// A boss's chordal tube (radius 3, 10 high, 12 quads round, 6 up) with four gussets standing on it all round (feet 2
// wide in `rows` rows, 4 quads up from its lower rim to 6 high, one every 90 degrees): the gaps round the feet meet
// into the whole tube, a ring (two rims) that unfolds onto a flat annulus, not a disc. The quads tile the tube once,
// conformal, with its two rims as boundary (their length as before, give or take the feet's corners on the circle),
// carry every foot's node and quad, none folded; at scales 1, 1e-3 and 1e3, with 2 and 3 rows.
TEST(FootprintInsert, FeetAllRoundATube) {
  constexpr double kR = 3, kH = 10, kFoot = 2, kFootHigh = 6;
  constexpr int kAround = 12, kUp = 6, kFeet = 4, kFootUp = 4;
  for (const int rows : {2, 3})
    for (const double s : {1.0, 1e-3, 1e3}) {
      SCOPED_TRACE("rows " + std::to_string(rows) + " x " + std::to_string(s));
      auto onTube = [&](double angle, double z) -> Vec3 {
        return s * Vec3(kR * std::cos(angle), kR * std::sin(angle), z);
      };
      Sheet tube;
      for (int j = 0; j <= kUp; ++j)
        for (int i = 0; i < kAround; ++i) tube.quads.nodes.push_back(onTube(2 * M_PI * i / kAround, kH * j / kUp));
      for (int j = 0; j < kUp; ++j)
        for (int i = 0; i < kAround; ++i) {
          const int a = j * kAround + i, b = j * kAround + (i + 1) % kAround;
          tube.quads.quads.push_back({a, b, b + kAround, a + kAround});
          tube.chordal.facets.push_back({a, b, b + kAround, -1});
          tube.chordal.facets.push_back({a, b + kAround, a + kAround, -1});
        }
      tube.chordal.vertices = tube.quads.nodes;
      for (const Vec3& v : tube.chordal.vertices) tube.chordal.normals.push_back(Vec3(v.x(), v.y(), 0).normalized());
      tube.chordal.radius.assign(tube.chordal.vertices.size(), s);
      FootprintQuads f;
      for (int k = 0; k < kFeet; ++k) {
        const double middle = 2 * M_PI * (k + 0.3) / kFeet, half = 0.5 * kFoot / kR;  // off the tube's grid lines
        const int first = static_cast<int>(f.nodes.size());
        for (int j = 0; j <= kFootUp; ++j)
          for (int i = 0; i <= rows; ++i)
            f.nodes.push_back(onTube(middle - half + 2 * half * i / rows, kFootHigh * j / kFootUp));
        for (int j = 0; j < kFootUp; ++j)
          for (int i = 0; i < rows; ++i) {
            const int a = first + j * (rows + 1) + i;
            f.quads.push_back({a, a + 1, a + rows + 2, a + rows + 1});
          }
      }
      const ChordalLocator locator(tube.chordal);
      const FootprintInsertion in = insertFootprints(tube.quads, f, locator, 1.6 * s);
      std::map<std::pair<int, int>, int> uses;
      for (const auto& q : in.quads.quads)
        for (int k = 0; k < 4; ++k) ++uses[std::minmax(q[k], q[(k + 1) % 4])];
      double rims = 0;
      for (const auto& [e, n] : uses) {
        EXPECT_LE(n, 2);
        if (n == 1) rims += (in.quads.nodes[e.first] - in.quads.nodes[e.second]).norm();
      }
      const double polygon = 2 * kAround * 2 * kR * std::sin(M_PI / kAround) * s;  // both rims, as the tube's quads
      EXPECT_NEAR(rims / polygon, 1, 0.01);
      EXPECT_GT(in.worstQuad, 0.2);
      expectFootprintIn(in, f);
    }
}

// A foot that runs off the sheet is refused.
TEST(FootprintInsert, AFootOffTheSheetIsRefused) {
  const Sheet g = gridSheet(1);
  const ChordalLocator locator(g.chordal);
  FootprintQuads f;
  addStrip(f, 50, 70, 20, 2, 2, 10, 1);
  try {
    insertFootprints(g.quads, f, locator, kQuad);
    FAIL() << "not refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::UnsupportedGeometry);
    EXPECT_NE(std::string(e.what()).find("junction"), std::string::npos) << e.what();
  }
}

// Ribs crossing the sheet: feet on both its walls at one place, alike (the other's nodes, moved along the sheet by
// 0.6 mm: an oblique crossing), are one footprint, each node at the middle of its pair; the sheet carries it. Feet
// that overlap but are not alike (another column count) stay two, and the sheet refuses them, naming the crossing.
TEST(FootprintInsert, FeetOnBothSidesAreOne) {
  for (double s : {1.0, 1e-3, 1e3}) {
    SCOPED_TRACE("x " + std::to_string(s));
    const Sheet g = gridSheet(s);
    const ChordalLocator locator(g.chordal);
    FootprintQuads f;
    addStrip(f, 10.3, 30.3, 20.5, 2, 2, 10, s);
    addStrip(f, 10.9, 30.9, 20.5, 2, 2, 10, s);
    const std::size_t half = f.nodes.size() / 2;
    const MergedFootprints m = mergeFeetOnBothSides(f, locator);
    ASSERT_EQ(m.footprint.nodes.size(), half);
    EXPECT_EQ(m.footprint.quads.size(), f.quads.size() / 2);
    EXPECT_NEAR(m.shift, 0.3 * s, 1e-9 * s);
    for (std::size_t n = 0; n < half; ++n) {
      EXPECT_EQ(m.node[n], m.node[n + half]);
      EXPECT_NEAR((m.footprint.nodes[m.node[n]] - 0.5 * (f.nodes[n] + f.nodes[n + half])).norm(), 0, 1e-9 * s);
    }
    expectCarried(insertFootprints(g.quads, m.footprint, locator, kQuad * s), m.footprint, s, 0.3);

    FootprintQuads unlike;
    addStrip(unlike, 10.3, 30.3, 20.5, 2, 2, 10, s);
    addStrip(unlike, 10.9, 30.9, 20.5, 2, 2, 11, s);
    const MergedFootprints two = mergeFeetOnBothSides(unlike, locator);
    EXPECT_EQ(two.footprint.nodes.size(), unlike.nodes.size());
    EXPECT_EQ(two.shift, 0);
    try {
      insertFootprints(g.quads, two.footprint, locator, kQuad * s);
      ADD_FAILURE() << "not refused";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::UnsupportedGeometry);
      EXPECT_NE(std::string(e.what()).find("both sides"), std::string::npos) << e.what();
    }
  }
}
