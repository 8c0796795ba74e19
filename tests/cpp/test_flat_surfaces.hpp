// Chordal surfaces built by hand for the unit tests of quadmesh/ (header-only, no test of its own): flat
// rectangles of unit quads, with holes, shared by test_surface_map.cpp and test_block_grids.cpp.
#pragma once
#include <algorithm>
#include <array>
#include <vector>

#include "chordal/chordal_surface.hpp"

namespace hexlayer::test_flat_surfaces {

// The surface without the vertices no facet uses.
inline ChordalSurface withoutUnusedVertices(const ChordalSurface& s) {
  ChordalSurface out;
  std::vector<int> index(s.vertices.size(), -1);
  for (auto f : s.facets) {
    for (int& v : f)
      if (v >= 0) {
        if (index[v] < 0)
          index[v] = static_cast<int>(out.vertices.size()), out.vertices.push_back(s.vertices[v]),
          out.normals.push_back(s.normals[v]);
        v = index[v];
      }
    out.facets.push_back(f);
  }
  return out;
}

// A flat nx x ny rectangle of unit quads, normal +z, without the cells whose lower left corner is
// in [hx0, hx1) x [hy0, hy1) for each hole (hx0, hx1, hy0, hy1). `chamfered`: each hole's four corner
// cells keep their outer half (a triangle), so the holes are octagons with 45 degree chamfers.
inline ChordalSurface rectangle(int nx, int ny, const std::vector<std::array<int, 4>>& holes = {},
                                bool chamfered = false) {
  ChordalSurface s;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) s.vertices.emplace_back(i, j, 0), s.normals.push_back(Vec3::UnitZ());
  auto v = [&](int i, int j) { return j * (nx + 1) + i; };
  auto inHole = [&](int i, int j) {
    return std::any_of(holes.begin(), holes.end(),
                       [&](const auto& h) { return i >= h[0] && i < h[1] && j >= h[2] && j < h[3]; });
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (!inHole(i, j)) s.facets.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
  for (const auto& [x0, x1, y0, y1] : chamfered ? holes : std::vector<std::array<int, 4>>{}) {
    s.facets.push_back({v(x0, y0), v(x0 + 1, y0), v(x0, y0 + 1), -1});
    s.facets.push_back({v(x1 - 1, y0), v(x1, y0), v(x1, y0 + 1), -1});
    s.facets.push_back({v(x1, y1 - 1), v(x1, y1), v(x1 - 1, y1), -1});
    s.facets.push_back({v(x0, y1 - 1), v(x0 + 1, y1), v(x0, y1), -1});
  }
  return withoutUnusedVertices(s);
}

}  // namespace hexlayer::test_flat_surfaces
