// Gmsh 4.1 ASCII. Volume entity 1 holds every node and hex; the boundary quads are split into
// surface entities, one per CAD face (physical groups FaceN and top/bottom/rim) or, without surface
// groups, "top", "bottom", "rim". Gmsh's 8-node hex order is
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
constexpr int kSolidPhysical =
    4;  // physical tags 1..3 are "top", "bottom", "rim", 5.. the CAD faces: every tag is unique
const std::array<const char*, 3> kSurfaceNames = {"top", "bottom", "rim"};

// One surface entity: boundary quads (4 corners, then for 20-node hexes the mid-edge nodes of the
// quad's edges, Gmsh's 8-node quad), their class (0 top, 1 bottom, 2 rim) and the CAD face, if any.
struct Patch {
  std::string cadFace;  // "FaceN", or empty without surface groups
  int surfaceClass = 2;
  std::vector<ElementNodes> quads;
};

int surfaceOf(const HexMesh& mesh, const std::array<int, 4>& quad) {
  if (mesh.nodeLayer.size() != mesh.nodes.size()) return 2;
  auto all = [&](int layer) {  // a rim cap's faces lie on the rim in every layer
    for (int n : quad)
      if (mesh.nodeLayer[n] != layer || (n < static_cast<int>(mesh.nodeOnRim.size()) && mesh.nodeOnRim[n] == kRimCap))
        return false;
    return true;
  };
  return all(mesh.layers) ? 0 : all(0) ? 1 : 2;
}

BoundaryFace boundaryFace(const HexMesh& mesh, const HexFace& f) {
  BoundaryFace b{{}, f.hex, f.localFace};
  for (int i = 0; i < 4; ++i) b.nodes[i] = mesh.hexes[f.hex][kHexFaces[f.localFace][i]];
  return b;
}

// Without surface groups: the boundary split into top, bottom and rim by nodeLayer.
std::vector<Patch> classPatches(const HexMesh& mesh) {
  std::vector<Patch> byClass(3);
  for (int c = 0; c < 3; ++c) byClass[c].surfaceClass = c;
  for (const BoundaryFace& f : boundaryFaces(mesh))
    byClass[surfaceOf(mesh, f.nodes)].quads.push_back(boundaryFaceNodes(mesh, f));
  std::vector<Patch> patches;
  for (Patch& p : byClass)
    if (!p.quads.empty()) patches.push_back(std::move(p));
  return patches;
}

