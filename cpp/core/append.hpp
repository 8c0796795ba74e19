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

// [in,out] all: the hexes so far, with part's appended (its nodes after all's, its layer count taken).
inline void appendHexMesh(HexMesh& all, const HexMesh& part) {
  const int offset = static_cast<int>(all.nodes.size());
  all.layers = part.layers;
  all.nodes.insert(all.nodes.end(), part.nodes.begin(), part.nodes.end());
  all.nodeLayer.insert(all.nodeLayer.end(), part.nodeLayer.begin(), part.nodeLayer.end());
  all.nodeOnRim.insert(all.nodeOnRim.end(), part.nodeOnRim.begin(), part.nodeOnRim.end());
  all.nodeFace.insert(all.nodeFace.end(), part.nodeFace.begin(), part.nodeFace.end());
  appendCells(all.hexes, part.hexes, offset);
  appendCells(all.midEdges, part.midEdges, offset);
}

}  // namespace hexlayer
