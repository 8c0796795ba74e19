// Writers (writers/writers.hpp): each format is read back by another program (Gmsh API, meshio) or parsed as
// CalculiX would.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "quality/quality.hpp"
#include "sweep/quadratic.hpp"
#include "test_hex_blocks.hpp"
#include "writers/writers.hpp"

using namespace hexlayer;
using hexlayer::test_hex_blocks::twoHexBlock;
namespace fs = std::filesystem;

namespace {

std::vector<NodeSet> layerSets(const HexMesh& m) {
  std::vector<NodeSet> sets{{"TOP", {}}, {"bottom", {}}};
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    sets[m.nodeLayer[i] == 1 ? 0 : 1].nodes.push_back(static_cast<int>(i));
  return sets;
}

// Surface groups of the block as the CAD box 2 x 1 x 1 numbers its faces (BRepPrimAPI_MakeBox, FreeCAD's
// Part box): Face1 x = 0, Face2 x = 2, Face3 y = 0, Face4 y = 1, Face5 z = 0, Face6 z = 1; plus an empty Face7.
std::vector<SurfaceGroup> boxSurfaces(const HexMesh& m) {
  std::vector<SurfaceGroup> groups;
  const std::array<std::pair<int, double>, 6> planes = {{{0, 0}, {0, 2}, {1, 0}, {1, 1}, {2, 0}, {2, 1}}};
  for (std::size_t g = 0; g < planes.size(); ++g) {
    const auto [axis, value] = planes[g];
    auto on = [&, axis = axis, value = value](int n) { return m.nodes[n][axis] == value; };
    SurfaceGroup group{"Face" + std::to_string(g + 1), {}, {}};
    for (std::size_t n = 0; n < m.nodes.size(); ++n)
      if (on(static_cast<int>(n))) group.nodes.push_back(static_cast<int>(n));
    for (std::size_t h = 0; h < m.hexes.size(); ++h)
      for (int f = 0; f < 6; ++f)
        if (std::all_of(kHexFaces[f].begin(), kHexFaces[f].end(), [&](int c) { return on(m.hexes[h][c]); }))
          group.hexFaces.push_back({static_cast<int>(h), f});
    groups.push_back(group);
  }
  groups.push_back({"Face7", {}, {}});
  return groups;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Data lines of the keyword block starting with `keyword` (up to the next line starting with '*').
std::vector<std::string> inpBlock(const std::vector<std::string>& all, const std::string& keyword) {
  std::vector<std::string> out;
  bool in = false;
  for (const std::string& l : all) {
    if (!l.empty() && l[0] == '*')
      in = l.rfind(keyword, 0) == 0;
    else if (in)
      out.push_back(l);
  }
  return out;
}

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f.substr(f.find_first_not_of(' ')));
  return out;
}

// The block with 20-node hexes: its 20 edges get a node each at their midpoints (ids 12..31).
HexMesh quadratic(HexMesh m) {
  addMidEdgeNodes(m, [](Side, const Vec3&) { return std::nullopt; });
  return m;
}

// Runs `/usr/bin/python3 script file` and expects exit status 0.
void expectPythonPasses(const fs::path& script, const fs::path& file) {
  const std::string command = "/usr/bin/python3 '" + script.string() + "' '" + file.string() + "'";
  const int status = std::system(command.c_str());
  ASSERT_NE(status, -1);
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << command;
}

// Elements of each physical group (by name) of the model Gmsh has open.
std::map<std::string, std::size_t> elementsPerPhysicalGroup() {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::map<std::string, std::size_t> elements;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    std::vector<int> entities, types;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    std::vector<std::vector<std::size_t>> elementTags, elementNodes;
    for (int e : entities) {
      gmsh::model::mesh::getElements(types, elementTags, elementNodes, dim, e);
      for (const auto& t : elementTags) elements[name] += t.size();
    }
  }
  return elements;
}

ExitCode codeOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  return ExitCode::Ok;
}

class Writers : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hexlayer_writer_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    mesh_ = twoHexBlock();
    sets_ = layerSets(mesh_);
    fields_ = {{"scaled_jacobian", measureQuality(mesh_).scaledJacobian}, {"hex_id", {1.5, 2.5}}};
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name) {
    const fs::path p = dir_ / name;
    writeMesh(p.string(), mesh_, {sets_, surfaces_, fields_});
    return p;
  }

  fs::path dir_;
  HexMesh mesh_;
  std::vector<NodeSet> sets_;
  std::vector<SurfaceGroup> surfaces_;
  std::vector<CellField> fields_;
};

}  // namespace

