// Sweep (paper §7): every quad node is swept along the interpolated normal to place the hex nodes
// of all layers (§7.2), and every quad gives one hex per layer (§7.3).
#pragma once
#include <functional>
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "sweep/untangle.hpp"

namespace hexlayer {

struct SweepDirection {
  Vec3 normal;    // unit sweep direction n̄
  double radius;  // half-thickness r
};

// n̄ and r at a point of the chordal surface (§7.1), interpolated from the facet's corners:
// Eq. 4-5 on an edge, Eq. 6-7 (area weights) in a triangle, inverse bilinear weights in a quad.
SweepDirection interpolateSweep(const ChordalSurface& chordal, const ChordalPoint& at);

// Offsets of the m + 1 hex nodes along n̄ in units of the radius r, from bottom to top (§7.2):
// even m: h_i = q ± n̄ s i (one node on the chordal surface); odd m: h_i = q ± n̄ s (i + 0.5);
// both are q + n̄ s (k - m/2), k = 0..m, with step s = 2r/m.
std::vector<double> layerOffsets(int layers);

// The ends of a quad node's sweep line: its images π_b(q) on the bottom and π_t(q) on the top wall (§3),
// and the CAD faces they lie on (-1: an end not on the CAD). The hex nodes at the ends inherit the faces.
struct SweepLine {
  Vec3 bottom, top;
  int bottomFace = -1, topFace = -1;
};

// Where the sweep line of chordal point q, swept along the unit vector n with radius r, meets the walls.
// Called from several OpenMP threads at once.
using WallMap = std::function<SweepLine(const Vec3& q, const Vec3& n, double r)>;

// The paper's sweep line (§7.2): q ∓ r n̄, the walls as the radius function sees them.
SweepLine radiusSweepLine(const Vec3& q, const Vec3& n, double r);

// The hex node at layer offset t (from layerOffsets, -1 at the bottom, +1 at the top) on the sweep
// line of q: q + t (π_t(q) - q) above the chordal surface, q - t (π_b(q) - q) below it.
Vec3 layerNode(const Vec3& q, const SweepLine& line, double t);

// §7.3: one hex per quad and layer, quad j's hex of layer k at index j * m + k; hex node of quad node i in layer k at
// i * (m + 1) + k (nodeLayer k, nodeOnRim for the quads' rim nodes, nodeFace -1; positions left at zero). A quad is
// turned counter-clockwise seen from its nodes' mean `up`, so that every hex is positively oriented once its nodes are
// placed up the columns. [in] q; [in] up: per quad node, its column's direction; [in] m: layers.
HexMesh layeredHexes(const QuadMesh& q, const std::vector<Vec3>& up, int m);

// Builds the layered hex mesh. Quads are turned so that their normal agrees with n̄, which makes
// every hex positively oriented; a quad node shared by quads gives shared hex nodes (conformal).
// Where sweep lines converge (a bend whose inner radius is smaller than the wall's half-thickness)
// the directions are untangled (untangle.hpp) before the nodes are placed for good.
// [in] walls: where each line ends; [in] aimed: if given, the map of the first placement instead, which may turn a
// line (sweep_to_walls.hpp's aimSweepLine): a turned line's direction then replaces the chordal normal, and the
// untangling places its lines with `walls`, as it turns them.
struct SweepResult {
  HexMesh mesh;
  UntangleResult untangled;
};
SweepResult sweepQuads(const QuadMesh& quads, const ChordalLocator& chordal, int layers,
                       const WallMap& walls = radiusSweepLine, const WallMap& aimed = {});

// Every column of a layered mesh (layer 0 to the top: the nodes above one another in the hexes, corners k, k + 4),
// indexed by its bottom node (empty for the other nodes). [in] mesh: nodeLayer sized.
std::vector<std::vector<int>> columnsByBottom(const HexMesh& mesh);

// Each foot end's sweep column (quad node i's: nodes i * (layers + 1) ..., as layeredHexes numbers them): its end
// nearer to `at` put there if it is farther than `near` from it, and the nodes between that end and the chordal
// surface put on the new half line as layerNode puts them. A wall's foot node lies on the sheet's wall, where the
// joined mesh takes it for the column's end; the sweep line from the chordal surface ends at it, or near (a column
// sheared by a tilted wall's foot: a pin upright through a sloping plate), except at a bend's inside corner between
// walls of different thickness, where it ends 1-2 mm off. A lap's node (FootEnd::lap) is put there however near: the
// sheet's hexes there lie face to face with the wall's, every one of their nodes moved by the join else (a boss merged
// into a box's wall, meshed with its foot nodes left to the join: a hex folded where the boss's flat meets the floor).
// [in,out] mesh: as swept; [in] quads: the quad mesh swept (its nodes the chordal points); [in] feet; [in] near.
// Returns per node of the mesh whether it is a foot end, put or near (empty without feet): the smoothing leaves it.
std::vector<char> placeFootEnds(HexMesh& mesh, const QuadMesh& quads, const std::vector<FootEnd>& feet, double near);

}  // namespace hexlayer
