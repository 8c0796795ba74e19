// π_t, π_b of the paper (§3) for single points: the nearest point of the top (ω_t), the bottom
// (ω_b) or the lateral (ω_l) faces of the CAD solid. Puts the mid-edge nodes of quadratic hexes on
// the walls and the rim nodes on the lateral faces.
#pragma once
#include <Bnd_Box.hxx>
#include <TopoDS_Face.hxx>

#include <array>
#include <optional>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

class WallProjector {
 public:
  WallProjector(const CadSolid& cad, const WallSides& sides);
  // The point nearest to p on the faces of the `side` wall (inside a face, on its edges or
  // vertices: trimmed faces, not their underlying surfaces), with the face it was found on (on a CAD
  // edge: one of the faces there); nullopt for a side without faces.
  std::optional<FacePoint> project(Side side, const Vec3& p) const;

 private:
  struct WallFace {
    TopoDS_Face face;
    int index;   // in CadSolid::faces, 0-based
    Bnd_Box box;  // contains the face: its distance to p bounds the face's from below
  };
  std::array<std::vector<WallFace>, 3> faces_;  // by side: bottom, lateral, top (Side + 1)
};

}  // namespace hexlayer