TEST_F(Writers, MshReadsBackThroughGmsh) {
  const fs::path p = write("block.msh");
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(p.string());

  std::vector<std::size_t> nodeTags;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(nodeTags, coords, params);
  EXPECT_EQ(nodeTags.size(), 12u);
  for (std::size_t i = 0; i < nodeTags.size(); ++i)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(coords[3 * i + d], mesh_.nodes[nodeTags[i] - 1][d]);

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elementTags, elementNodes;
  gmsh::model::mesh::getElements(types, elementTags, elementNodes, 3);
  ASSERT_EQ(types, std::vector<int>{5});
  ASSERT_EQ(elementTags[0].size(), 2u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(elementNodes[0][i], static_cast<std::size_t>(mesh_.hexes[0][i] + 1));
  gmsh::model::mesh::getElements(types, elementTags, elementNodes, 2);
  std::size_t quads = 0;
  for (std::size_t t = 0; t < types.size(); ++t) {
    EXPECT_EQ(types[t], 3);
    quads += elementTags[t].size();
  }
  EXPECT_EQ(quads, 10u);

  const std::map<std::string, std::size_t> expected{{"top", 2}, {"bottom", 2}, {"rim", 6}, {"solid", 2}};
  EXPECT_EQ(elementsPerPhysicalGroup(), expected);

  std::vector<int> views;
  gmsh::view::getTags(views);
  EXPECT_EQ(views.size(), 2u);  // one $ElementData per cell field
  gmsh::finalize();
}

TEST_F(Writers, MshOmitsEmptySurfacesAndPutsAllQuadsInRimWithoutLayers) {
  mesh_.nodeLayer.clear();
  const std::string text = readText(write("nolayers.msh"));
  EXPECT_NE(text.find("2 3 \"rim\""), std::string::npos);
  EXPECT_EQ(text.find("\"top\""), std::string::npos);
  EXPECT_EQ(text.find("\"bottom\""), std::string::npos);
  EXPECT_NE(text.find("\n2 1 3 10\n"), std::string::npos);  // one block of 10 quads in surface entity 1 (physical 3)
}

TEST_F(Writers, MshHasOnePhysicalGroupPerCadFaceReadBackThroughGmsh) {
  surfaces_ = boxSurfaces(mesh_);
  const fs::path p = write("faces.msh");
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(p.string());
  const std::map<std::string, std::size_t> elementsPerGroup = elementsPerPhysicalGroup();
  gmsh::finalize();
  const std::map<std::string, std::size_t> expected{{"Face1", 1}, {"Face2", 1}, {"Face3", 2}, {"Face4", 2},
                                                    {"Face5", 2}, {"Face6", 2}, {"top", 2},   {"bottom", 2},
                                                    {"rim", 6},   {"solid", 2}};
  EXPECT_EQ(elementsPerGroup, expected) << "Face7 has no mesh faces: no group";
}

TEST_F(Writers, InpHasANodeSetAndAnElementFaceSurfacePerCadFace) {
  surfaces_ = boxSurfaces(mesh_);
  const std::vector<std::string> all = lines(readText(write("faces.inp")));
  EXPECT_EQ(inpBlock(all, "*NSET, NSET=FACE1"), (std::vector<std::string>{"1, 4, 7, 10"}));
  // CalculiX's C3D8 faces: S1 = 1-2-3-4 (bottom), S2 = 5-8-7-6 (top), S3 = 1-5-6-2 (y = 0), S4 = 2-6-7-3,
  // S5 = 3-7-8-4 (y = 1), S6 = 4-8-5-1 (x = 0 for hex 1, whose nodes 1, 4, 5, 8 are there).
  EXPECT_EQ(inpBlock(all, "*SURFACE, NAME=FACE1_S, TYPE=ELEMENT"), (std::vector<std::string>{"1, S6"}));
  EXPECT_EQ(inpBlock(all, "*SURFACE, NAME=FACE2_S, TYPE=ELEMENT"), (std::vector<std::string>{"2, S4"}));
  EXPECT_EQ(inpBlock(all, "*SURFACE, NAME=FACE3_S, TYPE=ELEMENT"), (std::vector<std::string>{"1, S3", "2, S3"}));
  EXPECT_EQ(inpBlock(all, "*SURFACE, NAME=FACE4_S, TYPE=ELEMENT"), (std::vector<std::string>{"1, S5", "2, S5"}));
  EXPECT_EQ(inpBlock(all, "*SURFACE, NAME=FACE5_S, TYPE=ELEMENT"), (std::vector<std::string>{"1, S1", "2, S1"}));
  EXPECT_EQ(inpBlock(all, "*SURFACE, NAME=FACE6_S, TYPE=ELEMENT"), (std::vector<std::string>{"1, S2", "2, S2"}));
  EXPECT_NE(std::find(all.begin(), all.end(), "** CAD face Face7 has no mesh faces"), all.end());
  EXPECT_EQ(inpBlock(all, "*NSET, NSET=FACE7"), std::vector<std::string>{});
}

TEST_F(Writers, VtuHasTheCadFaceOfEveryNode) {
  surfaces_ = boxSurfaces(mesh_);
  const fs::path p = write("faces.vtu");
  const fs::path script = dir_ / "check.py";
  // Every node of the block is on a face; a node on several gets the lowest N (x = 0 before z = 0 ...).
  std::ofstream(script)
      << "import sys, meshio\n"
         "m = meshio.read(sys.argv[1])\n"
         "assert list(m.point_data['cad_face']) == [1, 3, 2, 1, 4, 2] * 2, m.point_data['cad_face']\n";
  expectPythonPasses(script, p);
}

TEST_F(Writers, InpHasNodesC3D8IElementsAndNodeSets) {
  const std::vector<std::string> all = lines(readText(write("block.inp")));
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all[0], "*HEADING");
  const std::vector<std::string> nodes = inpBlock(all, "*NODE");
  ASSERT_EQ(nodes.size(), 12u);
  EXPECT_EQ(splitCommas(nodes[11]), (std::vector<std::string>{"12", "2", "1", "1"}));
  const std::vector<std::string> elements = inpBlock(all, "*ELEMENT, TYPE=C3D8I");
  ASSERT_EQ(elements.size(), 2u);
  EXPECT_EQ(elements[1], "2, 2, 3, 6, 5, 8, 9, 12, 11");
  EXPECT_NE(std::find(all.begin(), all.end(), "*NODE, NSET=NALL"), all.end());
  EXPECT_NE(std::find(all.begin(), all.end(), "*ELEMENT, TYPE=C3D8I, ELSET=EALL"), all.end());
  EXPECT_EQ(inpBlock(all, "*NSET, NSET=TOP"), (std::vector<std::string>{"7, 8, 9, 10, 11, 12"}));
  EXPECT_EQ(inpBlock(all, "*NSET, NSET=BOTTOM"), (std::vector<std::string>{"1, 2, 3, 4, 5, 6"}));
}

