// Butt joints (issue 18). Two walls of one sheet meeting in a sharp inside edge are one sheet bent there (a mitre:
// the sweep column on the bend's chordal crease runs from the inside edge to the outside corner). Where one of them
// ends part way up the other while the other runs on flush with its outside (a box's lower end wall between higher
// side walls, a flange narrower than the plate it is bent from), no column can serve both: the crease ends inside
// the other wall's chordal surface, and the hexes there fold. Such a wall is cut off as a wall standing on the walls
// it meets in sharp inside edges instead, its foot reaching their rim (junction_cut.hpp): its outside face, which
// runs on over the ends of those walls, is split along their inside faces' planes, so that it is a wall face of the
// standing wall alone and the ends are rim faces of the walls it stands on.
#pragma once
#include <cstddef>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

// A wall that butts on walls of its own sheet.
struct ButtJoint {
  int wall = -1;           // 0-based: its inside face, meeting the others in sharp inside (concave) edges
  int outside = -1;        // its outside face (the face its rays cross the wall to)
  std::vector<int> bases;  // the wall faces of its sheet it meets in sharp inside edges
};

// The walls that end on a wall of their own sheet: a wall face A whose rim face C meets a wall face B of A's sheet in
// a sharp inside edge, A and B meeting in one too (the end wall's top on the side wall, beside the corner's inside
// edge). Only planes: A's outside face and the bases are planar. [in] cad; [in] sides (classifyWallSides).
std::vector<ButtJoint> findButtJoints(const CadSolid& cad, const WallSides& sides);

// Every butt joint's outside face split along its bases' planes (where they cross the face), the sides measured
// again. [in,out] cad, sides. Returns how many faces were split (0: none found, or OpenCASCADE could not split them).
std::size_t splitButtJoints(CadSolid& cad, WallSides& sides);

}  // namespace hexlayer
