// OpenCASCADE's boxes as the box trees' (core/box_tree.hpp).
#pragma once
#include <Bnd_Box.hxx>

#include <cmath>

#include "core/box_tree.hpp"

namespace hexlayer {

// [in] b: a box, its gap included. Returns the same box (empty for a void one).
inline Box boxOf(const Bnd_Box& b) {
  Box box;
  if (b.IsVoid()) return box;
  double x0, y0, z0, x1, y1, z1;
  b.Get(x0, y0, z0, x1, y1, z1);
  box.add(Vec3(x0, y0, z0)), box.add(Vec3(x1, y1, z1));
  return box;
}

// Whether a tree node's box may hold an item whose box is within `limit` of p: a margin far above the rounding
// of the two ways of measuring (the items' own Bnd_Box::Distance decides).
inline bool mayBeWithin(const Vec3& p, const Box& box, double limit) {
  return std::sqrt(squaredDistanceToBox(p, box)) <= limit * (1 + 1e-9) + 1e-12;
}

}  // namespace hexlayer