TEST_F(Writers, InpWrapsLongNodeSetsAt16Ids) {
  sets_ = {{"all nodes", {}}};
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i < 12; ++i) sets_[0].nodes.push_back(i);  // 36 ids
  const std::vector<std::string> set = inpBlock(lines(readText(write("long.inp"))), "*NSET, NSET=ALL_NODES");
  ASSERT_EQ(set.size(), 3u);
  EXPECT_EQ(splitCommas(set[0]).size(), 16u);
  EXPECT_EQ(splitCommas(set[2]).size(), 4u);
}

TEST_F(Writers, InpCoordinatesFitCalculiXTwentyCharacterFields) {
  for (Vec3& p : mesh_.nodes) p = -p * 1.2345678901234567e-5 - Vec3(1.0 / 3.0, 2e-300, 7e123);
  const std::vector<std::string> nodes = inpBlock(lines(readText(write("tiny.inp"))), "*NODE");
  ASSERT_EQ(nodes.size(), 12u);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::vector<std::string> f = splitCommas(nodes[i]);
    ASSERT_EQ(f.size(), 4u);
    for (int d = 0; d < 3; ++d) {
      EXPECT_LE(f[d + 1].size(), 20u) << f[d + 1];
      EXPECT_NEAR(std::stod(f[d + 1]), mesh_.nodes[i][d], 1e-12 * std::abs(mesh_.nodes[i][d]));
    }
  }
}

