// Plain data passed between the Hex-Layer stages. No stage owns another's internals:
// each stage reads one of these structs and returns the next.
#pragma once
#include <Eigen/Core>
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace hexlayer {

using Vec3 = Eigen::Vector3d;

// Length of the diagonal of the points' bounding box; 0 for none.
inline double boxDiagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

// Where along the segment a-b its point nearest to p lies: 0 at a, 1 at b (0 if a = b).
inline double nearestOnSegment(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  return len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
}

// The angle between two vectors, in [0, pi] (atan2 of the cross's norm and the dot: exact near 0 and pi too).
inline double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

// The median of the values (the upper one of an even count); 0 for none. [in] values: a copy, reordered.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The value below which `share` of the weight lies (0.5: the weighted median); 0 for none. [in] weighted: (value,
// weight) pairs, a copy, reordered.
inline double weightedQuantile(std::vector<std::pair<double, double>> weighted, double share) {
  if (weighted.empty()) return 0;
  std::sort(weighted.begin(), weighted.end());
  double total = 0, acc = 0;
  for (const auto& [value, weight] : weighted) total += weight;
  for (const auto& [value, weight] : weighted)
    if ((acc += weight) >= share * total) return value;
  return weighted.back().first;
}

// Which side of the thin wall a surface point belongs to (paper §3: ω_t, ω_b, ω_l).
enum class Side : signed char { Bottom = -1, Lateral = 0, Top = 1 };

// The 12 edges of a hex as pairs of its corners, in the order of the mid-edge nodes 9-20 of
// CalculiX's C3D20 (= VTK_QUADRATIC_HEXAHEDRON's 8-19): bottom quad, top quad, then the sweep edges.
inline constexpr std::array<std::array<int, 2>, 12> kHexEdges = {
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// HexMesh::nodeOnRim values other than 0.
constexpr char kRimSwept = 1, kRimCap = 2;

// A layered all-hex mesh (paper §7). Node order of each hex follows CalculiX/VTK/Gmsh:
// corners 0-3 form the quad on the bottom side (counter-clockwise seen from the top side),
// corners 4-7 the quad above them, so edges i -> i+4 (i = 0..3) run along the sweep direction.
// Quadratic (20-node) hexes keep their 8 corners in `hexes` and add one node per edge in
// `midEdges`, in kHexEdges order; a mid-edge node is shared by all hexes around its edge.
// A rim cap (rim_cap.hpp) adds one more column of hexes per layer beyond the rim, layered the same way.
struct HexMesh {
  std::vector<Vec3> nodes;
  std::vector<std::array<int, 8>> hexes;
  std::vector<std::array<int, 12>> midEdges;  // empty for linear (8-node) hexes, else one per hex
  std::vector<int> nodeLayer;   // 0 = bottom surface ... layers = top surface; -1 = mid-edge node between two
                                // layers, or a rim cap's node inside the part (rim_cap.hpp)
  std::vector<char> nodeOnRim;  // kRimSwept: swept from a node on the chordal surface's boundary (or mid-edge node of a
                                // rim edge); kRimCap: on a rim cap column (rim_cap.hpp), beyond the sweep; else 0
  std::vector<int> nodeFace;    // CAD face (0-based, FreeCAD's Face1 = 0) the node was put on; -1 if none, or not sized
  int layers = 0;
  bool quadratic() const { return !midEdges.empty(); }
};

// A named set of node ids (0-based), written by the writers as NSET / physical groups.
struct NodeSet {
  std::string name;
  std::vector<int> nodes;
};

// A point put on the CAD: where it is and the face it lies on (0-based index of FreeCAD's FaceN, -1: none).
struct FacePoint {
  Vec3 point;
  int face = -1;
};

// One face of a hex, `localFace` as in kHexFaces (quality.hpp): 0 bottom, 1 top, 2..5 the sides. CalculiX
// and Abaqus name the same faces S1..S6 (S = localFace + 1).
struct HexFace {
  int hex;
  int localFace;
  bool operator==(const HexFace& o) const { return hex == o.hex && localFace == o.localFace; }
};

// The mesh on one CAD face (FreeCAD's "FaceN", N = 1-based index of TopExp::MapShapes(solid, TopAbs_FACE)):
// the boundary nodes on it within the face's tolerance (a node on a CAD edge or vertex is in every face
// there), and the boundary hex faces that lie on it (each boundary hex face on exactly one CAD face).
struct SurfaceGroup {
  std::string name;
  std::vector<int> nodes;         // sorted, corners and mid-edge nodes
  std::vector<HexFace> hexFaces;  // sorted by hex, then local face
};

// A mid-surface shell mesh (issue 20): the quad mesh of the chordal surface as shell elements, each node with the
// wall thickness there. Order 2 adds one mid-side node per quad edge (CalculiX S8R, Gmsh's and VTK's 8-node quad).
// `faces`: per CAD face FaceN the shell nodes whose sweep line ends on it (a wall) or whose sweep column lies on it
// (a rim face: the shell's edge on its mid-line); their hexFaces are empty.
struct ShellMesh {
  std::vector<Vec3> nodes;                   // the quad mesh's nodes, then the mid-side nodes (order 2)
  std::vector<std::array<int, 4>> quads;     // corners, counter-clockwise seen from the top wall
  std::vector<std::array<int, 4>> midSides;  // order 2: the node of edge k (corners k, k + 1) of each quad
  std::vector<double> thickness;             // per node: the wall thickness through it
  std::vector<NodeSet> nodeSets;             // RIM: the nodes on the shell's boundary
  std::vector<SurfaceGroup> faces;           // one per CAD face, Face1..FaceN as FreeCAD numbers them
  bool quadratic() const { return !midSides.empty(); }
};

}  // namespace hexlayer
