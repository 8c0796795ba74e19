// CAD faces that are partly wall and partly rim: one B-spline skin that runs over a wall and wraps round its
// edge (as other CAD systems write a rounded rim), which the sides of §3 cannot take whole. Such a face is
// split along a parameter line between the samples whose rays cross the wall and those whose rays do not, so
// that every face is wall or rim; the pieces keep the input face's name (Face<N>) in everything the user sees.
#pragma once
#include <BRepBuilderAPI_MakeShape.hxx>

#include <vector>

#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

// Where one face is split: the parameter line u = at (alongV: the line runs along v) or v = at.
struct FaceSplit {
  int face = -1;  // 0-based in CadSolid::faces
  bool alongV = true;
  double at = 0;
  bool afterOthers = false;  // split once the others are (a round beside a flush rim, whose split line ends on it)
};

// [in] cad, sides (classifyWallSides, with its ray marks). The faces to split: a parameter line parts the
// face's samples into a wall piece (at least kWallPiece of its area crossing the wall) and a rim piece (at
// most kRimPiece), each facing one way, whose mean normals differ by at least kRimTurn (the rim turns away from
// the wall: a band of a flat wall along its rim, whose rays also miss the middle of the wall, does not); the line that
// misplaces the least sample area, on a knot of the surface where one is as good. A skin over a wall, its rim and
// the other wall is split on two knots round the rim piece: two FaceSplits of one face.
std::vector<FaceSplit> findMixedFaces(const CadSolid& cad, const WallSides& sides);

// [in] cad: the solid given to `split`; [in] split: done, its shape a solid with some of cad's faces split (Modified:
// their pieces). That solid prepared (prepareSolid) at cad's unit, each face named after the input face it is (a
// piece of); an empty solid if there is none, or a face has no input face.
CadSolid namedPieces(const CadSolid& cad, BRepBuilderAPI_MakeShape& split);

// [in] cad, splits. The solid with those faces split, prepared (prepareSolid) at the same unit, its
// inputFace naming the input face of every face; an empty solid (faces.Extent() == 0) if OpenCASCADE could
// not split them.
CadSolid splitFaces(const CadSolid& cad, const std::vector<FaceSplit>& splits);

// [in] cad, sides (classifyWallSides, with its ray marks). Wall faces thinner over a part of them (a box's wall whose
// outer half is cut away over its top: a lid's lip; the face inside is 2 walls thick below and 1 above): a parameter
// line parts the face's crossing samples into a thin piece and a thick one, with a step between them (the thin
// piece's 90th percentile under kThinStep x the thick one's 10th: not a taper), each at least kThinPart of the
// face. Split there, each piece gets bubbles for its own thickness (bubble_packing.cpp): sized for the whole face's
// median, the thick part's sparse bubbles made tets across the box's inside corners, dropped as outside, which tore
// the chordal surface over the lip. One split per face.
std::vector<FaceSplit> findThinParts(const CadSolid& cad, const WallSides& sides);

// [in] cad, splits (findThinParts's). The solid with those faces split, as splitFaces, and each face OpenCASCADE
// left whole (where two faces' lines end at one point of the edge they share, round a box's inside corner) split
// again on its own; an empty solid if OpenCASCADE could not split them.
CadSolid splitThinParts(const CadSolid& cad, const std::vector<FaceSplit>& splits);

// Faces that are partly wall and partly rim split into pieces that are one or the other (findMixedFaces, splitFaces),
// the sides measured again, for as many rounds as there are such faces (at most kMaxSplitRounds); then the wall faces
// thinner over a part (findThinParts, splitThinParts), measured again. [in,out] cad, sides. Returns how many faces
// were split.
std::size_t splitMixedFaces(CadSolid& cad, WallSides& sides);

}  // namespace hexlayer
