// Fillets at the feet of walls standing on a sheet (issue 18: "fillets at a rib's foot may be smoothed over when
// smaller than the quad size; report them, as small_features does"). A sheet that stands on another through fillets
// meets it in no concave edge, so the cut finds no foot. Its fillets are the concave faces of one radius below the
// wall thickness (their larger principal curvature the same across them: cylinders, spheres, tori's tubes, also
// written as B-splines) joining its faces, across such faces, to faces of the sheets before it, and chamfers: plane
// rim faces narrower than the wall whose edges with walls are all concave (a 45-degree chamfer at a rib's root). They
// are removed with OpenCASCADE's defeaturing (BRepAlgoAPI_Defeaturing: the faces beside them extended to meet in the
// sharp edge the fillet rounded; where it leaves them, as beside a plate written in pieces, the faces on one surface
// merged first), and the part so smoothed is cut and meshed; the pipeline groups the fillets' nodes and element faces
// (and those of faces merged) by nearness and reports them.
#pragma once
#include <TopoDS_Solid.hxx>

#include <optional>
#include <vector>

#include "geometry/cad_solid.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

struct FootFillets {
  CadSolid smooth;           // the part without them (its inputFace: the input's face each face is, a piece of)
  std::vector<int> faces;    // the part's faces removed, 0-based
  double largestRadius = 0;  // of those faces (a chamfer's: its width)
  WallSides sides;           // smooth's faces' sides (classifyWallSides), no mixed face split yet
  std::vector<int> merged;   // the part's faces (0-based) merged into a neighbour on their surface before the fillets
                             // could be removed (a plate written in pieces): no face of smooth is named after them
};

// [in] cad: the part (pipeline units); [in] sides: its faces' sides; [in] sheets: findSheets's, the first the base.
// Returns the part without the fillets at the feet of the standing sheets that meet the sheets before them in no
// concave edge; none if there are no such sheets or fillets, or the defeaturing fails (the cut then refuses the
// sheet, naming it).
std::optional<FootFillets> removeFootFillets(const CadSolid& cad, const WallSides& sides,
                                             const std::vector<Sheet>& sheets);

// A part that is one sheet only through fillets at its walls' feet (a boss whose root fillet joins its wall to the
// plate's smoothly: findSheets sees one sheet): the part without every concave fillet below the wall thickness that
// meets two other faces tangentially and none in a concave sharp edge (not a bore), if it then is sheets standing on
// sheets; none otherwise (a bent sheet's inside rounds removed leave one sheet: it is
// meshed as it is). [in] cad: the part (pipeline units); [in] sides: its faces' sides.
std::optional<FootFillets> removeRootFillets(const CadSolid& cad, const WallSides& sides);

}  // namespace hexlayer
