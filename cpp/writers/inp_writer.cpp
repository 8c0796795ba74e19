// CalculiX/Abaqus input deck. CalculiX's C3D8I node order equals HexMesh's and C3D20R's mid-edge
// order kHexEdges', so hexes are written as elementNodes lists them.
#include <cctype>
#include <charconv>

#include "writers/writers.hpp"

namespace hexlayer {
namespace {

constexpr int kIdsPerLine = 16;        // Abaqus limit for data lines of *NSET and *ELEMENT
constexpr std::size_t kMaxField = 20;  // CalculiX reads a *NODE coordinate from its first 20 characters
constexpr std::size_t kMaxName = 80;   // CalculiX set names

// Shortest round-trip text if it fits in 20 characters, else scientific with as many digits as fit
// (at least 13 significant digits), written at `at` (room for 32 characters); returns its end.
char* inpNumber(double v, char* at) {
  char* end = std::to_chars(at, at + 32, v).ptr;
  for (int digits = 16; static_cast<std::size_t>(end - at) > kMaxField && digits > 0; --digits)
    end = std::to_chars(at, at + 32, v, std::chars_format::scientific, digits).ptr;
  return end;
}

// Writes the decimal text of a non-negative integer at `at` (room for 20 characters); returns its end.
char* inpInteger(std::size_t v, char* at) { return std::to_chars(at, at + 20, v).ptr; }

// Upper case, at most 80 characters, characters other than letters, digits and '_' replaced by '_'.
std::string inpName(const std::string& name) {
  std::string s = name.empty() ? "SET" : name.substr(0, kMaxName);
  for (char& c : s) c = std::isalnum(static_cast<unsigned char>(c)) ? std::toupper(static_cast<unsigned char>(c)) : '_';
  return s;
}

// Each line composed in a local buffer and written at once (no formatting through the stream).
void writeNodes(std::ostream& out, const std::vector<Vec3>& nodes) {
  out << "*NODE, NSET=NALL\n";
  char line[160];
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    char* at = inpInteger(i + 1, line);
    for (int k = 0; k < 3; ++k) *at++ = ',', *at++ = ' ', at = inpNumber(nodes[i][k], at);
    *at++ = '\n';
    out.write(line, at - line);
  }
}

// count elements of one type in ELSET=EALL, element e's nodes nodesOf(e); more than 16 entries continue on a second
// line after the first 16 (the line ends with a comma).
template <class NodesOf>
void writeElements(std::ostream& out, const char* type, std::size_t count, NodesOf&& nodesOf) {
  out << "*ELEMENT, TYPE=" << type << ", ELSET=EALL\n";
  char line[512];
  for (std::size_t e = 0; e < count; ++e) {
    char* at = inpInteger(e + 1, line);
    const ElementNodes nodes = nodesOf(e);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      *at++ = ',';
      *at++ = (i + 1) % kIdsPerLine == 0 ? '\n' : ' ';
      at = inpInteger(static_cast<std::size_t>(nodes[i]) + 1, at);
    }
    *at++ = '\n';
    out.write(line, at - line);
  }
}

void writeNodeSet(std::ostream& out, const NodeSet& set) {
  if (set.nodes.empty()) {  // CalculiX rejects an *NSET without members
    out << "** node set " << inpName(set.name) << " is empty\n";
    return;
  }
  out << "*NSET, NSET=" << inpName(set.name) << "\n";
  for (std::size_t i = 0; i < set.nodes.size(); ++i) {
    out << set.nodes[i] + 1;
    const bool lineEnd = (i + 1) % kIdsPerLine == 0 || i + 1 == set.nodes.size();
    out << (lineEnd ? "\n" : ", ");
  }
}

// A CAD face's nodes as *NSET FACEN and its boundary hex faces as the element-face *SURFACE FACEN_S:
// HexMesh's local face f is CalculiX's (and Abaqus') S(f + 1) of C3D8 and C3D20 (S1 = nodes 1-2-3-4,
// S2 = 5-8-7-6, S3 = 1-5-6-2, S4 = 2-6-7-3, S5 = 3-7-8-4, S6 = 4-8-5-1).
// A face narrower than the hexes (a rim's flat strip between two fillets) has nodes but no mesh face.
void writeSurfaceGroup(std::ostream& out, const SurfaceGroup& g) {
  writeNodeSet(out, {g.name, g.nodes});
  if (g.hexFaces.empty()) {
    out << "** CAD face " << g.name << " has no mesh faces\n";
    return;
  }
  out << "*SURFACE, NAME=" << inpName(g.name + "_S") << ", TYPE=ELEMENT\n";
  for (const HexFace& f : g.hexFaces) out << f.hex + 1 << ", S" << f.localFace + 1 << "\n";
}

}  // namespace

void writeInp(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups) {
  out << "*HEADING\n";
  out << "HexLayer layered all-hex mesh: " << mesh.nodes.size() << " nodes, " << mesh.hexes.size() << " hexes, "
      << mesh.layers << " layers\n";
  writeNodes(out, mesh.nodes);
  // Incompatible-mode C3D8I for 8-node hexes (bending-accurate), reduced-integration C3D20R for 20-node ones.
  writeElements(out, mesh.quadratic() ? "C3D20R" : "C3D8I", mesh.hexes.size(),
                [&](std::size_t h) { return elementNodes(mesh, h); });
  for (const NodeSet& s : groups.nodeSets) writeNodeSet(out, s);
  for (const SurfaceGroup& g : groups.surfaces) writeSurfaceGroup(out, g);
}

void writeShellInp(std::ostream& out, const ShellMesh& shell) {
  out << "*HEADING\n";
  out << "HexLayer mid-surface shell: " << shell.nodes.size() << " nodes, " << shell.quads.size() << " elements\n";
  writeNodes(out, shell.nodes);
  writeElements(out, shell.quadratic() ? "S8R" : "S4", shell.quads.size(),
                [&](std::size_t e) { return shellElementNodes(shell, e); });
  for (const NodeSet& s : shell.nodeSets) writeNodeSet(out, s);
  for (const SurfaceGroup& g : shell.faces) writeNodeSet(out, {g.name, g.nodes});
  out << "*NODAL THICKNESS\n";
  char line[64];
  for (std::size_t i = 0; i < shell.thickness.size(); ++i) {
    char* at = inpInteger(i + 1, line);
    *at++ = ',', *at++ = ' ', at = inpNumber(shell.thickness[i], at);
    *at++ = '\n';
    out.write(line, at - line);
  }
  out << "** The deck defines *MATERIAL, NAME=" << kShellMaterial << " before it includes this file.\n";
  out << "*SHELL SECTION, ELSET=EALL, MATERIAL=" << kShellMaterial << ", NODAL THICKNESS\n1.\n";
}

}  // namespace hexlayer
