// Which faces of a thin solid are its top (ω_t), bottom (ω_b) and lateral (ω_l) surfaces (paper §3),
// and how thick the wall is. The user gives neither: both are measured here by casting rays.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/sheet_edges.hpp"

namespace hexlayer {

class BoundaryTriangles;

// One sample of a face with its inward ray: where it is on the face, its share of the face's area, its
// outward normal, whether the ray crosses the wall (classifyWallSides), the face it hits (-1: none) and how far.
struct RayMark {
  double u = 0, v = 0, area = 0;
  Vec3 point = Vec3::Zero(), normal = Vec3::Zero();
  bool crossing = false;
  int hitFace = -1;
  double length = 0;  // to the hit (0: none)
  double airGap = 0;  // a crossing ray's: the solid in front of the sample, across the air (0: none)
};

// A face's width: twice its area over its perimeter (about the wall's thickness for a rim face, a post's width for its
// foot). [in] face.
double faceWidth(const TopoDS_Shape& face);

struct FaceSide {
  Side side = Side::Lateral;
  double thickness = 0;  // area-weighted median distance to the opposite wall along the inward normal
  double width = 0;      // faceWidth: about the wall thickness for a lateral (rim) face
  double area = 0;
  int opposite = -1;           // 0-based index of the face most rays crossing the wall hit, -1 if none
  double wallShare = 0;        // share of the face's area whose inward rays cross the wall (a wall face: >= 0.5)
  double airGap = 0;           // the narrowest air gap in front of the face's wall, up to 1.5 x its thickness (0: none)
  std::vector<RayMark> marks;  // its samples (mixed_faces.hpp splits a face that is partly wall, partly rim)
};

struct WallSides {
  std::vector<FaceSide> faces;        // indexed like CadSolid::faces, 0-based (FreeCAD's Face<i+1>)
  double thickness = 0;               // area-weighted median over top and bottom faces
  double sheetAreaShare = 0;          // area of top + bottom over the whole boundary
  std::vector<SheetJoin> sheetJoins;  // faces sharing a smooth or convex edge (sheet_edges.hpp)
  std::vector<int> ownSideFaces;      // wall faces facing a wall on their own side: the sheet branches there
  std::vector<SheetJoin> knifeEdges;  // convex edges between faces on opposite sides: a tapered end's tip
  std::vector<int> obliqueRims;       // wall-facing faces made rims: a rim cut so obliquely it faces a wall
  std::vector<int> bendRounds;        // rim-like faces made walls: a bend's outside round at a sharp inside edge
};

// Measures the wall and sorts the faces into top, bottom and lateral.
//  - Rays are cast inward from samples spread over every face. A ray crosses the wall when its middle
//    is about as far from all of the boundary as from its ends (the centre of an inscribed ball); rays
//    from a rim run along the wall or leave it steeply, and their middles lie near a wall. A face is a
//    wall face (top or bottom) when the rays crossing the wall stand for half its area or more, so a
//    rim of any shape (flat, round, fillet-flat-fillet, chamfered, cut obliquely) is lateral, and a
//    wall split into pieces is wall in every piece, unless the piece is narrower than a quarter of the
//    wall (a sliver along a bend, no room for a bubble).
//  - Wall faces sharing a smooth edge are on the same side; faces whose rays cross the wall to each
//    other are on opposite sides; faces sharing a convex sharp edge are on the same side unless that
//    contradicts the rest (the knife edge of a tapered end). A parity union-find takes them in that
//    order; the side whose faces look more towards +z is called Top.
//  - A face on the far side of a knife edge that is at most kMaxObliqueRim walls wide across that edge (its
//    area over the edge's length) is a rim cut obliquely, not a taper: it is made lateral, so the hexes'
//    last column lies on it (sheared by the cut's angle) instead of the wall running out to its tip.
//  - A narrow face whose rays cross no wall but that joins two walls bent round a sharp inside edge (the outside
//    round of a zero-radius bend, bend_rounds.hpp) is a wall face too, listed in bendRounds.
//  - A face narrower than the wall is thick on the surface of a wall face it meets in a smooth edge, facing its way,
//    whose rays land across the wall where that wall's do (or on a face on the same surface), at the wall's thickness,
//    is a wall face too, though most of its rays pass a rim on the way: a wall split into a narrow ring round a hole
//    (a top face split round a hole, a boss's bore bottom over a hole through the plate).
//  - A wall face's samples whose rays cross the wall also cast a ray outward: the nearest solid within 1.5 x the wall
//    there, across the air, is the face's airGap (a hem folded back over its sheet, the legs of a narrow U), which
//    the bubble packing's spacing must stay under.
//  - Walls whose rays cross to a wall that the relations put on their own side (over 2 % of the wall
//    area) are where the sheet branches: they are listed in ownSideFaces (see ownSideError).
// [in] cad: the prepared solid; [in] boundary: its triangles (built here if not given). Throws geometryError when the
// part is not a thin section or its sides cannot be told apart.
WallSides classifyWallSides(const CadSolid& cad);
WallSides classifyWallSides(const CadSolid& cad, const BoundaryTriangles& boundary);

// The same for a solid whose faces were split (mixed_faces.hpp, butt_joints.hpp), the same surfaces: a face left as it
// was keeps its samples, and of their rays only those that hit a face that was split are cast again (on a part with
// many faces most rays are not cast again). [in] cad: the split solid; [in] before, sidesBefore: the solid before the
// split and its classification.
WallSides classifyWallSidesAfterSplit(const CadSolid& cad, const CadSolid& before, const WallSides& sidesBefore);

// The error for a sheet that branches (WallSides::ownSideFaces not empty): the faces and where they
// meet the other walls.
Error ownSideError(const CadSolid& cad, const WallSides& sides);

// CAD features smaller than the quad size, which the quad mesh may smooth over: edges of the top
// and bottom walls shorter than `size` (a small hole's rim, a short edge), faces narrower than it
// (walls) or than half the wall thickness (lateral faces): slivers, small fillets and chamfers.
struct SmallFeatures {
  int shortEdges = 0, narrowFaces = 0;   // narrowFaces: wall or lateral
  Vec3 firstAt = Vec3::Zero();           // the middle of the first such edge, else a point of the first such face
  std::vector<std::string> footFillets;  // fillets at walls' feet smoothed over (foot_fillets.hpp): their faces
  double footFilletRadius = 0;           // the largest of them
};
SmallFeatures findSmallFeatures(const CadSolid& cad, const WallSides& sides, double size);

// Whether lateral face f is narrower than half the wall's thickness (a small feature whatever the quad size: a
// chamfer, a small round, a sliver; findSmallFeatures counts it). [in] sides, f.
inline bool narrowLateral(const WallSides& sides, int f) {
  return sides.faces[f].side == Side::Lateral && sides.faces[f].width < 0.5 * sides.thickness;
}

// The creases of a piece's laps: its edges between a cut face lying along its wall (a foot taken for a wall face: a
// boss merged into a box's wall, cut off along the wall: its flat, lapFeet) and a wall face that is no cut (its
// cylinder), turning at least kMinCreaseTurn from one to the other at the edge's middle. [in] cad: a piece; [in] sides:
// its faces' sides; [in] step: the samples' spacing. Returns each crease sampled from one end to the other, both ends
// included.
std::vector<std::vector<Vec3>> lapCreases(const CadSolid& cad, const WallSides& sides, double step);

}  // namespace hexlayer
