// Surface groups (issue 3): every boundary node and boundary hex face of the mesh on the CAD face it
// lies on, numbered like FreeCAD (FaceN), and how far the boundary nodes are from their faces.
#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_faces.hpp"
#include "geometry/wall_projector.hpp"
#include "quality/quality.hpp"

namespace hexlayer {

// The boundary nodes of a mesh (corners and mid-edge nodes of its boundary faces `quads`), ascending.
std::vector<int> boundaryNodes(const HexMesh& mesh, const std::vector<BoundaryFace>& quads);

// Gives every boundary node that no stage put on the CAD (nodeFace -1: a sweep ray that missed its
// wall, a rim node kept off its lateral face to save a hex) the nearest face of its side: the
// lateral faces for rim nodes, else the bottom (layer 0) or top (last layer) wall. The node is not
// moved: boundary_deviation says how far off it is. Returns how many nodes got a face this way.
std::size_t faceUnplacedNodes(HexMesh& mesh, const WallProjector& walls, const std::vector<int>& boundary);

struct SurfaceGroups {
  std::vector<SurfaceGroup> groups;  // one per CAD face, Face1..FaceN in order (a group may be empty)
  nlohmann::json surfaceReport;      // report["surface_groups"]
  nlohmann::json deviationReport;    // report["boundary_deviation"]
};

// The groups of a mesh whose boundary nodes all have a nodeFace. A node is in the group of its
// nodeFace and of every neighbouring face it lies on within that face's tolerance (CAD edges and
// vertices); a boundary hex face is in the group its corners share (the nearest of them to its
// centre where they share none or several). Deviation: distance of each boundary node to its
// nodeFace, absolute and relative to the local wall thickness (the hex's sweep edges x layers).
// `quads`: the mesh's boundaryFaces, `boundary`: their boundaryNodes.
SurfaceGroups surfaceGroups(const HexMesh& mesh, const CadFaces& faces, const std::vector<BoundaryFace>& quads,
                            const std::vector<int>& boundary);

// The groups of `part` appended to `all`, for a mesh made of several solids: node and hex ids shifted
// by the part mesh's offsets, faces renumbered after the groups already there (FreeCAD's numbering
// of a compound of disjoint solids).
void appendSurfaceGroups(std::vector<SurfaceGroup>& all, const std::vector<SurfaceGroup>& part, int nodeOffset,
                         int hexOffset);

}  // namespace hexlayer
