#include "pipeline/shell_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "core/groups.hpp"

namespace hexlayer {
namespace {

// The hex mesh's nodes of each shell node's sweep column, from the bottom wall to the top wall.
using Columns = std::vector<std::vector<int>>;

// A quad edge: its corners, its mid-side node (order 2, else -1) and how many quads share it (1 on the rim).
struct ShellEdge {
  int a = 0, b = 0, node = -1, uses = 0;
};

// Twice the vector area of quad q: (p2 - p0) x (p3 - p1).
Vec3 quadVectorArea(const std::vector<Vec3>& x, const std::array<int, 4>& q) {
  return (x[q[2]] - x[q[0]]).cross(x[q[3]] - x[q[1]]);
}

void requireSweepLayout(const HexMesh& mesh, const QuadMesh& quads) {
  const std::size_t m = static_cast<std::size_t>(mesh.layers);
  if (m < 1 || quads.nodes.size() * (m + 1) > mesh.nodes.size() || quads.quads.size() * m > mesh.hexes.size())
    throw Error(ExitCode::Internal, "the hex mesh (" + std::to_string(mesh.hexes.size()) +
                                        " hexes) was not swept from the quad mesh (" +
                                        std::to_string(quads.quads.size()) + " quads)");
}

// The corners: quad node i and its column; the quads turned as the sweep turned them (the first layer's hex).
void addCorners(const HexMesh& mesh, const QuadMesh& quads, ShellMesh& shell, Columns& columns) {
  const int m = mesh.layers, stride = m + 1;
  shell.nodes = quads.nodes;
  columns.resize(quads.nodes.size());
  for (std::size_t i = 0; i < quads.nodes.size(); ++i)
    for (int k = 0; k <= m; ++k) columns[i].push_back(static_cast<int>(i) * stride + k);
  shell.quads.resize(quads.quads.size());
  for (std::size_t j = 0; j < quads.quads.size(); ++j)
    for (int c = 0; c < 4; ++c) shell.quads[j][c] = mesh.hexes[j * m][c] / stride;
}

// The mid-side node of edge e of quad j: its column the mid-edge nodes of that edge in every layer (edge e of the
// bottom face, e + 4 of the last layer's top face: kHexEdges), the node midway between the column's wall ends.
void addMidSide(const HexMesh& mesh, std::size_t j, int e, ShellEdge& edge, ShellMesh& shell, Columns& columns) {
  const std::size_t m = static_cast<std::size_t>(mesh.layers);
  std::vector<int> column;
  for (std::size_t k = 0; k < m; ++k) column.push_back(mesh.midEdges[j * m + k][e]);
  column.push_back(mesh.midEdges[j * m + m - 1][e + 4]);
  edge.node = static_cast<int>(shell.nodes.size());
  shell.nodes.push_back(0.5 * (mesh.nodes[column.front()] + mesh.nodes[column.back()]));
  columns.push_back(std::move(column));
}

// Every quad edge once, in the order the quads meet them; order 2 gives each a mid-side node.
std::vector<ShellEdge> addEdges(const HexMesh& mesh, ShellMesh& shell, Columns& columns) {
  std::vector<ShellEdge> edges;
  std::unordered_map<long long, int> index;
  const long long n = static_cast<long long>(shell.nodes.size());
  if (mesh.quadratic()) shell.midSides.resize(shell.quads.size());
  for (std::size_t j = 0; j < shell.quads.size(); ++j)
    for (int e = 0; e < 4; ++e) {
      const int a = shell.quads[j][e], b = shell.quads[j][(e + 1) % 4];
      const auto [at, added] = index.try_emplace(std::min(a, b) * n + std::max(a, b), static_cast<int>(edges.size()));
      if (added) edges.push_back({a, b, -1, 0});
      ShellEdge& edge = edges[at->second];
      ++edge.uses;
      if (!mesh.quadratic()) continue;
      if (added) addMidSide(mesh, j, e, edge, shell, columns);
      shell.midSides[j][e] = edge.node;
    }
  return edges;
}

// RIM: the corners and mid-side nodes of the edges of a single quad.
NodeSet rimNodes(const std::vector<ShellEdge>& edges, std::size_t nodes) {
  std::vector<char> rim(nodes, 0);
  for (const ShellEdge& e : edges)
    if (e.uses == 1) rim[e.a] = rim[e.b] = 1, rim[e.node >= 0 ? e.node : e.a] = 1;
  NodeSet set{"RIM", {}};
  for (std::size_t i = 0; i < nodes; ++i)
    if (rim[i]) set.nodes.push_back(static_cast<int>(i));
  return set;
}

// Unit normal at every node: at a corner the sum of its quads' vector areas, at a mid-side node its corners' mean.
std::vector<Vec3> nodeNormals(const ShellMesh& shell, const std::vector<ShellEdge>& edges) {
  std::vector<Vec3> normal(shell.nodes.size(), Vec3::Zero());
  for (const auto& q : shell.quads) {
    const Vec3 area = quadVectorArea(shell.nodes, q);
    for (int c : q) normal[c] += area;
  }
  for (const ShellEdge& e : edges)
    if (e.node >= 0) normal[e.node] = normal[e.a].normalized() + normal[e.b].normalized();
  for (Vec3& v : normal) v.normalize();
  return normal;
}

// t = |(π_t - π_b) · n| at every node; the distance of the ends where the normal is undefined.
std::vector<double> columnThickness(const HexMesh& mesh, const Columns& columns, const std::vector<Vec3>& normal) {
  std::vector<double> t(columns.size());
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const Vec3 span = mesh.nodes[columns[i].back()] - mesh.nodes[columns[i].front()];
    t[i] = normal[i].allFinite() && normal[i].squaredNorm() > 0.5 ? std::abs(span.dot(normal[i])) : span.norm();
  }
  return t;
}

// Per CAD face the shell nodes with a column node in its surface group, ascending.
std::vector<SurfaceGroup> faceNodes(const HexMesh& mesh, const Columns& columns,
                                    const std::vector<SurfaceGroup>& groups) {
  const Groups<int> ofNode = groupByKey<int>(mesh.nodes.size(), [&](auto emit) {
    for (std::size_t g = 0; g < groups.size(); ++g)
      for (int n : groups[g].nodes) emit(n, static_cast<int>(g));
  });
  std::vector<SurfaceGroup> faces(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) faces[g].name = groups[g].name;
  for (std::size_t s = 0; s < columns.size(); ++s)
    for (int n : columns[s])
      for (int k = ofNode.start[n]; k < ofNode.start[n + 1]; ++k) {
        std::vector<int>& set = faces[ofNode.items[k]].nodes;
        if (set.empty() || set.back() != static_cast<int>(s)) set.push_back(static_cast<int>(s));
      }
  return faces;
}

}  // namespace

