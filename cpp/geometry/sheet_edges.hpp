// Where one sheet runs on across a CAD edge. Two faces sharing an edge belong to the same side of
// one sheet when the edge is smooth (a bend's tangent edge) or convex; along a concave sharp edge
// a rib, boss or flange stands on the sheet (a T-junction), and the faces there need not be on the
// same side. OpenCASCADE's offset analysis (BRepOffset_Analyse) tells the edges apart.
#pragma once
#include <utility>
#include <vector>

#include "geometry/cad_solid.hpp"

namespace hexlayer {

// Pairs of distinct faces (0-based, lower first) sharing an edge that is smooth or convex.
std::vector<std::pair<int, int>> sheetJoins(const CadSolid& cad);

}  // namespace hexlayer
