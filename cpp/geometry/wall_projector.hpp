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

  // The point nearest to p on the one face `face` (0-based in CadSolid::faces); nullopt if it has no side.
  std::optional<FacePoint> projectOntoFace(int face, const Vec3& p) const;

  // The point nearest to p on the edges where the `side` wall (Top or Bottom) meets the lateral faces,
  // with the wall face of that edge; nullopt if the wall meets no lateral face.
  std::optional<FacePoint> projectOntoRimEdges(Side side, const Vec3& p) const;

  // The same, on the edges where the `side` wall meets the one lateral face `lateral` (0-based); nullopt if
  // they do not meet.
  std::optional<FacePoint> projectOntoRimEdgesOf(Side side, int lateral, const Vec3& p) const;

  // The point midway between the top and the bottom wall's rim edges nearest to p on the lateral face nearest
  // to p (on the nearest rim edges of either wall if that face meets only one wall: a round's fillet); nullopt
  // if there are none. The middle line of a flat rim, the axis of a round one, the middle of an oblique cut.
  std::optional<Vec3> rimMiddle(const Vec3& p) const;

 private:
  struct Piece {
    TopoDS_Shape shape;  // a face, or an edge of a face
    int face;            // in CadSolid::faces, 0-based
    int lateral = -1;    // for a rim edge, the lateral face on its other side
    Bnd_Box box;         // contains the shape: its distance to p bounds the shape's from below
  };
  static std::optional<FacePoint> nearest(const std::vector<Piece>& pieces, const Vec3& p);
  std::array<std::vector<Piece>, 3> faces_;     // by side: bottom, lateral, top (Side + 1)
  std::array<std::vector<Piece>, 3> rimEdges_;  // by side (bottom and top): the walls' edges on lateral faces
};

}  // namespace hexlayer
