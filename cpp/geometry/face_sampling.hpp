// Points on a CAD face, spread evenly over its triangulation and evaluated on the exact surface.
#pragma once
#include <TopoDS_Shape.hxx>
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

struct FaceSample {
  Vec3 point;        // on the exact surface
  Vec3 normal;       // unit, pointing out of the solid
  double u = 0, v = 0;
  double area = 0;   // share of the face's area this sample stands for
};

// Samples about one point per spacing x spacing of area (at least one per triangle of the face's
// triangulation), in a deterministic order. The face must have been triangulated (prepareSolid does).
std::vector<FaceSample> sampleFace(const TopoDS_Shape& face, double spacing);

// Area of the face's triangulation.
double triangulatedArea(const TopoDS_Shape& face);

}  // namespace hexlayer
