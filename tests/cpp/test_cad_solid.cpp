// The CAD solid as the pipeline reads it (geometry/cad_solid.hpp): its volume, the mesh's reference, exact also
// on B-spline faces (OpenCASCADE's default rule is 1 % off there), run at scales 1, 1e-3 and 1e3; and a file that
// holds only a closed shell, read as the solid it bounds.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "geometry/cad_solid.hpp"

using namespace hexlayer;

namespace {

// The upper half of a spherical shell of radii 10 s and 12 s.
TopoDS_Solid hemisphereShell(double s) {
  const TopoDS_Shape outer = BRepPrimAPI_MakeSphere(12 * s, 0, M_PI / 2).Shape();
  const TopoDS_Shape inner = BRepPrimAPI_MakeSphere(10 * s, 0, M_PI / 2).Shape();
  TopExp_Explorer solid(BRepAlgoAPI_Cut(outer, inner).Shape(), TopAbs_SOLID);
  return TopoDS::Solid(solid.Current());
}

}  // namespace

TEST(CadSolid, VolumeIsExactOnAnalyticAndBSplineFaces) {
  for (double s : {1.0, 1e-3, 1e3})
    for (bool bspline : {false, true}) {
      SCOPED_TRACE("x " + std::to_string(s) + (bspline ? " B-spline" : ""));
      const TopoDS_Solid shell = hemisphereShell(s);
      const CadSolid cad =
          prepareSolid(bspline ? TopoDS::Solid(BRepBuilderAPI_NurbsConvert(shell, true).Shape()) : shell);
      const double exact = 2.0 / 3 * M_PI * (12 * 12 * 12 - 10 * 10 * 10) * s * s * s;
      EXPECT_NEAR(cad.volume / exact, 1, 1e-6);
    }
}

// A file holding only the closed shell of a part (as sheet-metal exports often do) gives its solid.
TEST(CadSolid, ClosedShellFileIsReadAsTheSolidItBounds) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40, 30, 2).Solid();
  TopExp_Explorer shell(box, TopAbs_SHELL);
  ASSERT_TRUE(shell.More());
  const std::string path = ::testing::TempDir() + "hexlayer_shell_only.brep";
  ASSERT_TRUE(BRepTools::Write(shell.Current(), path.c_str()));
  const std::vector<TopoDS_Solid> solids = readSolids(path);
  std::remove(path.c_str());
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_NEAR(prepareSolid(solids[0]).volume, 2400.0, 1e-6);
}
