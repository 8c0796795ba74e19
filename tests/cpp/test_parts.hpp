// Parts built in code for the unit tests (header-only, no test of its own): CAD solids that several test files
// mesh or classify, so that each is written once.
#pragma once
#include <BRepPrimAPI_MakeBox.hxx>

#include "geometry/cad_solid.hpp"

namespace hexlayer::test_parts {

// [in] dx, dy, dz. The box [0, dx] x [0, dy] x [0, dz], prepared as the pipeline prepares a solid (unit 1).
inline CadSolid box(double dx, double dy, double dz) {
  return prepareSolid(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), dx, dy, dz).Solid());
}

}  // namespace hexlayer::test_parts
