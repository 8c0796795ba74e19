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

// A layered all-hex mesh (paper §7). Node order of each hex follows CalculiX/VTK/Gmsh:
// corners 0-3 form the quad on the bottom side (counter-clockwise seen from the top side),
// corners 4-7 the quad above them, so edges i -> i+4 (i = 0..3) run along the sweep direction.
struct HexMesh {
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 8>> hexes;
  std::vector<int> nodeLayer;    // 0 = bottom surface ... layers = top surface
  std::vector<char> nodeOnRim;   // swept from a node on the chordal surface's boundary
  int layers = 0;
};

// A named set of node ids (0-based), written by the writers as NSET / physical groups.
struct NodeSet {
  std::string name;
  std::vector<int> nodes;
};

}  // namespace hexlayer
