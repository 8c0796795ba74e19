// A column standing on a sheet (issue 18): a pin, a post, a block thicker than the wall it stands on, cut off at its
// foot (junction_cut.hpp). It is no thin sheet (its two sides are farther apart than the part is thin), but every
// line along its axis (its foot's normal) runs from the foot to its cap inside it: its hexes are its foot's quads
// swept along the axis (column_sweep.hpp), as a sheet's are its chordal surface's swept across its wall.
#pragma once
#include <TopoDS_Wire.hxx>

#include <optional>
#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "geometry/wall_sides.hpp"

namespace hexlayer {

// A ledge: a cap below the column's top from whose edges a side rises, all round an outline at one height (a blind
// bore's bottom, flat or a drill point's cone; a shoulder; a counterbore's floor). The column's hexes under it stop
// there, those beside it go on up (column_sweep.hpp); the foot's quads follow the outline of every step
// (column_foot.hpp).
struct ColumnLedge {
  int face = -1;                   // the cap (0-based in CadSolid::faces)
  double height = 0;               // its steps' outlines' over the foot's plane, along the axis (no point of it higher)
  std::vector<TopoDS_Wire> steps;  // its wires a rising side shares all of: a step's closed outline
  bool partial = false;            // no ledge the sweep takes (a step that runs to the column's side): refused
};

struct ColumnPiece {
  int foot = -1;               // the face the column stands on (0-based in CadSolid::faces): a cut face
  std::vector<int> sides;      // the faces along the axis: every normal within kMaxColumnDraft of square to it
  std::vector<int> caps;       // the others: facing up the axis (a flat top, a rounded or domed tip)
  Vec3 axis = Vec3::Zero();    // up the column: its sides' direction, or the foot's normal into it (at its middle)
  Vec3 origin = Vec3::Zero();  // a point of the foot's plane (square to the axis; through the foot's middle if off it)
  double height = 0;           // the column's reach along the axis from the foot's plane
  bool footOffPlane = false;   // the foot is curved or tilted to the axis: its nodes are put on it along the axis
  std::vector<ColumnLedge> ledges;  // lowest first; none for a column whose caps all end it
};

// A side may lean this far (radians) from the axis (a draft, a cone); a cap's normals as far below square to it.
inline constexpr double kMaxColumnDraft = 0.35;  // 20 degrees
// Of the column's height: a cap this much or more below its top, with a side rising from it, is a ledge.
inline constexpr double kLedgeDrop = 1e-3;

// [in] cad: a piece cut off the part (CadSolid::cutInput: its cut faces), prepared (its faces triangulated).
// The axis is the foot's normal at its middle, or the direction the sides run in if that is over a degree off it (a
// pin or post drawn straight on a wall sloping up to 45 degrees or on a curved one: its sides' normals' least-squares
// square direction). Returns the column if its one cut face is a plane square to the axis (or lies on one), or is
// curved or tilted with its normals within 45 degrees of the axis (a pin on a shell, on a slope), and every other
// face's normals (at its
// triangulation's nodes) face the axis's way or square to it within kMaxColumnDraft (no face looks back at the foot:
// no overhang, so every line up the axis from the foot leaves the column through a cap), with at least one cap;
// nullopt otherwise. Its ledges: the caps one of whose edges a side shares that reaches higher by more than
// kLedgeDrop of its height (a rising side); a wire all of whose edges rise, level within as much, is a step; a ledge
// with a wire part of whose edges rise, or steps at two heights, or rising over its steps is `partial`.
std::optional<ColumnPiece> columnPiece(const CadSolid& cad);

// A column's faces as a sheet's walls (what the sweep projects onto): its foot the bottom, its caps the top, its sides
// the rim; its thickness the foot's width (faceWidth). [in] cad, column.
WallSides columnSides(const CadSolid& cad, const ColumnPiece& column);

}  // namespace hexlayer
