// OpenCASCADE's boxes as the box trees' (core/box_tree.hpp).
#pragma once
#include <Bnd_Box.hxx>

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

}  // namespace hexlayer
