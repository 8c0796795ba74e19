// Which CAD faces a point lies on, and how far it is from one: what FreeCAD's FemMesh.getNodesByFace
// asks of a mesh node (distance to the trimmed face below the face's tolerance).
#pragma once
#include <BRepAdaptor_Surface.hxx>
#include <BRepClass_FaceExplorer.hxx>
#include <BRepExtrema_ExtPC.hxx>
#include <Bnd_Box.hxx>
#include <Extrema_ExtPS.hxx>
#include <NCollection_DataMap.hxx>
#include <TopAbs_State.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/box_grid.hpp"
#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/uv_boundary.hpp"

namespace hexlayer {

class BoxTree;

// Faces' exact boxes (of their geometry: BRepBndLib::AddOptimal's takes milliseconds on a curved face), kept for the
// solids that share faces: the pieces a part is cut into keep most of its faces (junction_cut.hpp), each measured once.
class FaceBoxes {
 public:
  // [in] face. Returns the box kept for it (or for a face IsSame to it: the same surface and place), else null.
  const Bnd_Box* find(const TopoDS_Face& face) const { return boxes_.Seek(face); }
  // [in] face, box: kept (a face kept already keeps its box).
  void keep(const TopoDS_Face& face, const Bnd_Box& box) {
    if (!boxes_.IsBound(face)) boxes_.Bind(face, box);
  }

 private:
  NCollection_DataMap<TopoDS_Shape, Bnd_Box, TopTools_ShapeMapHasher> boxes_;
};

// A point's faces: the face it was put on (first, whatever its distance) and every face sharing a
// vertex with that one that the point lies on within the face's tolerance (a CAD edge or vertex).
struct FacesAtPoint {
  std::vector<int> faces;  // 0-based indices into CadSolid::faces
  double distance = 0;     // from the point to the face it was put on
};

// The solid's faces with what the distance queries need of each, computed once and read by every thread.
class CadFaces {
 public:
  // A face and what BRepExtrema_DistShapeShape would derive from it at every query.
  struct Face {
    TopoDS_Face face;
    std::string name;  // FreeCAD's name of the input face it is (a piece of): "Face<N>"
    double tolerance = 0;
    Bnd_Box exactBox;                   // of the exact geometry, not the triangulation (a torus: its extreme points)
    Bnd_Box box;                        // exactBox enlarged by the tolerance: the quick test of `lies`
    Bnd_Box extremaBox;                 // BRepBndLib::Add, as BRepExtrema boxes the face
    std::vector<gp_Pnt> vertices;       // TopExp::MapShapes order
    std::vector<int> edges;             // into edges()
    std::vector<int> neighbours;        // faces sharing a vertex, ascending
    double uvBounds[4] = {0, 0, 0, 0};  // BRepTools::UVBounds: u1, u2, v1, v2
    std::unique_ptr<UvBoundary> boundary;
    std::unique_ptr<BoxTree> edgeTree;  // over the boxes of `edges`, in their order (none if one is void)
    // A freeform face's triangulation nodes (prepareSolid's) and their (u, v): where a local search for a point's foot
    // starts (CadFaceProbe::footNearSeed); none on the other faces.
    struct Seed {
      Vec3 point;
      gp_Pnt2d uv;
    };
    std::vector<Seed> seeds;
    std::unique_ptr<BoxGrid> seedGrid;  // over the seeds' points, by index
  };
  // An edge and the box BRepExtrema gives it.
  struct Edge {
    TopoDS_Edge edge;
    Bnd_Box box;
    bool degenerated = false;
  };

  // [in] cad; [in,out] boxes: the exact boxes of faces measured before (taken), and of the others (kept); null: none.
  explicit CadFaces(const CadSolid& cad, FaceBoxes* boxes = nullptr);
  ~CadFaces();  // where BoxTree is complete
  int count() const { return static_cast<int>(faces_.size()); }
  double tolerance(int face) const { return faces_[face].tolerance; }
  const Face& face(int face) const { return faces_[face]; }
  const Edge& edge(int edge) const { return edges_[edge]; }
  int edgeCount() const { return static_cast<int>(edges_.size()); }
  // True if BRepExtrema_DistShapeShape keeps the first vertex's distance when another is within
  // Precision::Confusion() of it (it splits the vertex pairs over its thread pool's threads).
  bool keepsFirstVertex() const { return keepsFirstVertex_; }

