// Junctions meshed all-hex and conformal (issue 18; ../shared/design/junctions.md): walls standing on a sheet (ribs,
// bosses, walls on a floor). The part is cut at the walls' feet (junction_cut.hpp); each standing wall's piece is
// meshed as one sheet, and its hex nodes on its foot form a footprint of (layers + 1) rows of quads along the foot
// (a strip, or a ring round a boss); the sheet's quad mesh is made to carry every footprint (footprint_insert.hpp),
// and the sheet's swept nodes under each foot are the wall's foot nodes, by id (append.hpp's joinHexMesh). Every hex
// is a hex of one sheet.
#pragma once
#include <Bnd_Box.hxx>
#include <ShapeAnalysis_Surface.hxx>

#include <optional>
#include <vector>

#include "core/types.hpp"
#include "geometry/junction_cut.hpp"
#include "quadmesh/footprint_insert.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

// The surface a foot lies on (a plane, a cylinder, any), and how far a point near the foot is from it.
class FootSurface {
 public:
  // [in] foot: a foot face of the cut (JunctionCut::feet); [in] tolerance: how near a point lies to it.
  FootSurface(const Foot& foot, double tolerance);
  // Whether p lies on the foot's surface, within the foot's box (within `reach` of them; default: the tolerance).
  bool holds(const Vec3& p, double reach = -1);
  // The point of the foot's surface nearest to p (on a plane: along its normal).
  Vec3 project(const Vec3& p);
  // The foot face's area (the cut's).
  double area() const { return area_; }

 private:
  double area_;
  double tolerance_;
  Bnd_Box box_;
  std::optional<std::pair<Vec3, double>> plane_;  // normal, offset
  Handle(ShapeAnalysis_Surface) surface_;         // none on a plane
};

// [in] cut; [in] sheet: a standing sheet's index (its piece's); [in] base: the sheet it stands on; [in] tolerance.
// Returns the surfaces of its feet on that sheet.
std::vector<FootSurface> footSurfaces(const JunctionCut& cut, int sheet, int base, double tolerance);

// A standing wall's feet as its hexes have them.
struct WallFoot {
  FootprintQuads footprint;   // its nodes where the wall's are (not yet on the sheet's chordal surface)
  std::vector<int> wallNode;  // per footprint node, the wall's hex node it is
  std::vector<char> lap;      // per footprint node, whether it is a lap's (the wall lying along the foot), or empty
  bool ring = false;          // every foot closed on itself (a boss)
  bool column = false;        // the foot filled: a column's (column_piece.hpp)
  std::vector<std::vector<Vec3>> footColumns;  // a wall's sweep columns on the foot, each its nodes (not a column's)
};

// A standing piece whose foot lies across the sheet from the foot of a piece meshed before it (a boss through the
// plate, standing on both of its walls at one place): its quads' rim nodes on the foot are put across from that
// foot's sweep columns (their middles projected onto this foot), so that the two feet are one another's node for node
// and the sheet carries them as one footprint (footprint_insert.hpp's mergeFeetOnBothSides). Only where the rim nodes
// on the foot and the columns across it pair off one to one, each nearest to its own and within `reach`; else the
// quads stay. [in,out] quads: the piece's, its nodes `unit` times the feet's units; [in,out] feet: the piece's own;
// [in] across: the other feet's sweep columns (WallFoot::footColumns, the feet's units); [in] unit; [in] reach: in
// the feet's units. Returns how many rim nodes were put across (0: none).
using FootColumns = std::vector<std::vector<Vec3>>;

// Whether every column's middle, projected onto one of the feet, lies on it (the columns stand across the sheet from
// those feet). [in,out] feet; [in] columns. False if there are none.
bool columnsAcross(std::vector<FootSurface>& feet, const FootColumns& columns);
std::size_t alignFootAcross(QuadMesh& quads, std::vector<FootSurface>& feet, const FootColumns& across, double unit,
                            double reach);

// After the sweep, the piece's sweep columns on its feet that alignFootAcross put across from another foot's columns
// get their nodes across from those (each node projected onto the foot, the nearer end to the nearer end): the
// sweep's columns from two chordal nodes across from one another lean apart by their normals (a few degrees on a
// boss's coarse ring), which left the sheet's columns between them off a round bore. At order 2 a mid-edge node at a
// moved node moves by the mean of its edge's ends' moves. [in,out] piece: its hexes, `unit` times the feet's units;
// [in] quads: it was swept from; [in,out] feet; [in] across; [in] unit; [in] reach: how far (the feet's units) a
// column's middle may be from the one across's projection. Returns how many columns moved.
std::size_t snapFootColumnsAcross(HexMesh& piece, const QuadMesh& quads, std::vector<FootSurface>& feet,
                                  const FootColumns& across, double unit, double reach);

