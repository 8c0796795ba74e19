// Bends whose inside edge is sharp. Two walls meeting in a sharp inside (concave) edge, their outside faces joined
// by a small round or a chamfer, are one sheet bent with a zero inside radius, as a sheet-metal or molded box is
// at its floor and corners. The round's inward rays run to the sharp inside edge and cross no wall, so the round
// alone would be a rim face (wall_sides.hpp) and the walls two sheets, one standing on the other. The round is a
// top or bottom face of the bent sheet instead (paper §3: ω_t and ω_b run on through a bend).
#pragma once
#include <map>
#include <vector>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

// The rim (lateral) faces that are the outside of a bend with a sharp (or small chamfered or rounded) inside edge:
//  - a face at most as wide as the wall is thick (FaceSide::width: a round of radius up to about 0.6 x the wall)
//    tangent (a smooth edge, WallSides::sheetJoins) to two wall faces whose rays cross the wall to two faces meeting
//    in the bend's inside (a concave edge, or a face narrower than the wall sharing a concave edge with both), and
//    joined by no smooth or convex edge to two walls facing each other (a rim across the wall joins a wall to its
//    other side), or
//  - a chamfer: a face at most sqrt 2 x the thicker wall wide meeting two such walls in convex sharp edges, most of
//    its own rays landing on the bend's inside faces (a molded cover's chamfered outside edge; a channel's flat end
//    face at a corner looks along the bend instead), and
//  - then, repeatedly, a face as narrow joined by such edges only to wall faces and faces found so, tangent to at
//    least two of those: a sphere, torus or cone where rounds or chamfers of three walls meet at a corner.
// A rim's round (tangent to one wall, or to two facing each other across the wall) is none of them, nor is a rim
// face meeting walls that face each other.
// [in] cad: the solid; [in] w: the first classification (sides Top or Lateral, sheetJoins, thickness);
// [in] across: per face, the ray area crossing the wall to each face. Returns the faces, ascending.
std::vector<int> findBendRounds(const CadSolid& cad, const WallSides& w,
                                const std::vector<std::map<int, double>>& across);

}  // namespace hexlayer
