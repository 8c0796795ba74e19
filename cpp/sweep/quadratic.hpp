// Quadratic hexes: the layered mesh of the sweep (§7) turned into 20-node serendipity hexes
// (CalculiX C3D20, VTK_QUADRATIC_HEXAHEDRON) by one node on every edge, shared by the hexes
// around that edge. Where an edge lies on the top or bottom wall its node is put on the CAD wall.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>

#include "core/types.hpp"

namespace hexlayer {

// The point of the `side` wall (Side::Top, Side::Bottom or Side::Lateral) nearest to p and its CAD face; nullopt if
// there is none.
using WallProjection = std::function<std::optional<FacePoint>(Side side, const Vec3& p)>;

struct QuadraticStats {
  std::size_t midNodes = 0;      // nodes added, one per edge of the mesh
  std::size_t wallNodes = 0;     // of them on an edge of the top or bottom wall
  std::size_t projected = 0;     // wall nodes moved onto the CAD wall
  std::size_t rimNodes = 0;      // nodes on an edge of a lateral boundary face (the rim)
  std::size_t rimProjected = 0;  // of them moved onto a lateral CAD face
  double maxProjectionMove = 0;  // largest distance a node was moved onto the CAD
};

// Adds the mid-edge nodes to `mesh` (ids after the corners, numbered by first appearance going
// through the hexes in order and their edges in kHexEdges order) and fills mesh.midEdges; a node
// projected onto the CAD gets its face in mesh.nodeFace (if sized), the others -1.
//  - sweep edge (layer k to k + 1): midpoint of its ends, on the straight sweep line; layer -1.
//  - edge of the top (bottom) wall, both ends in the last (first) layer: its midpoint projected
//    onto that wall; the midpoint is kept when the projection fails or would move it farther
//    than a quarter of the edge length (a bulge that large folds the element).
//  - edge of an inner layer: between the nodes of the bottom and top wall edges of the same two
//    sweep lines, at the mean fraction of its ends along their sweep lines (exact on a block).
//  - edge on the rim (on a lateral boundary face of the mesh): its node, placed as above, then
//    projected onto the lateral CAD faces (ω_l) under the same quarter-edge limit; on a rim wall edge
//    that puts it on the CAD edge between wall and lateral face.
// Requires a linear mesh with nodeLayer and nodeOnRim.
// [in,out] mesh: the mid-edge nodes appended (nodes, nodeLayer, nodeOnRim, nodeFace if sized), midEdges filled;
// [in] project: the projection onto the CAD walls.
QuadraticStats addMidEdgeNodes(HexMesh& mesh, const WallProjection& project);

}  // namespace hexlayer
