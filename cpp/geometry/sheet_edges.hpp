// Where one sheet runs on across a CAD edge. Two faces sharing an edge belong to the same side of
// one sheet when the edge is smooth (a bend's tangent edge) or convex; along a concave sharp edge
// a rib, boss or flange stands on the sheet (a T-junction), and the faces there need not be on the
// same side. OpenCASCADE's offset analysis (BRepOffset_Analyse) tells the edges apart.
#pragma once
#include <set>
#include <vector>

#include "geometry/cad_solid.hpp"

namespace hexlayer {

struct SheetJoin {
  int a = -1, b = -1;   // 0-based faces, a < b
  bool smooth = false;  // tangent edge; else a convex sharp edge (a sharp bend, or a tapered wall's knife edge)
  int edge = -1;        // 0-based in CadSolid::edges (-1: not from an edge)
  // A convex edge whose faces' normals at its middle are within BRepOffset_Analyse's tolerance (0.5 rad) of opposite:
  // a knife edge, or a crevice the analysis cannot tell from one (a boss merged 0.2-0.3 into a wall, or drafted, meets
  // the wall's face in an air wedge of 20-28 degrees, which it takes for convex).
  bool folded = false;
};

// [in] cad: the solid. Returns the pairs of distinct faces sharing an edge that is smooth or convex.
std::vector<SheetJoin> sheetJoins(const CadSolid& cad);

// Whether faces a and b of smooth join j are one surface across its edge: at the edge's middle their mean curvatures
// (along the outward normal) and Gaussian curvatures agree (G2), as where a CAD system split a cylinder, a cone or a
// B-spline into faces; a fillet or a bend's round meets a plane with a step in curvature. [in] cad, j: from
// sheetJoins. Returns false for a sharp join or where a curvature is undefined.
bool oneSurfaceAcross(const CadSolid& cad, const SheetJoin& j);

// A CAD edge between two faces (concave and sharp: where a rib, boss or flange may stand on a sheet).
struct FacePairEdge {
  int edge = -1;         // 0-based in CadSolid::edges
  int a = -1, b = -1;    // its two distinct faces, 0-based, a < b
  bool concave = false;  // some piece of it concave (concaveEdges: all)
};

// [in] cad: the solid. Returns its concave sharp edges between two distinct faces.
std::vector<FacePairEdge> concaveEdges(const CadSolid& cad);

// [in] cad: the solid. Returns its sharp edges, concave or convex (FacePairEdge::concave), between two distinct faces.
std::vector<FacePairEdge> sharpEdges(const CadSolid& cad);

// [in] cad: the solid. Per face (0-based), the faces it shares an edge with.
std::vector<std::set<int>> faceNeighbours(const CadSolid& cad);

}  // namespace hexlayer
