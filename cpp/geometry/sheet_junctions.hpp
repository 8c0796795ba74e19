// Sheets and their junctions. The method meshes one sheet: a wall whose top and bottom faces run
// on through bends. A rib, a boss or a flange standing on a sheet meets it in a T-junction, where
// the chordal surface would be non-manifold (the paper's open case, §9). Such a sheet is found
// here from the CAD faces, before any node is placed, so that the user learns where it is.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

struct Sheet {
  std::vector<int> faces;      // 0-based (FreeCAD's Face<i+1>), top and bottom faces
  double area = 0;             // of those faces
  double volume = 0;           // about: half the sum of face area x the wall thickness measured from it
  Vec3 centre = Vec3::Zero();  // area-weighted centre of the faces' samples
  bool column = false;         // lateral faces standing on walls (standingColumns): a post, a pin, a block
};

// Wall faces joined by a smooth or convex edge (WallSides::sheetJoins) or across the wall
// (a face and the face its rays hit) are one sheet. Sheets joined only by concave sharp edges
// stand on each other. The first sheet is the largest (the one that is meshed), the others follow
// by decreasing area, then the columns standing on them (standingColumns).
std::vector<Sheet> findSheets(const CadSolid& cad, const WallSides& sides);

// Pieces standing on walls that have no wall of their own (a square post, a block, a low pad: no face's rays cross
// a wall): lateral faces that meet no wall in a smooth or convex edge and are no cut face, joined by their edges, a
// group of them meeting a wall in a concave sharp edge or through a fillet at its foot (a concave fillet below the
// wall's thickness meeting the wall smoothly, which the pipeline removes before the cut: foot_fillets.hpp). A rim
// meets its walls in convex edges and a thickness step's side meets the thicker wall's top in one, so neither is
// taken; a post's side flush with the sheet's rim (one face with it) is left to the rim, the cut closing its foot
// along the rim; a group whose faces are all narrower than half the wall (narrowLateral) within a box less than two
// walls across is a small feature (a nub, a corner's chip), smoothed over and counted as one. Its volume: the
// divergence theorem over its faces from a point of its foot (exact for a plane foot). [in] cad, sides. Returns them
// by decreasing area, `column` set.
std::vector<Sheet> standingColumns(const CadSolid& cad, const WallSides& sides);

// Thickness steps: a lateral face meeting a wall face A in a concave edge and a wall face B in a convex one, A and B
// on the same side, facing the same way there (their normals at the edges' middles within 30 degrees), B's wall
// thicker than A's by over half the face's width, the face (its width: faceWidth) no wider than A's wall: a thinner
// wall going on from a thicker one, its faces stepping in (one or both) across the whole side. (A tab narrower than
// the plate's rim it stands on is not one: the rim face is as wide as the plate's wall; meshed as one sheet its hexes
// were poor, 0.12 / 0.69.) [in] cad, sides; [in] highest: how many of A's walls the face may be wide (kStepWalls: a
// step the sweep's hexes take; infinity: any step, to name one in a refusal). Returns the pairs (A, B), A < B, sorted.
inline constexpr double kStepWalls = 1.05;
std::vector<std::pair<int, int>> thicknessSteps(const CadSolid& cad, const WallSides& sides,
                                                double highest = kStepWalls);

// The sides of the thickness steps the sweep takes (thicknessSteps at kStepWalls): lateral faces that bound no rim of
// the chordal surface, which runs on across them. [in] cad, sides. Returns per face (0-based) 1 if it is one.
std::vector<char> thicknessStepSides(const CadSolid& cad, const WallSides& sides);

// "(x, y, z)": the sheet's centre in the input's units (CadSolid::unit), for messages.
std::string sheetPlace(const CadSolid& cad, const Sheet& s);

// The given wall faces as one sheet (area, estimated volume, centre), e.g. to report them.
Sheet sheetOf(const CadSolid& cad, const WallSides& sides, const std::vector<int>& faces);

// Per face (0-based, `faces` of them), the index of the sheet it is a wall face of, -1 for the others. [in] sheets.
std::vector<int> wallSheetOfFaces(const std::vector<Sheet>& sheets, std::size_t faces);

// Leaves the faces of every sheet but the first out of the walls (they become lateral faces: no
// nodes are placed on them, and the first sheet's chordal surface runs on under them).
// [in] sheets (findSheets, the first kept); [in,out] sides: the other sheets' faces made lateral.
void keepFirstSheet(const std::vector<Sheet>& sheets, WallSides& sides);

}  // namespace hexlayer
