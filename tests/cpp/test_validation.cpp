// Validation of a finished hex mesh (quality/validation.hpp): the checks that refuse a mesh (inverted hexes,
// conformity, watertight boundary, volume against the CAD, repeated nodes, a hole the part does not have), each named
// with its place.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "quality/quality.hpp"
#include "quality/validation.hpp"
#include "test_hex_blocks.hpp"

using namespace hexlayer;
using hexlayer::test_hex_blocks::block;
using hexlayer::test_hex_blocks::box;
using hexlayer::test_hex_blocks::singleHex;

namespace {

std::vector<ValidationFailure> validate(const HexMesh& m, double cadVolume, std::optional<long> cadEuler = {}) {
  return validateMesh(m, measureQuality(m), checkBoundary(m), cadVolume, cadEuler);
}

// The failure of that check in `failures` (which must outlive the pointer), or nullptr.
const ValidationFailure* find(const std::vector<ValidationFailure>& failures, const std::string& check) {
  for (const ValidationFailure& f : failures)
    if (f.check == check) return &f;
  return nullptr;
}

}  // namespace

TEST(Validation, BlockOfGoodHexesPasses) { EXPECT_TRUE(validate(block({0, 1, 2}, {0, 1}, {0, 0.5, 1}), 2.0).empty()); }

TEST(Validation, InvertedHexIsNamedWithItsPlace) {
  HexMesh m = singleHex(box(2, 1, 1));
  std::swap(m.nodes[1], m.nodes[3]);  // mirrored: every corner inverted, volume -2
  const auto failures = validate(m, 2.0);
  const ValidationFailure* f = find(failures, "inverted");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->count, 1u);
  ASSERT_TRUE(f->at);
  EXPECT_TRUE(f->at->isApprox(Vec3(1, 0.5, 0.5)));  // the mirrored box's centroid
  EXPECT_EQ(f->message, "inverted: 1 inverted hexes (scaled Jacobian <= 0), the worst at (1, 0.5, 0.5)");
  EXPECT_NE(find(failures, "volume"), nullptr);  // -2 against +2
}

TEST(Validation, DuplicateNodesAreNotConformal) {
  HexMesh m = singleHex(box(1, 1, 1));
  for (int i = 0; i < 8; ++i) m.nodes.push_back(m.nodes[i] + Vec3(1, 0, 0));
  m.hexes.push_back({8, 9, 10, 11, 12, 13, 14, 15});
  const auto failures = validate(m, 2.0);
  ASSERT_EQ(failures.size(), 1u);  // two closed shells of good hexes, the right volume
  EXPECT_EQ(failures[0].check, "conformal");
  EXPECT_EQ(failures[0].count, 4u);
  EXPECT_TRUE(failures[0].at->isApprox(Vec3(1, 0, 0)));  // node 8, the first to close a pair (with node 1)
}

// Two blocks face to face at x = 1, not joined: a hex 1 x 1 x 1 and beside it 2 x 2 hexes 1 x 0.7 x 0.7 from y, z =
// -0.2 (no node of one at a node of the other, each block closed, so every other check passes): the hex's face on
// x = 1 and the 4 beside it lie face to face, refused as not joined, named at the first; the blocks 0.1 apart (a slit
// narrower than a hex, as a flexure's) pass; so does a plate 60 x 40 x 2 of two hexes, one on the other (its two wide
// walls 2 apart, under 5 % of a face's size but as deep as its hexes).
TEST(Validation, PiecesFaceToFaceNotJoinedAreRefused) {
  EXPECT_TRUE(validate(block({0, 60}, {0, 40}, {0, 1, 2}), 4800).empty());
  for (const double gap : {0.0, 0.1}) {
    SCOPED_TRACE("gap " + std::to_string(gap));
    HexMesh m = block({0, 1}, {0, 1}, {0, 1});
    const HexMesh beside = block({1 + gap, 2 + gap}, {-0.2, 0.5, 1.2}, {-0.2, 0.5, 1.2});
    const int first = static_cast<int>(m.nodes.size());
    m.nodes.insert(m.nodes.end(), beside.nodes.begin(), beside.nodes.end());
    for (auto h : beside.hexes) {
      for (int& v : h) v += first;
      m.hexes.push_back(h);
    }
    const auto failures = validate(m, 1 + 1.4 * 1.4);
    if (gap > 0) {
      EXPECT_TRUE(failures.empty());
      continue;
    }
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_EQ(failures[0].check, "joined");
    EXPECT_EQ(failures[0].count, 5u);
    ASSERT_TRUE(failures[0].at);
    EXPECT_DOUBLE_EQ(failures[0].at->x(), 1.0);
  }
}

