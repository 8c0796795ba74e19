// Points on a CAD face, spread evenly over its triangulation and evaluated on the exact surface.
#pragma once
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <vector>

#include "core/triangle_tree.hpp"
#include "core/types.hpp"

namespace hexlayer {

struct FaceSample {
  Vec3 point;   // on the exact surface
  Vec3 normal;  // unit, pointing out of the solid
  double u = 0, v = 0;
  double area = 0;  // share of the face's area this sample stands for
};

// A triangle of a face's triangulation: its corners in the face's parameter plane and in space.
struct Triangle2d {
  gp_Pnt2d uv[3];
  gp_Pnt xyz[3];
};

// The face's triangulation (prepareSolid makes it), placed where the face is; empty if it has none
// or no parameters at its nodes.
std::vector<Triangle2d> faceTriangles(const TopoDS_Face& face);

// The triangle's corners in space. [in] t.
Triangle spaceTriangle(const Triangle2d& t);

// Samples about one point per spacing x spacing of area (at least one per triangle of the face's
// triangulation), in a deterministic order. The face must have been triangulated (prepareSolid does).
std::vector<FaceSample> sampleFace(const TopoDS_Shape& face, double spacing);

// Area of the face's triangulation.
double triangulatedArea(const TopoDS_Shape& face);

}  // namespace hexlayer
