// The whole meshing result written for another process (pipeline/result_file.hpp): a small hand-made result
// written, then its JSON index and binary arrays read back here, value for value.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "pipeline/report.hpp"
#include "pipeline/result_file.hpp"
#include "test_hex_blocks.hpp"

using namespace hexlayer;
using hexlayer::test_hex_blocks::twoHexBlock;
namespace fs = std::filesystem;

namespace {

// Two hexes side by side along x, one layer, scaled to coordinates with all their bits (0.1, 1/3, 1e-3); with
// two node sets, a surface group (their bottom faces), a chordal surface of a quad and a triangle, its quad mesh.
MeshResult smallResult() {
  MeshResult r;
  r.mesh = twoHexBlock();
  for (Vec3& p : r.mesh.nodes) p = p.cwiseProduct(Vec3(0.1, 1.0 / 3, 1e-3));
  r.nodeSets = {{"TOP", {6, 7, 8, 9, 10, 11}}, {"BOTTOM", {0, 1, 2, 3, 4, 5}}};
  r.surfaceGroups = {{"Face5", {0, 1, 2, 3, 4, 5}, {{0, 0}, {1, 0}}}};
  r.scaledJacobian = {1.0, 0.875};
  r.chordalSurface.vertices = {Vec3(0, 0, 0.5), Vec3(1, 0, 0.5), Vec3(1, 1, 0.5), Vec3(0, 1, 0.5), Vec3(2, 0, 0.5)};
  r.chordalSurface.facets = {{0, 1, 2, 3}, {1, 4, 2, -1}};
  r.quadMesh.nodes = {Vec3(0, 0, 0.5), Vec3(1, 0, 0.5), Vec3(1, 1, 0.5), Vec3(0, 1, 0.5)};
  r.quadMesh.quads = {{0, 1, 2, 3}};
  return r;
}

// The array `name` of the index, read from the binary file's bytes: its shape, and its values as doubles.
struct Array {
  std::vector<std::size_t> shape;
  std::vector<double> values;
};

Array readArray(const nlohmann::json& index, const std::string& bytes, const std::string& name) {
  const nlohmann::json& a = index.at("arrays").at(name);
  Array out;
  out.shape = a.at("shape").get<std::vector<std::size_t>>();
  std::size_t count = 1;
  for (std::size_t n : out.shape) count *= n;
  const std::size_t offset = a.at("offset").get<std::size_t>();
  EXPECT_LE(offset + 8 * count, bytes.size()) << name;
  for (std::size_t i = 0; i < count && offset + 8 * (i + 1) <= bytes.size(); ++i) {
    const char* at = bytes.data() + offset + 8 * i;
    if (a.at("dtype") == "<f8") {
      double v;
      std::memcpy(&v, at, 8);
      out.values.push_back(v);
    } else {
      EXPECT_EQ(a.at("dtype"), "<i8") << name;
      std::int64_t v;
      std::memcpy(&v, at, 8);
      out.values.push_back(static_cast<double>(v));
    }
  }
  return out;
}

// The rows (points, cells) one after the other, as doubles.
template <class Rows>
std::vector<double> rowByRow(const Rows& rows) {
  std::vector<double> v;
  for (const auto& row : rows)
    for (const auto x : row) v.push_back(x);
  return v;
}

template <class T>
std::vector<double> asDoubles(const std::vector<T>& x) {
  return std::vector<double>(x.begin(), x.end());
}

// A fresh folder for one test's files, named after the test.
fs::path freshFolder() {
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("hexlayer_result_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(ResultFile, WrittenArraysReadBackEqual) {
  const fs::path dir = freshFolder();
  const MeshResult r = smallResult();
  const fs::path path = dir / "part.json";
  writeResult(path.string(), r);
  ASSERT_TRUE(fs::exists(path));
  ASSERT_TRUE(fs::exists(dir / "part.json.bin"));
  const nlohmann::json index = nlohmann::json::parse(readBytes(path));
  EXPECT_EQ(index.at("binary"), "part.json.bin") << "the binary's name, beside the index";
  EXPECT_EQ(index.at("report").dump(), toJson(r.report).dump()) << "as text: a NaN is written as null";
  const std::string bytes = readBytes(dir / "part.json.bin");

  struct Expected {
    std::string name;
    std::vector<std::size_t> shape;
    std::vector<double> values;
  };
  const std::vector<Expected> expected = {
      {"nodes", {12, 3}, rowByRow(r.mesh.nodes)},
      {"hexes", {2, 8}, rowByRow(r.mesh.hexes)},
      {"scaled_jacobian", {2}, r.scaledJacobian},
      {"node_sets/TOP", {6}, asDoubles(r.nodeSets[0].nodes)},
      {"node_sets/BOTTOM", {6}, asDoubles(r.nodeSets[1].nodes)},
      {"face_nodes/Face5", {6}, asDoubles(r.surfaceGroups[0].nodes)},
      {"face_elements/Face5", {2, 2}, {0, 0, 1, 0}},
      {"chordal_vertices", {5, 3}, rowByRow(r.chordalSurface.vertices)},
      {"chordal_facets", {2, 4}, {0, 1, 2, 3, 1, 4, 2, -1}},
      {"quad_nodes", {4, 3}, rowByRow(r.quadMesh.nodes)},
      {"quads", {1, 4}, {0, 1, 2, 3}},
      {"node_layer", {12}, asDoubles(r.mesh.nodeLayer)},
  };
  EXPECT_EQ(index.at("arrays").size(), expected.size());
  std::size_t total = 0;
  for (const Expected& e : expected) {
    SCOPED_TRACE(e.name);
    ASSERT_TRUE(index.at("arrays").contains(e.name));
    const Array a = readArray(index, bytes, e.name);
    EXPECT_EQ(a.shape, e.shape);
    EXPECT_EQ(a.values, e.values) << "to the last bit";
    total += 8 * e.values.size();
  }
  EXPECT_EQ(index["arrays"]["nodes"]["dtype"], "<f8");
  EXPECT_EQ(index["arrays"]["hexes"]["dtype"], "<i8");
  EXPECT_EQ(bytes.size(), total) << "the arrays and nothing else";
  fs::remove_all(dir);
}

// 20-node hexes: each row holds the 8 corners, then the 12 mid-edge nodes.
TEST(ResultFile, QuadraticHexRowsHaveTwentyNodes) {
  const fs::path dir = freshFolder();
  MeshResult r = smallResult();
  for (int h = 0; h < 2; ++h) {
    std::array<int, 12> mid;
    for (int k = 0; k < 12; ++k) mid[k] = 100 + 12 * h + k;
    r.mesh.midEdges.push_back(mid);
  }
  const fs::path path = dir / "quadratic.json";
  writeResult(path.string(), r);
  const nlohmann::json index = nlohmann::json::parse(readBytes(path));
  const Array hexes = readArray(index, readBytes(dir / "quadratic.json.bin"), "hexes");
  ASSERT_EQ(hexes.shape, (std::vector<std::size_t>{2, 20}));
  for (int h = 0; h < 2; ++h)
    for (int k = 0; k < 20; ++k)
      EXPECT_EQ(hexes.values[20 * h + k], k < 8 ? r.mesh.hexes[h][k] : r.mesh.midEdges[h][k - 8]) << h << ", " << k;
  fs::remove_all(dir);
}

TEST(ResultFile, UnwritablePathIsInputError) {
  const fs::path dir = freshFolder();
  try {
    writeResult((dir / "no_such_folder" / "part.json").string(), smallResult());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::BadInput);
  }
  fs::remove_all(dir);
}