// A hex 1 x 1 x 1 and beside it, not joined, a hex whose face on x = 1 is folded along its diagonal (one corner moved
// 0.9 off the plane, as a wall's quad with two opposite corners put on a sharp edge, half of it on either face): the
// cube's face on x = 1 lies on the folded face's half on the plane, not on its mean plane (28 degrees off), and is
// refused as not joined (fails before: the faces were compared along their mean planes only).
TEST(Validation, AFaceLyingOnHalfOfAFoldedFaceIsNotJoined) {
  HexMesh m = block({0, 1}, {0, 1}, {0, 1});
  HexMesh beside = block({1, 2}, {0.1, 1.3}, {-0.3, 0.9});
  for (Vec3& p : beside.nodes)
    if (p.isApprox(Vec3(1, 1.3, -0.3))) p.x() = 1.9;  // the half (y, z) above z = y - 0.4 stays on x = 1
  const int first = static_cast<int>(m.nodes.size());
  m.nodes.insert(m.nodes.end(), beside.nodes.begin(), beside.nodes.end());
  for (auto h : beside.hexes) {
    for (int& v : h) v += first;
    m.hexes.push_back(h);
  }
  double volume = 0;
  for (std::size_t h = 0; h < m.hexes.size(); ++h) volume += hexVolume(hexCorners(m, h));
  const auto failures = validate(m, volume);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].check, "joined");
  EXPECT_EQ(failures[0].count, 1u);
  ASSERT_TRUE(failures[0].at);
  EXPECT_TRUE(failures[0].at->isApprox(Vec3(1, 0.5, 0.5)));  // the cube's face
}

TEST(Validation, OpenBoundaryIsNotWatertight) {
  HexMesh m = block({0, 1, 2}, {0, 1}, {0, 1});
  m.hexes.push_back(m.hexes[1]);  // the face x=1 used three times: hex 0 is an open box
  const auto failures = validate(m, 3.0);
  const ValidationFailure* f = find(failures, "watertight");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->count, 4u);
  EXPECT_DOUBLE_EQ(f->at->x(), 1.0);  // an edge of the x=1 face
  EXPECT_NE(f->message.find("(4 open, 0 non-manifold, 0 flipped)"), std::string::npos) << f->message;
}

TEST(Validation, VolumeFarFromTheCadIsRefused) {
  const HexMesh m = block({0, 1}, {0, 1}, {0, 1});
  EXPECT_TRUE(validate(m, 1.04).empty());  // within 5 %
  const auto failures = validate(m, 1.25);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].check, "volume");
  EXPECT_FALSE(failures[0].at);
  EXPECT_EQ(failures[0].message, "volume: the mesh's 1 differs from the CAD's 1.25 by -20 % (at most 5 %)");
}

TEST(Validation, ElementWithARepeatedNodeIsNotAHex) {
  HexMesh m = singleHex(box(1, 1, 1));
  m.hexes[0][7] = 4;  // a wedge written as a hex
  const auto failures = validate(m, 1.0);
  const ValidationFailure* f = find(failures, "hexes");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->count, 1u);
}

TEST(Validation, EmptyMeshFails) {
  const auto failures = validate(HexMesh{}, 1.0);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].check, "hexes");
}

// A ring of 8 hexes (3 x 3 without the middle one): its boundary is a torus (Euler characteristic 0). Where the part is
// a ring too it passes; where the part is a plain block (2) the mesh has a hole the part does not have: refused. A
// block where the part is a ring fills the part's hole: not refused here (the CLI warns).
TEST(Validation, AHoleThePartDoesNotHaveIsRefused) {
  const HexMesh full = block({0, 1, 2, 3}, {0, 1, 2, 3}, {0, 1});
  HexMesh ring = full;
  ring.hexes.erase(ring.hexes.begin() + 4);  // the middle one of the 3 x 3
  ASSERT_EQ(checkBoundary(ring).eulerCharacteristic, 0);
  EXPECT_TRUE(validate(ring, 8.0, 0).empty());
  EXPECT_TRUE(validate(ring, 8.0).empty());  // no Euler characteristic given: not compared
  const auto failures = validate(ring, 8.0, 2);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].check, "topology");
  EXPECT_EQ(failures[0].count, 1u);
  EXPECT_FALSE(failures[0].at);
  EXPECT_EQ(failures[0].message,
            "topology: the mesh has 1 hole(s) the part does not have (its boundary's Euler characteristic 0, the "
            "part's 2)");
  EXPECT_TRUE(validate(full, 9.0, 0).empty());
}

// An open boundary's Euler characteristic counts no hole: only the watertight check fails.
TEST(Validation, AnOpenBoundaryIsNotCountedAsAHole) {
  HexMesh m = block({0, 1, 2}, {0, 1}, {0, 1});
  m.hexes.push_back(m.hexes[1]);
  const auto failures = validate(m, 3.0, 100);
  EXPECT_NE(find(failures, "watertight"), nullptr);
  EXPECT_EQ(find(failures, "topology"), nullptr);
}
