// VTK XML UnstructuredGrid, ASCII. elementNodes' order is VTK_HEXAHEDRON's and VTK_QUADRATIC_HEXAHEDRON's.
#include <algorithm>

#include "writers/writers.hpp"

namespace hexlayer {
namespace {

constexpr int kVtkHexahedron = 12, kVtkQuadraticHexahedron = 25, kVtkQuad = 9, kVtkQuadraticQuad = 23;
constexpr int kValuesPerLine = 8;

std::string xmlEscape(const std::string& s) {
  std::string e;
  for (char c : s) {
    if (c == '&')
      e += "&amp;";
    else if (c == '<')
      e += "&lt;";
    else if (c == '>')
      e += "&gt;";
    else if (c == '"')
      e += "&quot;";
    else
      e += c;
  }
  return e;
}

void openArray(std::ostream& out, const char* type, const std::string& name, int components = 1) {
  out << "<DataArray type=\"" << type << "\" Name=\"" << xmlEscape(name) << "\"";
  if (components > 1) out << " NumberOfComponents=\"" << components << "\"";
  out << " format=\"ascii\">\n";
}

// values[0..n) separated by spaces, kValuesPerLine per line, then </DataArray>.
template <class Value>
void writeValues(std::ostream& out, std::size_t n, Value&& value) {
  for (std::size_t i = 0; i < n; ++i) out << value(i) << ((i + 1) % kValuesPerLine == 0 || i + 1 == n ? "\n" : " ");
  out << "</DataArray>\n";
}

// N of the first surface group FaceN (in the groups' order) holding each of the `nodes` nodes, 0 for none.
std::vector<int> cadFaceOfNodes(std::size_t nodes, const std::vector<SurfaceGroup>& surfaces) {
  std::vector<int> face(nodes, 0);
  for (std::size_t g = surfaces.size(); g-- > 0;)
    for (int n : surfaces[g].nodes) face[n] = static_cast<int>(g) + 1;
  return face;
}

// One 0/1 array per node set, and "cad_face" with surface groups.
void writeGroupArrays(std::ostream& out, std::size_t nodes, const std::vector<NodeSet>& nodeSets,
                      const std::vector<SurfaceGroup>& surfaces) {
  std::vector<int> member(nodes);
  for (const NodeSet& s : nodeSets) {
    std::fill(member.begin(), member.end(), 0);
    for (int n : s.nodes) member[n] = 1;
    openArray(out, "Int32", s.name);
    writeValues(out, member.size(), [&](std::size_t i) { return member[i]; });
  }
  if (!surfaces.empty()) {
    const std::vector<int> face = cadFaceOfNodes(nodes, surfaces);
    openArray(out, "Int32", "cad_face");
    writeValues(out, face.size(), [&](std::size_t i) { return face[i]; });
  }
}

void writePointData(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups) {
  const bool layers = mesh.nodeLayer.size() == mesh.nodes.size();
  if (!layers && groups.nodeSets.empty() && groups.surfaces.empty()) return;
  out << "<PointData>\n";
  if (layers) {
    openArray(out, "Int32", "layer");
    writeValues(out, mesh.nodes.size(), [&](std::size_t i) { return mesh.nodeLayer[i]; });
  }
  writeGroupArrays(out, mesh.nodes.size(), groups.nodeSets, groups.surfaces);
  out << "</PointData>\n";
}

void writeCellData(std::ostream& out, const std::vector<CellField>& cellFields) {
  if (cellFields.empty()) return;
  out << "<CellData>\n";
  for (const CellField& f : cellFields) {
    openArray(out, "Float64", f.name);
    writeValues(out, f.values.size(), [&](std::size_t i) { return formatDouble(f.values[i]); });
  }
  out << "</CellData>\n";
}

void writePoints(std::ostream& out, const std::vector<Vec3>& nodes) {
  out << "<Points>\n";
  openArray(out, "Float64", "Points", 3);
  for (const Vec3& p : nodes)
    out << formatDouble(p.x()) << " " << formatDouble(p.y()) << " " << formatDouble(p.z()) << "\n";
  out << "</DataArray>\n</Points>\n";
}

// count cells of one VTK type with perCell nodes each, cell c's nodes nodesOf(c).
template <class NodesOf>
void writeCells(std::ostream& out, std::size_t count, std::size_t perCell, int type, NodesOf&& nodesOf) {
  out << "<Cells>\n";
  openArray(out, "Int64", "connectivity");
  for (std::size_t c = 0; c < count; ++c) {
    const ElementNodes nodes = nodesOf(c);
    for (std::size_t i = 0; i < nodes.size(); ++i) out << nodes[i] << (i + 1 == nodes.size() ? "\n" : " ");
  }
  out << "</DataArray>\n";
  openArray(out, "Int64", "offsets");
  writeValues(out, count, [&](std::size_t c) { return perCell * (c + 1); });
  openArray(out, "UInt8", "types");
  writeValues(out, count, [&](std::size_t) { return type; });
  out << "</Cells>\n";
}

void openPiece(std::ostream& out, std::size_t points, std::size_t cells) {
  out << "<?xml version=\"1.0\"?>\n";
  out << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out << "<UnstructuredGrid>\n";
  out << "<Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << cells << "\">\n";
}

void closePiece(std::ostream& out) { out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n"; }

}  // namespace

void writeVtu(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups) {
  openPiece(out, mesh.nodes.size(), mesh.hexes.size());
  writePointData(out, mesh, groups);
  writeCellData(out, groups.cellFields);
  writePoints(out, mesh.nodes);
  writeCells(out, mesh.hexes.size(), mesh.quadratic() ? 20 : 8,
             mesh.quadratic() ? kVtkQuadraticHexahedron : kVtkHexahedron,
             [&](std::size_t h) { return elementNodes(mesh, h); });
  closePiece(out);
}

void writeShellVtu(std::ostream& out, const ShellMesh& shell) {
  openPiece(out, shell.nodes.size(), shell.quads.size());
  out << "<PointData>\n";
  openArray(out, "Float64", "thickness");
  writeValues(out, shell.thickness.size(), [&](std::size_t i) { return formatDouble(shell.thickness[i]); });
  writeGroupArrays(out, shell.nodes.size(), shell.nodeSets, shell.faces);
  out << "</PointData>\n";
  writePoints(out, shell.nodes);
  writeCells(out, shell.quads.size(), shell.quadratic() ? 8 : 4, shell.quadratic() ? kVtkQuadraticQuad : kVtkQuad,
             [&](std::size_t e) { return shellElementNodes(shell, e); });
  closePiece(out);
}

}  // namespace hexlayer
