// Plain data passed between the Hex-Layer stages. No stage owns another's internals:
// each stage reads one of these structs and returns the next.
#pragma once
#include <Eigen/Core>
#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

namespace hexlayer {

using Vec3 = Eigen::Vector3d;

// Which side of the thin wall a surface point belongs to (paper §3: ω_t, ω_b, ω_l).
enum class Side : signed char { Bottom = -1, Lateral = 0, Top = 1 };

// The 12 edges of a hex as pairs of its corners, in the order of the mid-edge nodes 9-20 of
// CalculiX's C3D20 (= VTK_QUADRATIC_HEXAHEDRON's 8-19): bottom quad, top quad, then the sweep edges.
inline constexpr std::array<std::array<int, 2>, 12> kHexEdges = {{
    {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// A layered all-hex mesh (paper §7). Node order of each hex follows CalculiX/VTK/Gmsh:
// corners 0-3 form the quad on the bottom side (counter-clockwise seen from the top side),
// corners 4-7 the quad above them, so edges i -> i+4 (i = 0..3) run along the sweep direction.
// Quadratic (20-node) hexes keep their 8 corners in `hexes` and add one node per edge in
// `midEdges`, in kHexEdges order; a mid-edge node is shared by all hexes around its edge.
struct HexMesh {
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 8>> hexes;
  std::vector<std::array<int, 12>> midEdges;  // empty for linear (8-node) hexes, else one per hex
  std::vector<int> nodeLayer;    // 0 = bottom surface ... layers = top surface; -1 = mid-edge node between two layers
  std::vector<char> nodeOnRim;   // swept from a node on the chordal surface's boundary (or mid-edge node of a rim edge)
  int layers = 0;
  bool quadratic() const { return !midEdges.empty(); }
};

// A named set of node ids (0-based), written by the writers as NSET / physical groups.
struct NodeSet {
  std::string name;
  std::vector<int> nodes;
};

}  // namespace hexlayer
