// A column's foot meshed with quads (issue 18; column_piece.hpp): its outline divided at the quad size, Gmsh's quads
// inside it, every outline node fixed (footprint_insert.hpp's quadsInPolygon). The column's hexes are these quads
// swept up its axis (column_sweep.hpp); the sheet it stands on carries them as a footprint.
#pragma once
#include <Eigen/Core>

#include <optional>
#include <vector>

#include "core/child_process.hpp"
#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/column_piece.hpp"
#include "quadmesh/footprint_insert.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

struct ColumnFoot {
  QuadMesh quads;                             // on the foot, counter-clockwise seen from up the axis
  std::vector<std::vector<int>> loops;        // the outline: the outer loop counter-clockwise, then the holes clockwise
  std::vector<std::vector<int>> steps;        // the steps' outlines (column_piece.hpp's ledges), counter-clockwise
  Vec3 e1 = Vec3::Zero(), e2 = Vec3::Zero();  // the plane's axes (e1 x e2 = the column's axis), from its origin
};

// [in] foot, column; [in] p: a point. Returns its coordinates in the foot's plane (along e1 and e2 from its origin).
inline Eigen::Vector2d onFootPlane(const ColumnFoot& foot, const ColumnPiece& column, const Vec3& p) {
  return {(p - column.origin).dot(foot.e1), (p - column.origin).dot(foot.e2)};
}

// A closed loop of curves whose edges are not all straight (a round pin) gets at least this many nodes.
inline constexpr int kMinRoundLoop = 8;

// [in] cad: the column's piece (prepared); [in] column: columnPiece's; [in] size: the quad size; [in] server: forks
// Gmsh (null: this process). Every edge of the foot's wires is divided evenly into ceil(length / size) segments (a
// closed edge into three or more), a loop that is not all straight into kMinRoundLoop or more, the longest segments'
// edge once more where a loop's count is odd. Returns the quads, the loops' nodes first (exactly on the edges); a
// foot off its plane (curved, or tilted to the axis) gets its quads made on the plane and their inner nodes put on
// it along the axis.
// Throws geometryError if Gmsh cannot fill the foot with quads.
ColumnFoot columnFootQuads(const CadSolid& cad, const ColumnPiece& column, double size, ForkServer* server);

// A column standing on the other side of the sheet where another stands (a pin through a plate) takes that one's foot:
// its quads, their nodes put on this foot along the axis, turned to run counter-clockwise seen from up this axis, so
// that the two feet are one another's node for node (footprint_insert.hpp's mergeFeetOnBothSides). [in] cad, column:
// as columnFootQuads's; [in] other: the other column's foot quads, in cad's units; [in] size: the quad size. Returns
// nullopt unless every outline node lands on this foot's edges (within a hundredth of the size), in as many loops as
// the foot has wires (a pin of one section through the plate; a cone's feet differ).
std::optional<ColumnFoot> columnFootAcross(const CadSolid& cad, const ColumnPiece& column, const FootprintQuads& other,
                                           double size);

}  // namespace hexlayer
