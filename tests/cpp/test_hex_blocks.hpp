// Hex meshes built by hand for the unit tests of quality/ (header-only, no test of its own): one hex, a
// structured block of hexes, two hexes side by side, shared by test_quality.cpp, test_validation.cpp,
// test_writers.cpp and test_result_file.cpp.
#pragma once
#include <array>
#include <vector>

#include "core/types.hpp"

namespace hexlayer::test_hex_blocks {

using Hex = std::array<Vec3, 8>;

// [in] a, b, c. The corners of the box [0, a] x [0, b] x [0, c] in hex order.
inline Hex box(double a, double b, double c) {
  return {Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a, b, 0), Vec3(0, b, 0),
          Vec3(0, 0, c), Vec3(a, 0, c), Vec3(a, b, c), Vec3(0, b, c)};
}

// Structured block of hexes on the grid xs x ys x zs; node (i,j,k) has id i + nx*(j + ny*k), layer k.
inline HexMesh block(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& zs) {
  HexMesh m;
  const int nx = static_cast<int>(xs.size()), ny = static_cast<int>(ys.size()), nz = static_cast<int>(zs.size());
  auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        m.nodes.emplace_back(xs[i], ys[j], zs[k]);
        m.nodeLayer.push_back(k);
        m.nodeOnRim.push_back(0);
      }
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
        m.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                           id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  m.layers = nz - 1;
  return m;
}

// [in] x. The mesh of that one hex, one layer: nodes 0-3 on layer 0, 4-7 on layer 1.
inline HexMesh singleHex(const Hex& x) {
  HexMesh m;
  m.nodes.assign(x.begin(), x.end());
  m.hexes.push_back({0, 1, 2, 3, 4, 5, 6, 7});
  m.nodeLayer = {0, 0, 0, 0, 1, 1, 1, 1};
  m.layers = 1;
  return m;
}

// 2 x 1 x 1 unit hexes, one layer: 12 nodes, node (i,j,k) has id i + 3*(j + 2*k) and layer k.
inline HexMesh twoHexBlock() {
  HexMesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        m.nodes.emplace_back(i, j, k);
        m.nodeLayer.push_back(k);
        m.nodeOnRim.push_back(0);
      }
  for (int i = 0; i < 2; ++i) m.hexes.push_back({i, i + 1, i + 4, i + 3, i + 6, i + 7, i + 10, i + 9});
  m.layers = 1;
  return m;
}

}  // namespace hexlayer::test_hex_blocks