// With surface groups: one patch per CAD face with mesh faces, in the class most of its quads have.
std::vector<Patch> facePatches(const HexMesh& mesh, const std::vector<SurfaceGroup>& surfaces) {
  std::vector<Patch> patches;
  for (const SurfaceGroup& g : surfaces) {
    if (g.hexFaces.empty()) continue;
    Patch p{g.name, 0, {}};
    std::array<int, 3> votes{};
    for (const HexFace& f : g.hexFaces) {
      const BoundaryFace b = boundaryFace(mesh, f);
      ++votes[surfaceOf(mesh, b.nodes)];
      p.quads.push_back(boundaryFaceNodes(mesh, b));
    }
    p.surfaceClass = static_cast<int>(std::max_element(votes.begin(), votes.end()) - votes.begin());
    patches.push_back(std::move(p));
  }
  return patches;
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

// Physical tag of patch i's CAD face.
int facePhysical(std::size_t i) { return kSolidPhysical + 1 + static_cast<int>(i); }

std::vector<int> usedClasses(const std::vector<Patch>& patches) {
  std::vector<int> classes;
  for (int c = 0; c < 3; ++c)
    for (const Patch& p : patches)
      if (p.surfaceClass == c) {
        classes.push_back(c);
        break;
      }
  return classes;
}

void writePhysicalNames(std::ostream& out, const std::vector<Patch>& patches) {
  const std::vector<int> classes = usedClasses(patches);
  std::size_t faces = 0;
  for (const Patch& p : patches) faces += !p.cadFace.empty();
  out << "$PhysicalNames\n" << classes.size() + faces + 1 << "\n";
  for (int c : classes) out << "2 " << c + 1 << " \"" << kSurfaceNames[c] << "\"\n";
  for (std::size_t i = 0; i < patches.size(); ++i)
    if (!patches[i].cadFace.empty()) out << "2 " << facePhysical(i) << " " << quoted(patches[i].cadFace) << "\n";
  out << "3 " << kSolidPhysical << " \"solid\"\n$EndPhysicalNames\n";
}

// Surface entity i + 1 per patch, in its class's physical group and its CAD face's.
void writeEntities(std::ostream& out, const HexMesh& mesh, const std::vector<Patch>& patches) {
  out << "$Entities\n0 0 " << patches.size() << " 1\n";
  for (std::size_t i = 0; i < patches.size(); ++i) {
    Box box;
    for (const auto& q : patches[i].quads)
      for (int n : q) box.add(mesh.nodes[n]);
    out << i + 1 << " ";
    writeBox(out, box);
    if (patches[i].cadFace.empty())
      out << "1 " << patches[i].surfaceClass + 1 << " 0\n";
    else
      out << "2 " << patches[i].surfaceClass + 1 << " " << facePhysical(i) << " 0\n";
  }
  Box box;
  for (const Vec3& p : mesh.nodes) box.add(p);
  out << "1 ";
  writeBox(out, box);
  out << "1 " << kSolidPhysical << " " << patches.size();
  for (std::size_t i = 0; i < patches.size(); ++i) out << " " << i + 1;
  out << "\n$EndEntities\n";
}

// Every node in entity 1 of dimension dim.
void writeNodes(std::ostream& out, const std::vector<Vec3>& nodes, int dim) {
  const std::size_t n = nodes.size();
  out << "$Nodes\n" << (n ? 1 : 0) << " " << n << " " << (n ? 1 : 0) << " " << n << "\n";
  if (n) {
    out << dim << " 1 0 " << n << "\n";
    for (std::size_t i = 1; i <= n; ++i) out << i << "\n";
    for (const Vec3& p : nodes)
      out << formatDouble(p.x()) << " " << formatDouble(p.y()) << " " << formatDouble(p.z()) << "\n";
  }
  out << "$EndNodes\n";
}

// Node ids of hex h in Gmsh's order: the corners, then the mid-edge nodes in kGmshHexEdges order.
ElementNodes gmshHexNodes(const HexMesh& mesh, std::size_t h) {
  ElementNodes nodes;
  for (int n : mesh.hexes[h]) nodes.push_back(n);
  if (mesh.quadratic())
    for (int e : kGmshHexEdges) nodes.push_back(mesh.midEdges[h][e]);
  return nodes;
}

void writeElement(std::ostream& out, std::size_t tag, const ElementNodes& nodes) {
  out << tag;
  for (int n : nodes) out << " " << n + 1;
  out << "\n";
}

// Hexes get tags 1..H (as in the .inp), then the quads of each patch in turn.
void writeElements(std::ostream& out, const HexMesh& mesh, const std::vector<Patch>& patches) {
  std::size_t total = mesh.hexes.size();
  for (const Patch& p : patches) total += p.quads.size();
  out << "$Elements\n" << patches.size() + 1 << " " << total << " " << (total ? 1 : 0) << " " << total << "\n";
  out << "3 1 " << (mesh.quadratic() ? kGmshHex20 : kGmshHex) << " " << mesh.hexes.size() << "\n";
  std::size_t tag = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) writeElement(out, ++tag, gmshHexNodes(mesh, h));
  for (std::size_t i = 0; i < patches.size(); ++i) {
    out << "2 " << i + 1 << " " << (mesh.quadratic() ? kGmshQuad8 : kGmshQuad) << " " << patches[i].quads.size()
        << "\n";
    for (const auto& q : patches[i].quads) writeElement(out, ++tag, q);
  }
  out << "$EndElements\n";
}

// One scalar per element (kind "ElementData", tags 1..H) or node ("NodeData", tags 1..N), step 0, time 0.
void writeData(std::ostream& out, const std::string& kind, const std::string& name, const std::vector<double>& values) {
  out << "$" << kind << "\n1\n" << quoted(name) << "\n1\n0\n3\n0\n1\n" << values.size() << "\n";
  for (std::size_t i = 0; i < values.size(); ++i) out << i + 1 << " " << formatDouble(values[i]) << "\n";
  out << "$End" << kind << "\n";
}

}  // namespace

void writeMsh(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups) {
  const std::vector<Patch> patches = groups.surfaces.empty() ? classPatches(mesh) : facePatches(mesh, groups.surfaces);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  writePhysicalNames(out, patches);
  writeEntities(out, mesh, patches);
  writeNodes(out, mesh.nodes, 3);
  writeElements(out, mesh, patches);
  for (const CellField& f : groups.cellFields) writeData(out, "ElementData", f.name, f.values);
}

void writeShellMsh(std::ostream& out, const ShellMesh& shell) {
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n1\n2 1 \"shell\"\n$EndPhysicalNames\n";
  Box box;
  for (const Vec3& p : shell.nodes) box.add(p);
  out << "$Entities\n0 0 1 0\n1 ";
  writeBox(out, box);
  out << "1 1 0\n$EndEntities\n";
  writeNodes(out, shell.nodes, 2);
  const std::size_t n = shell.quads.size();
  out << "$Elements\n1 " << n << " " << (n ? 1 : 0) << " " << n << "\n";
  out << "2 1 " << (shell.quadratic() ? kGmshQuad8 : kGmshQuad) << " " << n << "\n";
  for (std::size_t e = 0; e < n; ++e) writeElement(out, e + 1, shellElementNodes(shell, e));
  out << "$EndElements\n";
  writeData(out, "NodeData", "thickness", shell.thickness);
}

}  // namespace hexlayer
