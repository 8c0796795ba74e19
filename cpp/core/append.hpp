// Concatenation of meshes (several solids of one file give one result): the cells of one more mesh after
// those already there, their node ids shifted by the nodes already there; -1 (a triangle's missing fourth
// corner) stays -1.
#pragma once
#include <vector>

#include "core/types.hpp"

namespace hexlayer {

// [in,out] to: the cells so far; [in] from: the next mesh's cells; [in] offset: the nodes before the next mesh's.
template <class Cell>
void appendCells(std::vector<Cell>& to, const std::vector<Cell>& from, int offset) {
  for (Cell cell : from) {
    for (int& v : cell) v += v >= 0 ? offset : 0;
    to.push_back(cell);
  }
}

// Two hex meshes joined where they share nodes (issue 18: a rib's hexes and the plate's under its foot): part's
// nodes that are nodes of `all` are those nodes, by id (not merged by distance); its other nodes and per-node data
// follow all's, in their order. [in,out] all: the hexes so far, with part's appended (its layer count taken);
// [in] part; [in] shared: per node of part, the node of `all` it is, or -1 (a new node).
// Returns per node of part its id in `all`.
inline std::vector<int> joinHexMesh(HexMesh& all, const HexMesh& part, const std::vector<int>& shared) {
  std::vector<int> id(part.nodes.size());
  all.layers = part.layers;
  for (std::size_t i = 0; i < part.nodes.size(); ++i) {
    id[i] = shared[i] >= 0 ? shared[i] : static_cast<int>(all.nodes.size());
    if (shared[i] >= 0) continue;
    all.nodes.push_back(part.nodes[i]);
    all.nodeLayer.push_back(part.nodeLayer[i]);
    all.nodeOnRim.push_back(part.nodeOnRim[i]);
    all.nodeFace.push_back(part.nodeFace[i]);
  }
  auto renumbered = [&](auto cell) {
    for (int& v : cell) v = id[v];
    return cell;
  };
  for (const auto& h : part.hexes) all.hexes.push_back(renumbered(h));
  for (const auto& e : part.midEdges) all.midEdges.push_back(renumbered(e));
  return id;
}

// [in,out] all: the hexes so far, with part's appended (its nodes after all's, its layer count taken).
inline void appendHexMesh(HexMesh& all, const HexMesh& part) {
  joinHexMesh(all, part, std::vector<int>(part.nodes.size(), -1));
}

}  // namespace hexlayer