TEST_F(Writers, VtuLoadsInMeshio) {
  const fs::path p = write("Block.VTU");  // extension in any case
  const fs::path script = dir_ / "check.py";
  std::ofstream(script) << "import sys, meshio\n"
                           "m = meshio.read(sys.argv[1])\n"
                           "assert len(m.points) == 12, len(m.points)\n"
                           "hexes = m.cells_dict['hexahedron']\n"
                           "assert hexes.shape == (2, 8), hexes.shape\n"
                           "assert list(hexes[1]) == [1, 2, 5, 4, 7, 8, 11, 10], hexes[1]\n"
                           "assert list(m.point_data['layer']) == [0] * 6 + [1] * 6\n"
                           "assert list(m.point_data['TOP']) == [0] * 6 + [1] * 6\n"
                           "assert list(m.point_data['bottom']) == [1] * 6 + [0] * 6\n"
                           "assert list(m.cell_data['hex_id'][0]) == [1.5, 2.5]\n"
                           "assert list(m.cell_data['scaled_jacobian'][0]) == [1.0, 1.0]\n";
  expectPythonPasses(script, p);
}

TEST_F(Writers, InpWritesC3D20RWithAContinuationLine) {
  mesh_ = quadratic(mesh_);
  const std::vector<std::string> all = lines(readText(write("quadratic.inp")));
  ASSERT_EQ(inpBlock(all, "*NODE").size(), 32u);
  EXPECT_NE(std::find(all.begin(), all.end(), "*ELEMENT, TYPE=C3D20R, ELSET=EALL"), all.end());
  const std::vector<std::string> data = inpBlock(all, "*ELEMENT, TYPE=C3D20R");
  ASSERT_EQ(data.size(), 4u);  // 16 entries, then the other 5
  for (std::size_t h = 0; h < 2; ++h) {
    EXPECT_EQ(data[2 * h].back(), ',');
    EXPECT_EQ(splitCommas(data[2 * h]).size(), 16u);
    std::vector<std::string> ids = splitCommas(data[2 * h].substr(0, data[2 * h].size() - 1) + ", " + data[2 * h + 1]);
    ASSERT_EQ(ids.size(), 21u);
    EXPECT_EQ(ids[0], std::to_string(h + 1));
    for (int e = 0; e < 12; ++e) {
      const Vec3 mid = 0.5 * (mesh_.nodes[std::stoi(ids[1 + kHexEdges[e][0]]) - 1] +
                              mesh_.nodes[std::stoi(ids[1 + kHexEdges[e][1]]) - 1]);
      EXPECT_EQ(mesh_.nodes[std::stoi(ids[9 + e]) - 1], mid) << "hex " << h << " C3D20 node " << 9 + e;
    }
  }
}

TEST_F(Writers, VtuWritesQuadraticHexahedraThatMeshioReads) {
  mesh_ = quadratic(mesh_);
  const fs::path p = write("quadratic.vtu");
  EXPECT_NE(readText(p).find("25 25\n"), std::string::npos);  // VTK_QUADRATIC_HEXAHEDRON
  const fs::path script = dir_ / "check.py";
  std::ofstream(script) << R"(import sys, meshio, numpy
m = meshio.read(sys.argv[1])
assert len(m.points) == 32, len(m.points)
cells = m.cells_dict['hexahedron20']
assert cells.shape == (2, 20), cells.shape
edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
for c in cells:
    for e, (a, b) in enumerate(edges):
        assert numpy.allclose(m.points[c[8 + e]], (m.points[c[a]] + m.points[c[b]]) / 2), (c, e)
)";
  expectPythonPasses(script, p);
}

