// §6 as the pipeline runs it: the chordal surface faired as much as Gmsh can reparametrize (strongest first,
// then less: Gmsh's reparametrization fails on one surface and not on another), its normals and radius
// (Eq. 1-3), its knife edges trimmed, then quad-meshed (quad_mesh.hpp) with uniform or adaptive sizes (§6.1).
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "chordal/chordal_surface.hpp"
#include "core/progress.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "quadmesh/sizing.hpp"
#include "tets/tet_mesh.hpp"

namespace hexlayer {

struct QuadStageOptions {
  double size = 0;          // target quad edge length
  bool adaptive = true;     // sizes from the radius function and curvature (§6.1), else uniform
  SizingOptions sizing;     // bounds of the adaptive sizes
  bool knifeEdges = false;  // the part has knife edges (WallSides::knifeEdges): trim the surface there
  // Progress of stage "quad_mesh": its tries done of the most there can be, and a note per failed fairing level
  // (may be empty).
  ProgressCallback progress;
  // Time budgets in seconds (0: from the chordal surface's area and the size): of one Gmsh try (gmshTryBudget
  // once there are quads to fall back on, until then what the stage has left; QuadMeshOptions::timeoutSeconds),
  // and of the whole stage (quadStageBudget), after which no Gmsh try starts and the best quads so far are kept.
  // A part whose tries all finish within their budgets gets the same quads on any machine; one that runs out gets
  // the quads of the tries that finished (a slower machine may finish fewer).
  double tryBudget = 0, stageBudget = 0;
  int ringAround = 0;                      // a ring grid's quads round (QuadMeshOptions::ringAround); 0: from the size
  std::vector<std::vector<Vec3>> creases;  // creases the quads should follow (QuadMeshOptions::creases)
};

struct QuadStage {
  ChordalSurface chordal;  // faired, with normals and radius: what the quads lie on
  QuadMesh quads;
  int fairingIterations = 0;    // Taubin steps the quads were made on
  std::size_t knifeFacets = 0;  // facets dropped where the wall runs out to a knife edge
  // Facet edges shorter than kSliverEdge x the median edge of the surface as cut: where there are any, the faired
  // levels are not tried (fairing folds the facets round them).
  std::size_t sliverEdges = 0;
  QuadTries tries;  // the Gmsh tries of every fairing level tried (also in quads.tries)
  // The walls' foot nodes on the sheet's quads (carried in by the pipeline's edit; empty: none): per foot node, the
  // quad node under it and where it is, in the stage's units. The end of that quad node's sweep column nearer to it
  // is put there (placeFootEnds), and the hex smoothing leaves it there.
  std::vector<FootEnd> feet;
  double budgetSeconds = 0;  // the stage's time budget used
};

// The fairing levels tried, strongest first.
constexpr int kFairingIterations[] = {10, 3, 0};

// A facet edge shorter than this share of the median edge is a sliver's: bubbles in pairs on a CAD face a few microns
// wide (the real U-channel's zero-radius bends) cut tet edges whose midpoints nearly coincide. The normals of such
// vertices are noise, and fairing moves them apart along those, folding the facets between them: every Gmsh try on
// the faired levels of the U-channel (573 such edges) and of the power-holder box (3) failed to make its patches
// ("Wrong topology of boundary mesh for parametrization"), 2 s each. No other part of 66 has one.
constexpr double kSliverEdge = 0.01;

// [in] s: a chordal surface. Returns its facet edges shorter than kSliverEdge x its median edge.
std::size_t sliverEdges(const ChordalSurface& s);

// The default time budget of the quad stage: 300 s plus a second per 100 quads the surface will get: a net for
// a part whose Gmsh tries would run on for many minutes, generous enough that a loaded machine does not change
// the mesh of a part that meshes (the real U-channel's tries take up to 400 s on a loaded machine).
// [in] quads: the estimated quad count. Returns seconds.
double quadStageBudget(double quads);

// [in] cut: the chordal surface as cut from the tets (its rim already placed, chordal_rim.hpp); [in] tets: the
// kept tets (for the radius function); [in] options. Throws geometryError with the last level's failure if no
// level can be meshed (within the budget).
QuadStage meshFairedChordalSurface(const ChordalSurface& cut, const TetMesh& tets, const QuadStageOptions& options);

// The layout's name in the report: grid, shared-grid, o-grid, ring, patch-grid or gmsh.
const char* layoutName(QuadLayout layout);

}  // namespace hexlayer
