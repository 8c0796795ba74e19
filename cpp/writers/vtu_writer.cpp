// VTK XML UnstructuredGrid, ASCII. elementNodes' order is VTK_HEXAHEDRON's and VTK_QUADRATIC_HEXAHEDRON's.
#include <algorithm>

#include "writers/writers.hpp"

namespace hexlayer {
namespace {

constexpr int kVtkHexahedron = 12, kVtkQuadraticHexahedron = 25;
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

// N of the first surface group FaceN (in the groups' order) holding each node, 0 for none.
std::vector<int> cadFaceOfNodes(const HexMesh& mesh, const std::vector<SurfaceGroup>& surfaces) {
  std::vector<int> face(mesh.nodes.size(), 0);
  for (std::size_t g = surfaces.size(); g-- > 0;)
    for (int n : surfaces[g].nodes) face[n] = static_cast<int>(g) + 1;
  return face;
}

void writePointData(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups) {
  const std::vector<NodeSet>& nodeSets = groups.nodeSets;
  const bool layers = mesh.nodeLayer.size() == mesh.nodes.size();
  if (!layers && nodeSets.empty() && groups.surfaces.empty()) return;
  out << "<PointData>\n";
  if (layers) {
    openArray(out, "Int32", "layer");
    writeValues(out, mesh.nodes.size(), [&](std::size_t i) { return mesh.nodeLayer[i]; });
  }
  std::vector<int> member(mesh.nodes.size());
  for (const NodeSet& s : nodeSets) {
    std::fill(member.begin(), member.end(), 0);
    for (int n : s.nodes) member[n] = 1;
    openArray(out, "Int32", s.name);
    writeValues(out, member.size(), [&](std::size_t i) { return member[i]; });
  }
  if (!groups.surfaces.empty()) {
    const std::vector<int> face = cadFaceOfNodes(mesh, groups.surfaces);
    openArray(out, "Int32", "cad_face");
    writeValues(out, face.size(), [&](std::size_t i) { return face[i]; });
  }
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

void writePoints(std::ostream& out, const HexMesh& mesh) {
  out << "<Points>\n";
  openArray(out, "Float64", "Points", 3);
  for (const Vec3& p : mesh.nodes)
    out << formatDouble(p.x()) << " " << formatDouble(p.y()) << " " << formatDouble(p.z()) << "\n";
  out << "</DataArray>\n</Points>\n";
}

void writeCells(std::ostream& out, const HexMesh& mesh) {
  out << "<Cells>\n";
  openArray(out, "Int64", "connectivity");
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    const ElementNodes nodes = elementNodes(mesh, h);
    for (std::size_t i = 0; i < nodes.size(); ++i) out << nodes[i] << (i + 1 == nodes.size() ? "\n" : " ");
  }
  out << "</DataArray>\n";
  const std::size_t perCell = mesh.quadratic() ? 20 : 8;
  openArray(out, "Int64", "offsets");
  writeValues(out, mesh.hexes.size(), [&](std::size_t h) { return perCell * (h + 1); });
  openArray(out, "UInt8", "types");
  const int type = mesh.quadratic() ? kVtkQuadraticHexahedron : kVtkHexahedron;
  writeValues(out, mesh.hexes.size(), [&](std::size_t) { return type; });
  out << "</Cells>\n";
}

}  // namespace

void writeVtu(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups) {
  out << "<?xml version=\"1.0\"?>\n";
  out << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out << "<UnstructuredGrid>\n";
  out << "<Piece NumberOfPoints=\"" << mesh.nodes.size() << "\" NumberOfCells=\"" << mesh.hexes.size() << "\">\n";
  writePointData(out, mesh, groups);
  writeCellData(out, groups.cellFields);
  writePoints(out, mesh);
  writeCells(out, mesh);
  out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace hexlayer
