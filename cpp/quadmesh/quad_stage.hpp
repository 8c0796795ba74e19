// §6 as the pipeline runs it: the chordal surface faired as much as Gmsh can reparametrize (strongest first,
// then less: Gmsh's reparametrization fails on one surface and not on another), its normals and radius
// (Eq. 1-3), its knife edges trimmed, then quad-meshed (quad_mesh.hpp) with uniform or adaptive sizes (§6.1).
#pragma once
#include <cstddef>
#include <functional>
#include <string>

#include "chordal/chordal_surface.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "quadmesh/sizing.hpp"
#include "tets/tet_mesh.hpp"

namespace hexlayer {

struct QuadStageOptions {
  double size = 0;          // target quad edge length
  bool adaptive = true;     // sizes from the radius function and curvature (§6.1), else uniform
  SizingOptions sizing;     // bounds of the adaptive sizes
  bool knifeEdges = false;  // the part has knife edges (WallSides::knifeEdges): trim the surface there
  std::function<void(const std::string&)> progress;  // a line per failed fairing level (may be empty)
};

struct QuadStage {
  ChordalSurface chordal;  // faired, with normals and radius: what the quads lie on
  QuadMesh quads;
  int fairingIterations = 0;    // Taubin steps the quads were made on
  std::size_t knifeFacets = 0;  // facets dropped where the wall runs out to a knife edge
};

// The fairing levels tried, strongest first.
constexpr int kFairingIterations[] = {10, 3, 0};

// [in] cut: the chordal surface as cut from the tets (its rim already placed, chordal_rim.hpp); [in] tets: the
// kept tets (for the radius function); [in] options. Throws the last level's error if no level can be meshed.
QuadStage meshFairedChordalSurface(const ChordalSurface& cut, const TetMesh& tets, const QuadStageOptions& options);

// The layout's name in the report: grid, o-grid, ring or gmsh.
const char* layoutName(QuadLayout layout);

}  // namespace hexlayer