ShellMesh midSurfaceShell(const HexMesh& mesh, const QuadMesh& quads, const std::vector<SurfaceGroup>& groups) {
  requireSweepLayout(mesh, quads);
  ShellMesh shell;
  Columns columns;
  addCorners(mesh, quads, shell, columns);
  const std::vector<ShellEdge> edges = addEdges(mesh, shell, columns);
  shell.nodeSets = {rimNodes(edges, shell.nodes.size())};
  shell.thickness = columnThickness(mesh, columns, nodeNormals(shell, edges));
  shell.faces = faceNodes(mesh, columns, groups);
  return shell;
}

double shellArea(const ShellMesh& shell) {
  double area = 0;
  for (const auto& q : shell.quads) area += 0.5 * quadVectorArea(shell.nodes, q).norm();
  return area;
}

ShellRecord measureShell(const ShellMesh& shell, double cadMidSurfaceArea) {
  ShellRecord r;
  r.order = shell.quadratic() ? 2 : 1;
  r.elements = shell.quads.size(), r.nodes = shell.nodes.size();
  r.area = shellArea(shell), r.cadMidSurfaceArea = cadMidSurfaceArea;
  std::vector<double> t = shell.thickness;
  if (t.empty()) return r;
  std::sort(t.begin(), t.end());
  r.thicknessMin = t.front(), r.thicknessMax = t.back();
  r.thicknessMedian = 0.5 * (t[(t.size() - 1) / 2] + t[t.size() / 2]);
  return r;
}

}  // namespace hexlayer
