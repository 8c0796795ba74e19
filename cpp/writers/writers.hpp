// Mesh output: CalculiX/Abaqus .inp, VTK XML .vtu and Gmsh 4.1 .msh, all ASCII and deterministic.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

// One value per hex, written as cell data (.vtu) or element data (.msh); ignored by .inp.
struct CellField {
  std::string name;
  std::vector<double> values;
};

// Writes the mesh in the format of the path's extension (.inp, .vtu, .msh, any case).
// Throws usageError for an unknown extension, inputError if the file cannot be written,
// Error(Internal) if a cell field or node set does not fit the mesh.
void writeMesh(const std::string& path, const HexMesh& mesh, const std::vector<NodeSet>& nodeSets,
               const std::vector<CellField>& cellFields = {});

// CalculiX/Abaqus: *NODE (NSET=NALL), *ELEMENT TYPE=C3D8I (C3D20R for 20-node hexes) ELSET=EALL,
// one *NSET per node set.
void writeInp(std::ostream& out, const HexMesh& mesh, const std::vector<NodeSet>& nodeSets);

// VTK XML UnstructuredGrid (VTK_HEXAHEDRON = 12, VTK_QUADRATIC_HEXAHEDRON = 25): point data "layer"
// and one 0/1 array per node set, cell data per field.
void writeVtu(std::ostream& out, const HexMesh& mesh, const std::vector<NodeSet>& nodeSets,
              const std::vector<CellField>& cellFields);

// Gmsh 4.1: volume 1 ("solid") with the hexes (type 5, or 17 with 20 nodes), boundary quads (type 3,
// or 16 with 8 nodes) in surfaces "top", "bottom", "rim" (by nodeLayer; all "rim" if nodeLayer is
// not sized), cell fields as $ElementData.
// Node sets are not written: the surface physical groups carry the same information.
void writeMsh(std::ostream& out, const HexMesh& mesh, const std::vector<CellField>& cellFields);

// Node ids of hex h in CalculiX C3D8/C3D20 order (= VTK's): the 8 corners, then for a 20-node hex
// its 12 mid-edge nodes (kHexEdges order).
std::vector<int> elementNodes(const HexMesh& mesh, std::size_t h);

// Shortest text that reads back to exactly v (std::to_chars).
std::string formatDouble(double v);

}  // namespace hexlayer
