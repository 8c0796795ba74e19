// Geometry input (OpenCASCADE): read a CAD file, take its solids, check each is a valid closed solid.
#pragma once
#include <Bnd_Box.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

// One solid with its topology numbered as FreeCAD numbers it (Face1 = faces.FindKey(1), ...).
struct CadSolid {
  TopoDS_Solid solid;
  TopTools_IndexedMapOfShape faces, edges, vertices;
  double volume = 0;    // CAD volume, in the units of `solid`
  double diagonal = 0;  // length of the bounding box diagonal
  double unit = 1;      // lengths of `solid` per length of the input: the input scaled by `unit` (normalizingUnit)
  std::vector<int> inputFace;  // per face (0-based), the input's face it is (a piece of); empty: the same faces
  // Per input face, whether the pipeline cut it through the part (a junction's foot, junction_cut.hpp): the part goes
  // on beyond it, it is no boundary a wall's thickness is measured against. Empty: none.
  std::vector<char> cutInput;
};

// Whether face f (0-based) of the solid is (a piece of) a cut through the part (CadSolid::cutInput).
inline bool isCutFace(const CadSolid& cad, int f) {
  const int input = cad.inputFace.empty() ? f : cad.inputFace[f];
  return input >= 0 && input < static_cast<int>(cad.cutInput.size()) && cad.cutInput[input] != 0;
}

// The input's face that face f (0-based) of the solid is, or is a piece of (mixed_faces.hpp splits faces).
inline int inputFaceOf(const CadSolid& cad, int f) { return cad.inputFace.empty() || f < 0 ? f : cad.inputFace[f]; }

// FreeCAD's name of the input's face that face f is (a piece of): "Face<N>".
inline std::string inputFaceName(const CadSolid& cad, int f) {
  return "Face" + std::to_string(inputFaceOf(cad, f) + 1);
}

// Reads STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep/.brp) and returns every solid in it.
// Throws inputError for a missing/unreadable file or one without a solid; the reading runs in a child
// process, so a reader that hangs or crashes on a damaged file gives an inputError too.
std::vector<TopoDS_Solid> readSolids(const std::string& path);

// The shape in a STEP, IGES or BREP file, read in this process (readSolids reads in a child process, as
// a reader can hang or crash on a damaged file). Throws inputError for an unknown or invalid file.
TopoDS_Shape readShapeInProcess(const std::string& path);

// Checks the solid (BRepCheck, closed shell, positive volume), scales it by `unit` (a copy; 1: as it
// is), numbers its topology and triangulates its faces for the later stages. Throws inputError naming
// what is wrong.
CadSolid prepareSolid(const TopoDS_Solid& solid, double unit = 1);

// The scale that brings a solid whose bounding-box diagonal is below 10 or at least 10 000 inside [10, 10 000): a
// power of 1000 (a part in metres is scaled by 1000, one in microns by 1e-3), else 1. OpenCASCADE's, TetGen's and
// Gmsh's tolerances are partly absolute: a part drawn in metres (or in microns) is met at the size of the same part
// drawn in millimetres, and gives its mesh, scaled.
double normalizingUnit(const TopoDS_Solid& solid);

// Euler characteristic of the solid's boundary, V - E + F - (W - F) (Euler-Poincaré with W wires):
// 2 - 2 x (number of holes) for one shell; a mesh of the solid must have the same.
long eulerCharacteristic(const CadSolid& cad);

// Each vertex of the face (in TopExp_Explorer's order, a vertex once per edge end) at its parameters on the face, as
// BRep_Tool::Parameters gives them (a point-on-surface record, else the end of the face's first edge through the
// vertex), found in one walk over the face's edges: Parameters walks them again for every vertex, which on a face
// with a thousand vertices (a keyboard plate's top) is a million steps. [in] face. Returns the (u, v) of each.
std::vector<gp_Pnt2d> vertexParameters(const TopoDS_Face& face);

// Triangulates the faces of a shape (BRepMesh, faces in parallel, each from its edges' polygons made first: the same
// triangles on any number of threads) to `deflection` and an angle of 0.3 rad by Watson's Delaunay (OpenCASCADE's
// default), but a face bounded by more than kManyEdges edges by Delabella's first: Watson's takes 0.8 s on a plane
// with 200 holes, whose 8 404 boundary points are all its nodes, Delabella's 0.08 s (a face it leaves without
// triangles, which it can, gets Watson's). [in,out] shape; [in] deflection: absolute.
constexpr int kManyEdges = 100;
void triangulateFaces(const TopoDS_Shape& shape, double deflection);

// An OpenCASCADE point as a Vec3.
inline Vec3 toVec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// Unit outward normal of face `f` at parameter (u, v), respecting the face orientation.
// [out] length: if given, |du x dv| there (about 0 near a pole: a cone's apex, where a parameter just past it turns the
// normal over).
Vec3 outwardNormal(const TopoDS_Shape& face, double u, double v, double* length = nullptr);

// The outward normal of `face` at the middle of its edge `edge` (zero if the edge has no curve on the face).
// [in] face, edge.
Vec3 normalAtEdge(const TopoDS_Face& face, const TopoDS_Edge& edge);

// The solid's volume and centre of mass (adaptive Gauss-Kronrod, to `relativeError`: OpenCASCADE's default rule is 1 %
// off on B-spline faces; a solid of planes only by the adaptive Gauss rule, exact there). [in] solid, relativeError.
std::pair<double, Vec3> volumeOf(const TopoDS_Shape& solid, double relativeError = 1e-7);

// The face's plane: its surface's if a plane, or the plane a B-spline (or other) surface lies on within tolerance
// (CAD systems and scaling write planes as B-splines); none if it is curved. [in] face, tolerance.
std::optional<gp_Pln> planeOf(const TopoDS_Shape& face, double tolerance);

// Whether the face lies in a plane within 10 x its own tolerance (planeOf: a plane, or a plane written as a B-spline by
// a CAD system or by a scaling). [in] face.
bool isFlat(const TopoDS_Shape& face);

// The face's cylinder: its surface's if a cylinder, or the circular cylinder a B-spline or Bézier surface lies on
// within tolerance (a boss written as a B-spline, trimmed to the face, has no surface where a rib covers it; its
// cylinder goes on round). None if it is another shape. [in] face, tolerance: absolute.
std::optional<gp_Cylinder> cylinderOf(const TopoDS_Shape& face, double tolerance);

// The radius of a concave fillet face: its larger principal curvature (BRepLProp_SLProps) the same at a 3 x 3 grid
// of points over its parameter box (a cylinder, a sphere, a torus's tube, also written as a B-spline), its centre of
// curvature outside the material (the outward normal points at it); none for any other face. [in] face.
std::optional<double> filletRadius(const TopoDS_Shape& face);

// Whether two planes are one: parallel (within `angle` rad) and each one's origin within `tolerance` of the other.
// [in] a, b, tolerance, angle.
inline bool samePlane(const gp_Pln& a, const gp_Pln& b, double tolerance, double angle = 1e-9) {
  return a.Axis().IsParallel(b.Axis(), angle) && a.Distance(b.Location()) <= tolerance &&
         b.Distance(a.Location()) <= tolerance;
}

// The largest tolerance of the shape's vertices, edges and faces.
double largestTolerance(const TopoDS_Shape& shape);

}  // namespace hexlayer
