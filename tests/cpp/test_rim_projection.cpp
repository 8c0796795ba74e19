// The rim onto the lateral faces (sweep/rim_projection.hpp) on strips whose ends are cut obliquely: every rim
// column lies on the cut (its last hexes sheared by the cut's angle, the best a hex can do at that edge), the
// columns beside it are shifted upright (where its edges move apart) or lean with it, and the columns at the corners
// with the strip's sides lie on the CAD edges there, so the mesh fills the part exactly. Run on the parts as drawn and
// scaled by 1e-3 and 1e3, each with its planes as drawn and turned into B-spline surfaces (as many exporters and
// scalings write them).
#include <gtest/gtest.h>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <string>

#include "geometry/cad_solid.hpp"
#include "pipeline/pipeline.hpp"
#include "test_boxes.hpp"

using namespace hexlayer;

namespace {

// The sample scaled by factor, its faces B-spline surfaces if bspline.
TopoDS_Solid scaled(const std::string& sample, double factor, bool bspline) {
  const TopoDS_Solid solid =
      readSolids(std::string(HEXLAYER_SOURCE_DIR) + "/Resources/samples/rims/" + sample + ".step").at(0);
  const TopoDS_Solid shape = test_boxes::scaled(solid, factor);
  return TopoDS::Solid(bspline ? BRepBuilderAPI_NurbsConvert(shape, true).Shape() : shape);
}

struct Oblique {
  const char* sample;
  double tilt;  // of the cut from the wall's normal, radians
};

}  // namespace

// strip_oblique_45 (end faces 1.41 walls wide) and strip_oblique_3x (3 walls wide, 19.5 degree edges): 60 x 20 x 2
// parallelograms extruded (rims/README.md). A hex with a corner on an edge of angle a has a scaled Jacobian of
// at most sin(a) = cos(tilt); the rim hexes reach it, no rim column is left where the sweep put it, every rim
// node is on a lateral face, and the mesh's volume is the part's (all its boundary faces are planes). The columns
// beside the rim are shifted upright, not sheared with it: only the rim's own hexes have its angle, and the 3 x
// strip's mean is 0.956 against at most 0.955 for a column of 1/3 at each end of 30 and the rest cubes (0.927
// when the columns beside it leaned with it).
TEST(RimProjection, ObliqueCutsAreMeshedToTheirEdges) {
  for (const Oblique& part : {Oblique{"strip_oblique_45", M_PI / 4}, Oblique{"strip_oblique_3x", std::acos(1.0 / 3)}})
    for (double factor : {1.0, 1e-3, 1e3})
      for (bool bspline : {false, true}) {
        SCOPED_TRACE(std::string(part.sample) + " x " + std::to_string(factor) + (bspline ? " B-spline" : ""));
        MeshOptions o;
        o.layers = 2;
        const MeshResult r = meshSolid(scaled(part.sample, factor, bspline), o);
        EXPECT_EQ(r.report.faces.lateral, 4) << "the cut ends are rims";
        EXPECT_EQ(r.report.rimProjection.columnsKept, 0u);
        EXPECT_EQ(r.report.rimProjection.onLateralFaces, r.report.rimProjection.rimNodes);
        EXPECT_NEAR(r.report.mesh.relativeVolumeError(), 0, 1e-6);
        EXPECT_GE(r.report.mesh.quality.sjMin, std::cos(part.tilt) - 1e-3);
        EXPECT_EQ(r.report.mesh.quality.inverted, 0u);
        EXPECT_GE(r.report.mesh.quality.sjAvg, 0.95);
      }
}
