// A quick inside/outside test on the solid's triangulation (prepareSolid's BRepMesh): a point
// farther from the triangles than they may lie from the exact boundary is on the same side of
// both, and the parity of a ray's crossings tells which side. Points nearer the boundary are left
// undecided, for OpenCASCADE's exact classifier.
#pragma once
#include <array>
#include <optional>

#include "core/triangle_tree.hpp"
#include "core/types.hpp"
#include "geometry/cad_solid.hpp"

namespace hexlayer {

enum class Containment : char { kInside, kOutside, kUndecided };

class BoundaryTriangles {
 public:
  // Undecided everywhere if a face has no triangulation or the triangles do not close.
  explicit BoundaryTriangles(const CadSolid& cad);

  // Inside or outside for a point farther than margin() from the triangles whose ray crossings
  // are clean; else undecided.
  Containment classify(const Vec3& p) const;

  // Whether p is surely farther than `distance` from the solid's exact boundary.
  bool fartherThan(const Vec3& p, double distance) const;

  // Whether no triangle comes within `distance` of p (the exact boundary lies within margin() of the
  // triangles), those of faces cut through the part (isCutFace) aside; true when there are no triangles to ask.
  bool noTriangleWithin(const Vec3& p, double distance) const;

  // Twice the largest distance measured between the triangles and the exact faces, plus the
  // shape's largest tolerance and 1e-6 of its diagonal.
  double margin() const { return margin_; }

 private:
  std::optional<TriangleTree> tree_;
  std::optional<TriangleTree> uncut_;  // the triangles of the faces not cut through the part, if some are
  double margin_ = 0;
  std::array<Vec3, 3> rays_;  // directions tried in turn, the first along the solid's thinnest extent
};

}  // namespace hexlayer