TEST_F(Writers, MshWrites20NodeHexesAnd8NodeQuadsInGmshOrder) {
  mesh_ = quadratic(mesh_);
  const fs::path p = write("quadratic.msh");
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(p.string());
  std::string name;
  int dim, order, nodes, primary;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(17, name, dim, order, nodes, local, primary);
  ASSERT_EQ(nodes, 20);
  std::vector<std::size_t> tags, hexNodes, quadTags, quadNodes, linearTags, linearNodes;  // fresh vectors per call
  gmsh::model::mesh::getElementsByType(17, tags, hexNodes);
  ASSERT_EQ(tags.size(), 2u);
  // Each node sits where Gmsh's reference node maps to on our box-shaped hexes (trilinear from the corners).
  auto at = [&](std::size_t tag) { return mesh_.nodes[tag - 1]; };
  for (std::size_t h = 0; h < 2; ++h)
    for (int i = 0; i < 20; ++i) {
      const double u = (local[3 * i] + 1) / 2, v = (local[3 * i + 1] + 1) / 2, w = (local[3 * i + 2] + 1) / 2;
      const std::size_t* c = &hexNodes[20 * h];
      const Vec3 bottom = (1 - v) * ((1 - u) * at(c[0]) + u * at(c[1])) + v * ((1 - u) * at(c[3]) + u * at(c[2]));
      const Vec3 top = (1 - v) * ((1 - u) * at(c[4]) + u * at(c[5])) + v * ((1 - u) * at(c[7]) + u * at(c[6]));
      EXPECT_EQ(at(c[i]), (1 - w) * bottom + w * top) << "hex " << h << " Gmsh node " << i;
    }
  gmsh::model::mesh::getElementsByType(16, quadTags, quadNodes);
  ASSERT_EQ(quadTags.size(), 10u);
  for (std::size_t q = 0; q < quadTags.size(); ++q)
    for (int i = 0; i < 4; ++i)
      EXPECT_EQ(at(quadNodes[8 * q + 4 + i]), 0.5 * (at(quadNodes[8 * q + i]) + at(quadNodes[8 * q + (i + 1) % 4])));
  gmsh::model::mesh::getElementsByType(5, linearTags, linearNodes);
  EXPECT_TRUE(linearTags.empty());
  gmsh::finalize();
}

TEST_F(Writers, OutputIsDeterministic) {
  for (const std::string ext : {".inp", ".vtu", ".msh"}) {
    const std::string a = readText(write("a" + ext)), b = readText(write("b" + ext));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b) << ext;
  }
}

TEST_F(Writers, UnknownExtensionIsUsageError) {
  EXPECT_EQ(codeOf([&] { write("block.stl"); }), ExitCode::BadUsage);
  EXPECT_EQ(codeOf([&] { write("block"); }), ExitCode::BadUsage);
  EXPECT_FALSE(fs::exists(dir_ / "block.stl"));
  try {
    write("block.stl");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("use .inp, .vtu or .msh"), std::string::npos);
  }
}

TEST_F(Writers, UnwritablePathIsInputError) {
  const std::string path = (dir_ / "missing_dir" / "block.inp").string();
  try {
    writeMesh(path, mesh_, {sets_, {}, {}});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::BadInput);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
}

TEST_F(Writers, CellFieldOfWrongSizeIsRejected) {
  fields_.push_back({"short", {1.0}});
  EXPECT_EQ(codeOf([&] { write("bad.vtu"); }), ExitCode::Internal);
}

namespace {

// Two unit squares side by side in z = 0 (corners 0-5), thickness 1 + x / 10 at every node; with `quadratic`
// the 7 mid-side nodes at their edges' midpoints (ids 6..12). RIM: every node but the shared edge's midpoint.
ShellMesh twoQuadShell(bool quadratic) {
  ShellMesh s;
  s.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  s.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  if (quadratic) {
    const std::array<std::array<int, 2>, 7> edges = {{{0, 1}, {1, 4}, {4, 3}, {3, 0}, {1, 2}, {2, 5}, {5, 4}}};
    for (const auto& [a, b] : edges) s.nodes.push_back(0.5 * (s.nodes[a] + s.nodes[b]));
    s.midSides = {{6, 7, 8, 9}, {10, 11, 12, 7}};
  }
  for (const Vec3& p : s.nodes) s.thickness.push_back(1 + p.x() / 10);
  NodeSet rim{"RIM", {}};
  for (int n = 0; n < static_cast<int>(s.nodes.size()); ++n)
    if (n != 7) rim.nodes.push_back(n);
  s.nodeSets = {rim};
  s.faces = {{"Face1", {0, 3, 9}, {}}, {"Face2", {2, 5, 11}, {}}};
  if (!quadratic) s.faces = {{"Face1", {0, 3}, {}}, {"Face2", {2, 5}, {}}};
  return s;
}

}  // namespace