 private:
  // [in] known: the face's exact box, if measured before.
  static Face makeFace(const CadSolid& cad, int index, const Bnd_Box* known);

  std::vector<Face> faces_;
  std::vector<Edge> edges_;
  bool keepsFirstVertex_ = false;
};

// One thread's distance queries on CadFaces. The distance is OpenCASCADE's BRepExtrema_DistShapeShape
// from a vertex at the point to the trimmed face (to the last bit on planes and the other analytic surfaces; on
// B-splines up to the rounding of the Newton steps, ~1e-9: the extrema tool searches its sample grid as a tree,
// sorted once, not walked at every query as BRepExtrema's is; the shell's surface groups 10.9 -> 2.5 s; a point lying
// on such a face, below its tolerance, by Newton's method from the nearest node of its triangulation: 1.9 -> 0.6 s):
// the smallest of the distances to the face's vertices, to its edges (BRepExtrema_ExtPC) and to the face
// (Extrema_ExtPS, foot points inside it), with the extrema tools built once per face and edge, and the foot points
// classified by the face's UvBoundary (BRepClass_FaceClassifier, as BRepExtrema does, near the face's boundary).
class CadFaceProbe {
 public:
  explicit CadFaceProbe(const CadFaces& faces);
  // Distance from p to the trimmed face `face`: inside, edges and vertices.
  double distance(int face, const Vec3& p);
  // True if p is closer to `face` than the face's tolerance (BRep_Tool::Tolerance, ~1e-7), FreeCAD's test.
  bool lies(int face, const Vec3& p);
  FacesAtPoint facesAt(int face, const Vec3& p);
  // The point of the planar face `face` nearest to p, and its distance, as BRepExtrema_DistShapeShape from a vertex at
  // p gives them (its one solution, to the last bit) where that is p's foot point on the plane, well inside the face
  // by the face's UvBoundary, with every edge and vertex of the face farther from p by more than 10 x BRepExtrema's
  // precision; nullopt elsewhere (or for a face that is not a plane): BRepExtrema is to answer.
  // [in] face: 0-based; [in] p: the point.
  std::optional<std::pair<double, gp_Pnt>> planeFoot(int face, const gp_Pnt& p);
  // The same on a face of any surface (planeFoot on a plane): the nearest extremum, well inside the face, where every
  // vertex and edge of the face is farther from p by more than 10 x BRepExtrema's precision; nullopt elsewhere.
  // [in] face: 0-based; [in] p: the point. Returns the distance and the point.
  std::optional<std::pair<double, gp_Pnt>> foot(int face, const gp_Pnt& p);

 private:
  struct Surface {
    BRepAdaptor_Surface adaptor;
    Extrema_ExtPS extrema;  // points to adaptor
    double tolU = 0, tolV = 0;
  };
  Surface& surface(int face);
  BRepExtrema_ExtPC& curve(int edge);
  TopAbs_State classify(int face, double u, double v);
  std::optional<double> faceDistance(int face, const gp_Pnt& p);
  std::optional<double> footNearSeed(int face, const gp_Pnt& p);
  std::optional<double> edgeDistance(int edge, const TopoDS_Vertex& vertex);
  double vertexDistance(const CadFaces::Face& f, const gp_Pnt& p) const;
  std::optional<double> edgesDistance(const CadFaces::Face& f, const gp_Pnt& p, const Bnd_Box& pointBox,
                                      std::optional<double> nearest);

  const CadFaces& faces_;
  std::vector<std::unique_ptr<Surface>> surfaces_;          // per face, built at its first query
  std::vector<std::unique_ptr<BRepExtrema_ExtPC>> curves_;  // per edge, built at its first query
  // Per face, BRepClass_FaceClassifier's explorer as it sets one up (its edge map and parameter bounds), built at the
  // face's first exact classification: the classifier rewinds it for every point.
  std::vector<std::unique_ptr<BRepClass_FaceExplorer>> explorers_;
};

}  // namespace hexlayer
