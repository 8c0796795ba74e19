// Gmsh 4.1 ASCII. Volume entity 1 holds every node and hex; the boundary quads are split into
// surface entities "top", "bottom", "rim", each its own physical group. Gmsh's 8-node hex order is
// HexMesh's; its 20-node hex lists the mid-edge nodes in another edge order (kGmshHexEdges).
#include <algorithm>
#include <array>

#include "quality/quality.hpp"
#include "writers/writers.hpp"

namespace hexlayer {
namespace {

constexpr int kGmshQuad = 3, kGmshHex = 5, kGmshQuad8 = 16, kGmshHex20 = 17;
// Gmsh's 20-node hex (type 17) mid-edge nodes 8..19 are on edges 0-1, 0-3, 0-4, 1-2, 1-5, 2-3,
// 2-6, 3-7, 4-5, 4-7, 5-6, 6-7: here as indices into kHexEdges.
constexpr std::array<int, 12> kGmshHexEdges = {0, 3, 8, 1, 9, 2, 10, 11, 4, 7, 5, 6};
constexpr int kSolidPhysical = 4;  // physical tags 1..3 are the surfaces, so every tag is unique
const std::array<const char*, 3> kSurfaceNames = {"top", "bottom", "rim"};

// Boundary quads of each surface (index = surface tag - 1): 4 corners, then for 20-node hexes the
// mid-edge nodes of the quad's edges 0-1, 1-2, 2-3, 3-0 (Gmsh's 8-node quad, type 16).
using SurfaceQuads = std::array<std::vector<std::vector<int>>, 3>;

// Index into kHexEdges of the edge between local corners a and b.
int hexEdge(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if (std::minmax(a, b) == std::minmax(kHexEdges[e][0], kHexEdges[e][1])) return e;
  return -1;
}

std::vector<int> quadNodes(const HexMesh& mesh, const BoundaryFace& f) {
  std::vector<int> nodes(f.nodes.begin(), f.nodes.end());
  if (!mesh.quadratic()) return nodes;
  const std::array<int, 4>& local = kHexFaces[f.localFace];
  for (int i = 0; i < 4; ++i) nodes.push_back(mesh.midEdges[f.hex][hexEdge(local[i], local[(i + 1) % 4])]);
  return nodes;
}

int surfaceOf(const HexMesh& mesh, const std::array<int, 4>& quad) {
  if (mesh.nodeLayer.size() != mesh.nodes.size()) return 2;
  auto all = [&](int layer) {
    for (int n : quad)
      if (mesh.nodeLayer[n] != layer) return false;
    return true;
  };
  return all(mesh.layers) ? 0 : all(0) ? 1 : 2;
}

SurfaceQuads splitBoundary(const HexMesh& mesh) {
  SurfaceQuads s;
  for (const BoundaryFace& f : boundaryFaces(mesh)) s[surfaceOf(mesh, f.nodes)].push_back(quadNodes(mesh, f));
  return s;
}

std::vector<int> nonEmptySurfaceTags(const SurfaceQuads& s) {
  std::vector<int> tags;
  for (int i = 0; i < 3; ++i)
    if (!s[i].empty()) tags.push_back(i + 1);
  return tags;
}

// Axis-aligned bounding box, written as "minX minY minZ maxX maxY maxZ " (zeros if empty).
struct Box {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  bool empty = true;
  void add(const Vec3& p) {
    lo = empty ? p : Vec3(lo.cwiseMin(p));
    hi = empty ? p : Vec3(hi.cwiseMax(p));
    empty = false;
  }
};

void writeBox(std::ostream& out, const Box& b) {
  for (double v : {b.lo.x(), b.lo.y(), b.lo.z(), b.hi.x(), b.hi.y(), b.hi.z()}) out << formatDouble(v) << " ";
}

// Gmsh string tags are double-quoted: a quote in the name becomes an apostrophe.
std::string quoted(std::string name) {
  for (char& c : name)
    if (c == '"') c = '\'';
  return "\"" + name + "\"";
}

void writePhysicalNames(std::ostream& out, const std::vector<int>& surfaces) {
  out << "$PhysicalNames\n" << surfaces.size() + 1 << "\n";
  for (int t : surfaces) out << "2 " << t << " \"" << kSurfaceNames[t - 1] << "\"\n";
  out << "3 " << kSolidPhysical << " \"solid\"\n$EndPhysicalNames\n";
}

void writeEntities(std::ostream& out, const HexMesh& mesh, const SurfaceQuads& quads, const std::vector<int>& surfaces) {
  out << "$Entities\n0 0 " << surfaces.size() << " 1\n";
  for (int t : surfaces) {
    Box box;
    for (const auto& q : quads[t - 1])
      for (int n : q) box.add(mesh.nodes[n]);
    out << t << " ";
    writeBox(out, box);
    out << "1 " << t << " 0\n";
  }
  Box box;
  for (const Vec3& p : mesh.nodes) box.add(p);
  out << "1 ";
  writeBox(out, box);
  out << "1 " << kSolidPhysical << " " << surfaces.size();
  for (int t : surfaces) out << " " << t;
  out << "\n$EndEntities\n";
}

void writeNodes(std::ostream& out, const HexMesh& mesh) {
  const std::size_t n = mesh.nodes.size();
  out << "$Nodes\n" << (n ? 1 : 0) << " " << n << " " << (n ? 1 : 0) << " " << n << "\n";
  if (n) {
    out << "3 1 0 " << n << "\n";
    for (std::size_t i = 1; i <= n; ++i) out << i << "\n";
    for (const Vec3& p : mesh.nodes) out << formatDouble(p.x()) << " " << formatDouble(p.y()) << " " << formatDouble(p.z()) << "\n";
  }
  out << "$EndNodes\n";
}

// Node ids of hex h in Gmsh's order: the corners, then the mid-edge nodes in kGmshHexEdges order.
std::vector<int> gmshHexNodes(const HexMesh& mesh, std::size_t h) {
  std::vector<int> nodes(mesh.hexes[h].begin(), mesh.hexes[h].end());
  if (mesh.quadratic())
    for (int e : kGmshHexEdges) nodes.push_back(mesh.midEdges[h][e]);
  return nodes;
}

void writeElement(std::ostream& out, std::size_t tag, const std::vector<int>& nodes) {
  out << tag;
  for (int n : nodes) out << " " << n + 1;
  out << "\n";
}

// Hexes get tags 1..H (as in the .inp), then the quads of each surface in turn.
void writeElements(std::ostream& out, const HexMesh& mesh, const SurfaceQuads& quads, const std::vector<int>& surfaces) {
  std::size_t total = mesh.hexes.size();
  for (int t : surfaces) total += quads[t - 1].size();
  out << "$Elements\n" << surfaces.size() + 1 << " " << total << " " << (total ? 1 : 0) << " " << total << "\n";
  out << "3 1 " << (mesh.quadratic() ? kGmshHex20 : kGmshHex) << " " << mesh.hexes.size() << "\n";
  std::size_t tag = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) writeElement(out, ++tag, gmshHexNodes(mesh, h));
  for (int t : surfaces) {
    out << "2 " << t << " " << (mesh.quadratic() ? kGmshQuad8 : kGmshQuad) << " " << quads[t - 1].size() << "\n";
    for (const auto& q : quads[t - 1]) writeElement(out, ++tag, q);
  }
  out << "$EndElements\n";
}

// One scalar per hex (element tags 1..H), step 0, time 0.
void writeElementData(std::ostream& out, const CellField& f) {
  out << "$ElementData\n1\n" << quoted(f.name) << "\n1\n0\n3\n0\n1\n" << f.values.size() << "\n";
  for (std::size_t h = 0; h < f.values.size(); ++h) out << h + 1 << " " << formatDouble(f.values[h]) << "\n";
  out << "$EndElementData\n";
}

}  // namespace

void writeMsh(std::ostream& out, const HexMesh& mesh, const std::vector<CellField>& cellFields) {
  const SurfaceQuads quads = splitBoundary(mesh);
  const std::vector<int> surfaces = nonEmptySurfaceTags(quads);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  writePhysicalNames(out, surfaces);
  writeEntities(out, mesh, quads, surfaces);
  writeNodes(out, mesh);
  writeElements(out, mesh, quads, surfaces);
  for (const CellField& f : cellFields) writeElementData(out, f);
}

}  // namespace hexlayer