TEST_F(Writers, ShellInpHasS8RNodalThicknessSectionAndFaceSets) {
  const ShellMesh shell = twoQuadShell(true);
  const fs::path p = dir_ / "shell.inp";
  writeShellMesh(p.string(), shell);
  const std::vector<std::string> all = lines(readText(p));
  EXPECT_EQ(inpBlock(all, "*NODE").size(), 13u);
  const std::vector<std::string> elements = inpBlock(all, "*ELEMENT, TYPE=S8R, ELSET=EALL");
  ASSERT_EQ(elements.size(), 2u);
  EXPECT_EQ(splitCommas(elements[1]), (std::vector<std::string>{"2", "2", "3", "6", "5", "11", "12", "13", "8"}));
  const std::vector<std::string> thickness = inpBlock(all, "*NODAL THICKNESS");
  ASSERT_EQ(thickness.size(), 13u);
  for (std::size_t i = 0; i < thickness.size(); ++i) {
    const std::vector<std::string> f = splitCommas(thickness[i]);
    EXPECT_EQ(f[0], std::to_string(i + 1));
    EXPECT_DOUBLE_EQ(std::stod(f[1]), shell.thickness[i]);
  }
  EXPECT_EQ(inpBlock(all, "*NSET, NSET=FACE2"), std::vector<std::string>{"3, 6, 12"});
  EXPECT_EQ(inpBlock(all, "*NSET, NSET=RIM").size(), 1u);
  EXPECT_NE(std::find(all.begin(), all.end(), "*SHELL SECTION, ELSET=EALL, MATERIAL=SHELL_MATERIAL, NODAL THICKNESS"),
            all.end());
}

TEST_F(Writers, ShellInpWritesS4ForLinearQuads) {
  const fs::path p = dir_ / "shell4.inp";
  writeShellMesh(p.string(), twoQuadShell(false));
  const std::vector<std::string> all = lines(readText(p));
  EXPECT_EQ(inpBlock(all, "*ELEMENT, TYPE=S4, ELSET=EALL"),
            (std::vector<std::string>{"1, 1, 2, 5, 4", "2, 2, 3, 6, 5"}));
  EXPECT_EQ(inpBlock(all, "*NODAL THICKNESS").size(), 6u);
}

TEST_F(Writers, ShellVtuHas8NodeQuadsAndThicknessThatMeshioReads) {
  const fs::path p = dir_ / "shell.vtu";
  writeShellMesh(p.string(), twoQuadShell(true));
  const fs::path script = dir_ / "check.py";
  std::ofstream(script) << R"(import sys, meshio, numpy
m = meshio.read(sys.argv[1])
cells = m.cells_dict['quad8']
assert cells.shape == (2, 8), cells.shape
for c in cells:
    for e in range(4):
        assert numpy.allclose(m.points[c[4 + e]], (m.points[c[e]] + m.points[c[(e + 1) % 4]]) / 2), (c, e)
assert numpy.allclose(m.point_data['thickness'], 1 + m.points[:, 0] / 10)
assert list(m.point_data['RIM']) == [1] * 7 + [0] + [1] * 5
assert list(m.point_data['cad_face'][[0, 2, 1]]) == [1, 2, 0]
)";
  expectPythonPasses(script, p);
}

TEST_F(Writers, ShellMshHasQuadsInTheShellGroupAndThicknessNodeData) {
  for (bool quadratic : {false, true}) {
    const ShellMesh shell = twoQuadShell(quadratic);
    const fs::path p = dir_ / (quadratic ? "shell8.msh" : "shell4.msh");
    writeShellMesh(p.string(), shell);
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(p.string());
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elementTags, elementNodes;
    gmsh::model::mesh::getElements(types, elementTags, elementNodes, 2);
    ASSERT_EQ(types, std::vector<int>{quadratic ? 16 : 3});
    EXPECT_EQ(elementTags[0].size(), 2u);
    EXPECT_EQ(elementsPerPhysicalGroup(), (std::map<std::string, std::size_t>{{"shell", 2}}));
    std::vector<int> views;
    gmsh::view::getTags(views);
    ASSERT_EQ(views.size(), 1u);
    std::string dataType;
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> data;
    double time;
    int components;
    gmsh::view::getModelData(views[0], 0, dataType, tags, data, time, components);
    EXPECT_EQ(dataType, "NodeData");
    ASSERT_EQ(tags.size(), shell.nodes.size());
    for (std::size_t i = 0; i < tags.size(); ++i) EXPECT_DOUBLE_EQ(data[i][0], shell.thickness[tags[i] - 1]);
    gmsh::finalize();
  }
}
