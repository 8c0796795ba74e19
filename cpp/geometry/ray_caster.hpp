// Where a line meets the faces of a CAD solid, with only the faces whose boxes the line passes looked at (a
// box tree built once), where OpenCASCADE's IntCurvesFace_ShapeIntersector tries every face for every ray: the
// side classification and the sweep cast a few rays per sample or node, so that was rays x faces. On a face whose
// surface is elementary (a plane, cylinder, cone, sphere or torus) the hits are computed in closed form, as the
// intersector computes them, and classified with the face's UvBoundary, the intersector asked only near the face's
// boundary: its own classification walks every edge of the face at every hit (a cylinder with 150 holes: rays x 150).
#pragma once
#include <BRepAdaptor_Surface.hxx>
#include <IntCurveSurface_TransitionOnCurve.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <gp_Pln.hxx>

#include <memory>
#include <optional>
#include <vector>

#include "core/box_tree.hpp"
#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/uv_boundary.hpp"

namespace hexlayer {

struct RayHit {
  double w = 0;   // parameter along the line (the distance from its origin for a unit direction)
  int face = -1;  // 0-based, in cad.faces
  Vec3 point;
  double u = 0, v = 0;  // on the face's surface
  IntCurveSurface_TransitionOnCurve transition = IntCurveSurface_Tangent;
  bool onBoundary = false;  // within the tolerance of the face's boundary (an edge, a vertex)
};

class RayCaster {
 public:
  // [in] cad: its faces, kept by reference, and its diagonal; [in] tolerance: the intersectors' (a point within it of
  // a face's boundary is on the face).
  RayCaster(const CadSolid& cad, double tolerance);

  // [in] from, dir: the line from + w dir (dir unit); [in] wMin, wMax: the range of w looked at.
  // Every hit in the range, by increasing w (equal w: by face). Not thread-safe (the intersectors keep state).
  std::vector<RayHit> all(const Vec3& from, const Vec3& dir, double wMin, double wMax);

  // The hit of least w in the range (equal w: the lowest face), as the first of all()'s.
  std::optional<RayHit> nearest(const Vec3& from, const Vec3& dir, double wMin, double wMax);

  // Whether p lies inside the solid, by the parity of the faces a ray from p crosses, where two rays agree (three
  // directions tried); nullopt if they disagree or fewer than two gave a clean count (a ray that passes a face's
  // boundary, touches a face, has two hits within `tolerance` of each other, or meets a face whose surface is not
  // analytic, a plane, cylinder, cone, sphere or torus, where its SurfaceGrid leaves the hits undecided, is not
  // counted). A point within
  // `tolerance` of a face along the ray is on the boundary: not inside.
  std::optional<bool> inside(const Vec3& p, double tolerance, double reach);

  const TopoDS_Face& face(int f) const { return faces_[f]->Face(); }

  // How many face queries a face on an elementary surface answered in closed form (not asking its intersector) so far.
  long closedFormAnswers() const { return closedForm_; }
  // How many face queries a non-analytic face answered from its SurfaceGrid (not asking its intersector) so far.
  long gridAnswers() const { return gridAnswers_; }

 private:
  // The faces whose boxes the line meets in the range, by where it enters them, with that w.
  std::vector<std::pair<double, int>> candidates(const Vec3& from, const Vec3& dir, double wMin, double wMax) const;
  // The hits on the faces given (candidates') in [wMin, wMax], by increasing w (equal w: by face).
  std::vector<RayHit> hitsOnFaces(const std::vector<std::pair<double, int>>& faces, const Vec3& from, const Vec3& dir,
                                  double wMin, double wMax);
  // Face f's hits in [wMin, wMax], appended to hits.
  void hitsOnFace(int f, const Vec3& from, const Vec3& dir, double wMin, double wMax, std::vector<RayHit>& hits);

  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> faces_;  // per face
  std::vector<Box> boxes_;
  // Whether the line cannot meet face f's surface in [wMin, wMax] (a plane met clearly outside it, by a margin far
  // above the rounding): OpenCASCADE's intersector would find no hit there, after classifying the plane's point
  // on the face (costly on a face with many edges).
  bool missesPlane(int f, const Vec3& from, const Vec3& dir, double wMin, double wMax) const;

