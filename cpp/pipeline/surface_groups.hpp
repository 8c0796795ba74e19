// Surface groups (issue 3): every boundary node and boundary hex face of the mesh on the CAD face it
// lies on, numbered like FreeCAD (FaceN), and how far the boundary nodes are from their faces.
#pragma once
#include <optional>
#include <string>
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
// [in,out] mesh: nodeFace set for those nodes; [in] walls: the nearest-point projector; [in] boundary: the mesh's
// boundaryNodes.
std::size_t faceUnplacedNodes(HexMesh& mesh, const WallProjector& walls, const std::vector<int>& boundary);

// How the boundary was grouped (report "surface_groups").
struct SurfaceGroupStats {
  int cadFaces = 0;                            // groups, one per CAD face
  std::size_t meshedCadFaces = 0;              // of them with element faces
  std::size_t boundaryNodes = 0;               // nodes of the boundary faces
  std::size_t nodesOnSeveralFaces = 0;         // on a CAD edge or vertex: in several groups
  std::size_t elementFaces = 0;                // boundary hex faces
  std::size_t elementFacesAcrossCadEdges = 0;  // whose corners share no CAD face
  std::size_t nodesNotPutOnCad = 0;            // faceUnplacedNodes (not counted by surfaceGroups)
};

// Boundary nodes farther from their CAD face than its tolerance, per kind of node.
struct OffFaceCounts {
  int wallCorners = 0, rimCorners = 0, wallMidEdge = 0, rimMidEdge = 0;
};

// How far the boundary nodes are from their CAD faces (report "boundary_deviation"); relative: over the local wall
// thickness.
struct BoundaryDeviation {
  std::size_t nodes = 0;  // boundary nodes
  double max = 0, mean = 0, maxRelative = 0, meanRelative = 0;
  OffFaceCounts offFaceTolerance;
  std::optional<Vec3> worstAt;  // the farthest node (none without boundary nodes)
  std::string worstFace;        // its face's name (FaceN)
};

struct SurfaceGroups {
  std::vector<SurfaceGroup> groups;  // one per CAD face, Face1..FaceN in order (a group may be empty)
  SurfaceGroupStats stats;
  BoundaryDeviation deviation;
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
// [in,out] all: the groups so far, part's appended; [in] part, nodeOffset, hexOffset.
void appendSurfaceGroups(std::vector<SurfaceGroup>& all, const std::vector<SurfaceGroup>& part, int nodeOffset,
                         int hexOffset);

}  // namespace hexlayer
