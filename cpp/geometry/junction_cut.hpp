// Junctions, first step (issue 18; ../shared/design/junctions.md): the part cut into pieces of one sheet each, as
// an analyst cuts a ribbed part by hand before sweeping it. Every sheet that stands on the base sheet (a rib on a
// plate, a boss, a partition on a floor) is cut off along the base's wall under it: the cut face, its foot, lies
// in that wall's surface (flat or curved); it is a rim face of the standing piece and a piece of the base piece's wall.
// Each piece is then a part the one-sheet method meshes (its chordal surface is 2-manifold).
#pragma once
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

#include <vector>

#include "geometry/cad_solid.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

// Where a standing sheet meets the base: one cut face.
struct Foot {
  int sheet = -1;     // the standing sheet (index into the sheets given; its piece has the same index)
  int base = 0;       // the sheet it stands on (an earlier one: the first sheet, or a wall standing on it)
  int baseFace = -1;  // 0-based face of the base's wall the foot lies on
  TopoDS_Face face;   // the foot, shared (IsSame) by the base's piece and the standing sheet's piece
  double area = 0;
};

struct JunctionCut {
  // Per sheet given, in their order, its piece (pieces[0] is the base); then the further pieces of sheets the cut
  // parts (a boss through the plate: above and below it), each standing on the sheet its feet lie on.
  std::vector<TopoDS_Solid> pieces;
  std::vector<int> sheetOf;  // per piece, the sheet it is (a piece of)
  std::vector<Foot> feet;    // Foot::sheet: the piece standing on it
  // Per piece, per face of the piece (TopExp::MapShapes order, FreeCAD's numbering), the 0-based face of the cut
  // solid it is or is a piece of; -1 for a foot (a face no CAD face gave).
  std::vector<std::vector<int>> faceOrigin;
};

// Ribs crossing (an X): findSheets sees each rib cut in segments by the other. Of two crossing ribs the larger runs
// through: its segments on each side of a crossing (their walls on the same planes, both meeting the other rib's
// segments there) become one sheet, and the other rib's segments stand on it. Crossings are taken largest first;
// a rib whose segments cross one already run through stays in segments there. [in] cad, sides; [in] sheets:
// findSheets's. Returns the sheets, merged, the largest first, then each standing sheet after the standing sheets it
// stands on (both its walls meet theirs: a rib ending on another rib's side, whichever is larger).
std::vector<Sheet> mergeCrossingRibs(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets);

// [in] cad: the solid; [in] sides: its faces' sides (classifyWallSides); [in] sheets: findSheets's, the first
// the base. Every other sheet is cut off along the base's wall faces it stands on (a sheet through the base, on both
// of its walls, in as many pieces as the cut makes of it) (the concave edges between
// its faces, walls and their rim faces, and the base's walls bound its foot; a foot running to the wall's
// edge is closed along it, on the wall's surface: plane, cylinder or any other).
// Throws geometryError naming the sheet's place if no foot can be made, or the cut does not give one piece per
// sheet. [out] (returned) the pieces, their feet and the origin of every piece's face.
JunctionCut cutAtJunctions(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets);

}  // namespace hexlayer