  // A face on an elementary surface (a plane, cylinder, cone, sphere or torus) as IntCurvesFace_Intersector sees it,
  // and its boundary for the quick classification.
  struct ElementaryFace {
    BRepAdaptor_Surface surface;  // restricted to the face's parameter bounds, as the intersector's
    GeomAbs_SurfaceType type = GeomAbs_Plane;
    gp_Pln plane;                          // the surface's, if it is a plane
    bool boundaryMade = false;             // `boundary` was built (at the face's first hit in range)
    std::unique_ptr<UvBoundary> boundary;  // null if its margin is not far above the intersector's tolerance
  };
  enum class ElementaryHits { kDone, kUndecided };
  // The hits of the line on the elementary face f in [wMin, wMax] computed as the intersector does (kDone: appended to
  // hits, if any), or kUndecided (nothing appended) where a hit lies near the face's boundary or the intersector
  // would take its general path (a cone opened nearly flat, a line IntAna_IntLinTorus fails on): the intersector is to
  // decide.
  ElementaryHits elementaryHits(int f, const gp_Lin& line, double wMin, double wMax, std::vector<RayHit>& hits);
  // The line's points on the elementary face f's surface, before classification, as the intersector appends them
  // (its parameters within the surface's periods and bounds, equal points merged); nullopt where the intersector
  // would take its general path.
  std::optional<std::vector<RayHit>> surfacePoints(int f, const gp_Lin& line) const;
  // Those of surfacePoints' in [wMin, wMax] that BRepClass_FaceClassifier puts IN or ON face f with the intersector's
  // widest ON band (onBand), appended to hits: where the intersector throws. False (nothing appended) where
  // surfacePoints has none in closed form.
  bool classifiedPoints(int f, const gp_Lin& line, double wMin, double wMax, std::vector<RayHit>& hits) const;
  // IntCurvesFace_Intersector::InternalCall's widest ON band in (u, v) on the face: max(tolerance, the resolution of
  // the face's and its edges' largest tolerance).
  double onBand(const ElementaryFace& face) const;
  // The face's UvBoundary (built at its first use), its margin far above the intersector's ON band in (u, v), else
  // null (no quick test).
  const UvBoundary* boundary(ElementaryFace& face) const;

  // A face whose surface is not analytic (a B-spline, a surface of revolution...) as a grid of cells over its
  // parameter bounds, each boxed with its points and grown by how far the surface strays from its corners' bilinear
  // patch (twice that, sampled at its middle and its sides' middles): a line meets the surface in a cell only where
  // it passes the cell's box. OpenCASCADE's intersector walks a polyhedron of the surface and sorts its boxes at
  // every query (Bnd_BoundSortBox::Compare): the periodic shell's rays were a quarter of its time.
  struct SurfaceGrid {
    BRepAdaptor_Surface surface;           // restricted to the face's parameter bounds, as the intersector's
    std::vector<double> us, vs;            // the cells' corners' parameters
    std::unique_ptr<BoxTree> cells;        // over the cells' boxes, cell (i, j) at i * (vs.size() - 1) + j
    std::unique_ptr<UvBoundary> boundary;  // null if its margin is not far above the tolerance
  };
  enum class SurfaceHits { kDone, kUndecided };
  SurfaceGrid& surfaceGrid(int f);
  // The hits of the line on the non-analytic face f in [wMin, wMax] (kDone: appended to hits), each found by Newton's
  // method on S(u, v) = from + w dir from the middle of a cell whose box the line passes; kUndecided (nothing
  // appended) where a step does not settle, the line crosses the surface at a grazing angle, or a hit lies near the
  // face's boundary: the intersector is to answer.
  SurfaceHits surfaceHits(int f, const gp_Lin& line, double wMin, double wMax, std::vector<RayHit>& hits);

  std::vector<std::unique_ptr<ElementaryFace>> elementary_;  // per face: null if its surface is not elementary
  std::vector<std::unique_ptr<SurfaceGrid>> grids_;          // per non-analytic face, built at its first query
  double tolerance_, diagonal_;
  long closedForm_ = 0, gridAnswers_ = 0;
  long intersectorOnOtherSurfaces_ = 0;  // queries a non-analytic face left to its intersector
  BoxTree tree_;
};

}  // namespace hexlayer
