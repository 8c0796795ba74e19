// π_t, π_b of the paper (§3) for single points: the nearest point of the top (ω_t), the bottom
// (ω_b) or the lateral (ω_l) faces of the CAD solid. Puts the mid-edge nodes of quadratic hexes on
// the walls and the rim nodes on the lateral faces.
#pragma once
#include <BRepExtrema_DistShapeShape.hxx>
#include <Bnd_Box.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

class BoxTree;
class CadFaces;
class FaceBoxes;
class CadFaceProbe;

// The queries may run on several OpenMP threads at once: each thread keeps its own OpenCASCADE distance tools
// (one per face or edge, built at its first query), the answers are the same bits on any thread. A foot point
// well inside a face comes from the face's own extrema tool (CadFaceProbe::foot), BRepExtrema's elsewhere.
class WallProjector {
 public:
  // [in] cad, sides: read at construction; cad's shapes are kept (by handle), not the objects; [in,out] boxes: the
  // faces' exact boxes measured for other solids sharing faces with cad (CadFaces); null: none.
  WallProjector(const CadSolid& cad, const WallSides& sides, FaceBoxes* boxes = nullptr);
  ~WallProjector();
  // The point nearest to p on the faces of the `side` wall (inside a face, on its edges or
  // vertices: trimmed faces, not their underlying surfaces), with the face it was found on (on a CAD
  // edge: one of the faces there); nullopt for a side without faces.
  std::optional<FacePoint> project(Side side, const Vec3& p) const;

  // True if a face of the `side` wall is within `reach` of p: the distance of project(side, p), as
  // BRepExtrema_DistShapeShape measures it (CadFaceProbe::distance), without its nearest point.
  // [in] reach: >= 0; [in] leftOut: per face (0-based), 1 if it is not looked at (empty: none).
  bool reaches(Side side, const Vec3& p, double reach, const std::vector<char>& leftOut = {}) const;

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

  // The solid's faces as the projector measures them (built once: their exact boxes are costly), for other queries
  // on the same solid.
  const CadFaces& faces() const { return *cadFaces_; }

 private:
  struct Piece {
    TopoDS_Shape shape;  // a face, or an edge of a face
    int face;            // in CadSolid::faces, 0-based
    int lateral = -1;    // for a rim edge, the lateral face on its other side
    Bnd_Box box;         // contains the shape: its distance to p bounds the shape's from below
  };
  // Pieces looked through together (a side's faces or rim edges), ascending in pieces_, with a box tree over them.
  struct PieceSet {
    std::vector<int> pieces;
    std::unique_ptr<BoxTree> tree;  // over pieces' boxes, in the order of `pieces` (none if a box is void)
  };
  // A piece's distance query: BRepExtrema_DistShapeShape with the piece loaded once (its sub-shapes' boxes).
  using Distance = std::unique_ptr<BRepExtrema_DistShapeShape>;
  struct Hit {
    double distance;  // from the query point
    FacePoint at;     // the nearest point, with the piece's face
  };
  // A piece whose distance was already asked, and the answer.
  using Known = std::optional<std::pair<int, std::optional<Hit>>>;

  static PieceSet pieceSet(const std::vector<Piece>& all, std::vector<int> ids);
  std::optional<FacePoint> nearest(const PieceSet& set, const Vec3& p) const;
  std::optional<FacePoint> nearestOf(const std::vector<std::pair<double, int>>& order, const TopoDS_Vertex& vertex,
                                     const Known& known) const;
  std::optional<Hit> distance(int piece, const TopoDS_Vertex& vertex) const;
  // distance()'s answer from the face's own extrema tool where that is certain, else nullopt.
  // [in] thread: the caller's.
  std::optional<Hit> faceFoot(int piece, const TopoDS_Vertex& vertex, std::size_t thread) const;
  // The calling thread's probe (built at its first query); null off the threads counted at construction.
  CadFaceProbe* probe() const;

  std::vector<Piece> pieces_;
  std::array<PieceSet, 3> faces_;                      // by side: bottom, lateral, top (Side + 1)
  std::array<PieceSet, 3> rimEdges_;                   // by side (bottom and top): the walls' edges on lateral faces
  std::array<std::map<int, PieceSet>, 3> rimEdgesOf_;  // by side and lateral face: its rim edges
  std::vector<int> pieceOfFace_;                       // per face: its piece (-1: none)
  mutable std::vector<std::vector<Distance>> tools_;   // per thread, per piece (built at its first query)
  // The faces for the foot points (CadFaceProbe::foot), and a probe per thread (built at its first
  // query): on a face with many edges BRepExtrema walks them all for every point.
  std::unique_ptr<CadFaces> cadFaces_;
  mutable std::vector<std::unique_ptr<CadFaceProbe>> probes_;
};

}  // namespace hexlayer
