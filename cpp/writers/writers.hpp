// Mesh output: CalculiX/Abaqus .inp, VTK XML .vtu and Gmsh 4.1 .msh, all ASCII and deterministic.
#pragma once
#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "quality/quality.hpp"

namespace hexlayer {

// One value per hex, written as cell data (.vtu) or element data (.msh); ignored by .inp.
struct CellField {
  std::string name;
  std::vector<double> values;
};

// What is written besides the mesh: node sets (TOP, BOTTOM, RIM), surface groups (one per CAD face)
// and cell fields. Any of them may be empty.
struct MeshGroups {
  std::vector<NodeSet> nodeSets;
  std::vector<SurfaceGroup> surfaces;
  std::vector<CellField> cellFields;
};

// Writes the mesh in the format of the path's extension (.inp, .vtu, .msh, any case).
// Throws usageError for an unknown extension, inputError if the file cannot be written,
// Error(Internal) if a cell field, node set or surface group does not fit the mesh.
void writeMesh(const std::string& path, const HexMesh& mesh, const MeshGroups& groups);

// CalculiX/Abaqus: *NODE (NSET=NALL), *ELEMENT TYPE=C3D8I (C3D20R for 20-node hexes) ELSET=EALL,
// one *NSET per node set; per non-empty surface group FaceN an *NSET FACEN of its nodes and an
// element-face *SURFACE FACEN_S (lines "element, Sk", k = localFace + 1: CalculiX's S1..S6).
// [out] out: the file's text written to it; [in] mesh, groups.
void writeInp(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups);

// VTK XML UnstructuredGrid (VTK_HEXAHEDRON = 12, VTK_QUADRATIC_HEXAHEDRON = 25): point data "layer",
// one 0/1 array per node set and, with surface groups, "cad_face": N of the node's first group FaceN
// (the lowest N; a node on a CAD edge is in several groups), 0 for a node on no face; cell data per field.
// [out] out: the file's text written to it; [in] mesh, groups.
void writeVtu(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups);

// Gmsh 4.1: volume 1 ("solid") with the hexes (type 5, or 17 with 20 nodes) and the boundary quads
// (type 3, or 16 with 8 nodes). With surface groups, one surface entity per meshed CAD face, in a
// physical group named FaceN, each also in one of the physical groups "top", "bottom", "rim" (the
// class most of its quads have by nodeLayer); without, three surfaces "top", "bottom", "rim" (all
// "rim" if nodeLayer is not sized). Cell fields as $ElementData. Node sets are not written: the
// surface physical groups carry the same information.
// [out] out: the file's text written to it; [in] mesh, groups.
void writeMsh(std::ostream& out, const HexMesh& mesh, const MeshGroups& groups);

// The mid-surface shell (ShellMesh, issue 20) in the format of the path's extension; throws as writeMesh does.
void writeShellMesh(const std::string& path, const ShellMesh& shell);

// The material name the shell's *SHELL SECTION refers to: the deck including the mesh defines it first.
inline constexpr const char* kShellMaterial = "SHELL_MATERIAL";

// CalculiX/Abaqus: *NODE (NSET=NALL), *ELEMENT TYPE=S4 (S8R for 8-node quads) ELSET=EALL (S4, which CalculiX expands
// into C3D8I, not S4R: its C3D8R hourglass, a 100 x 20 x 2 cantilever bent 28 times too far), one *NSET per node set
// (RIM) and per CAD face (FACEN), *NODAL THICKNESS (node, thickness) and *SHELL SECTION, ELSET=EALL,
// MATERIAL=SHELL_MATERIAL, NODAL THICKNESS. [out] out: the file's text written to it; [in] shell.
void writeShellInp(std::ostream& out, const ShellMesh& shell);

// VTK XML UnstructuredGrid (VTK_QUAD = 9, VTK_QUADRATIC_QUAD = 23): point data "thickness", one 0/1 array per node
// set and "cad_face" as writeVtu has it. [out] out: the file's text written to it; [in] shell.
void writeShellVtu(std::ostream& out, const ShellMesh& shell);

// Gmsh 4.1: surface 1 (physical group "shell") with the quads (type 3, or 16 with 8 nodes) and $NodeData
// "thickness". [out] out: the file's text written to it; [in] shell.
void writeShellMsh(std::ostream& out, const ShellMesh& shell);

// The node ids of one element or face, at most 20, held without a heap allocation (the writers
// make one per element).
struct ElementNodes {
  std::array<int, 20> ids{};
  std::size_t count = 0;
  void push_back(int id) { ids[count++] = id; }
  std::size_t size() const { return count; }
  int operator[](std::size_t i) const { return ids[i]; }
  const int* begin() const { return ids.data(); }
  const int* end() const { return ids.data() + count; }
};

// Node ids of a boundary face: its 4 corners (outward, kHexFaces order), then for 20-node hexes the
// mid-edge nodes of its edges 0-1, 1-2, 2-3, 3-0 (Gmsh's 8-node quad, type 16).
ElementNodes boundaryFaceNodes(const HexMesh& mesh, const BoundaryFace& face);

// Node ids of hex h in CalculiX C3D8/C3D20 order (= VTK's): the 8 corners, then for a 20-node hex
// its 12 mid-edge nodes (kHexEdges order).
ElementNodes elementNodes(const HexMesh& mesh, std::size_t h);

// Node ids of shell element e: its 4 corners, then for 8-node quads the mid-side nodes of edges 0-1, 1-2, 2-3, 3-0
// (CalculiX S8R's, Gmsh's type 16's and VTK_QUADRATIC_QUAD's order).
ElementNodes shellElementNodes(const ShellMesh& shell, std::size_t e);

// Shortest text that reads back to exactly v (std::to_chars).
std::string formatDouble(double v);

}  // namespace hexlayer