// [in] wall: hexes swept from `quads` (sweep.hpp's layout: quad node q's sweep column is the hex nodes q (m + 1) + k,
// k = 0..m); [in] quads; [in,out] feet: the surfaces of the wall's feet (footSurfaces). Returns the footprint: for
// every rim edge of the quads whose two sweep columns lie on one foot's surface, the m quads between the columns (a
// strip, or a ring); and where the wall lies along a foot, its side face to face with the sheet's wall (a boss merged
// into a box's wall, flattened there: a lap), its hexes' faces on the foot (a patch), their nodes flagged `lap`; and
// the faces of its rim caps' hexes on the foot (a rib's round end: the cap's profile where it meets the foot). Throws
// geometryError if there is none, if it covers under kCoveredFoot of the feet (a lap whose face is not the wall's side:
// only its rim would be joined to the sheet), or if a lap's quads cover under kCoveredLap of its foot (they straddle
// its edges: notches between the wall and the sheet).
WallFoot wallFoot(const HexMesh& wall, const QuadMesh& quads, std::vector<FootSurface>& feet);

// [in] column: hexes swept from `quads` up a column (column_sweep.hpp: each quad node's column in turn). Returns the
// footprint: the quads themselves, their nodes the columns' first (layer 0) nodes.
WallFoot columnFoot(const HexMesh& column, const QuadMesh& quads);

// Per node of the sheet's hexes, the standing walls' node it is, or -1: for every footprint node f the end of the
// sweep column of quad node column[f] nearer to it is walls' node wallNode[f]; for 20-node hexes the mid-edge node
// of every sheet edge between two of them is the walls' mid-edge node of that edge.
// [in] sheet: swept from the quads carrying the footprints, as many layers as the walls, of the same order;
// [in] column: FootprintInsertion::node; [in] walls: the walls' hexes, joined; [in] wallNode: per footprint node, its
// node in walls; [in] tolerance: how far a column's end may be from its foot node. Throws geometryError with the
// distance if one is farther (the sheet's walls do not meet the foot there), or if an edge on a foot is not a wall's.
std::vector<int> footNodesShared(const HexMesh& sheet, const std::vector<int>& column, const HexMesh& walls,
                                 const std::vector<int>& wallNode, double tolerance);

// Ribs crossing a sheet (feet on both its walls at one place, footprint_insert.hpp's mergeFeetOnBothSides): the
// sheet's sweep columns whose two ends are walls' foot nodes end on those, each inner node moved by the ends' moves
// interpolated along the column (a straight, even column stays one; a rim column on a bore through a boss on both
// walls stays on the bore). Where the ribs cross obliquely the two feet are offset along the sheet, so those columns
// lean; the columns within kLeanRings rings of quads round them lean less and less (each end moved by the nearest
// crossed column's end offset times 1 - ring / (kLeanRings + 1)), so that no hex between a leaning column and an
// upright one folds. Columns ending on one wall's foot stay, and rim columns but those next along the rim to a leaning
// rim column (a crossing at the sheet's rim: its offset lies along the rim). At order 2 every edge at a moved node
// whose mid-edge node is not a wall's moves it by the mean of its ends' moves. [in,out] sheet: its columns as sweep.hpp
// lays them; [in] quads: it is swept from; [in] shared: footNodesShared's; [in] walls.
void leanCrossedColumns(HexMesh& sheet, const QuadMesh& quads, const std::vector<int>& shared, const HexMesh& walls);

// Sweep columns ending on one wall's foot whose inner nodes lie off their even places between the column's ends (the
// foot node, the other end) by more than kUnevenColumn of a layer get them there: a column swept from a chordal point
// near one end (on a bend whose chordal surface cuts the inside corner, where a wall's foot ends on the rim). Others
// stay as swept. At order 2 the edges at moved nodes get their mid-edge nodes at their middles. [in,out] sheet; [in]
// columns: its quad nodes' count; [in] shared: footNodesShared's; [in] walls.
inline constexpr double kUnevenColumn = 0.25;
void evenFootColumns(HexMesh& sheet, int columns, const std::vector<int>& shared, const HexMesh& walls);

// The junction hexes: those with a corner among `footNodes`, and their scaled Jacobian's min and mean.
struct JunctionHexes {
  std::size_t hexes = 0;
  double minScaledJacobian = 0, meanScaledJacobian = 0;
};

// [in] mesh; [in] scaledJacobian: per hex; [in] footNodes: node ids. Returns the junction hexes' numbers.
JunctionHexes junctionHexes(const HexMesh& mesh, const std::vector<double>& scaledJacobian,
                            const std::vector<int>& footNodes);

}  // namespace hexlayer
