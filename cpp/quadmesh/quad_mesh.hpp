// Quad mesh of the chordal surface (paper §6): structured block grids laid out in a map of the
// surface onto the plane (block_grids.hpp), or through Gmsh's C++ API, where the chordal facets
// become a discrete surface that Gmsh reparametrizes, meshes quad-dominant and turns all-quad;
// the best of the tries is kept.
#pragma once
#include <array>
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "core/types.hpp"

namespace hexlayer {

// The Gmsh tries of a quad mesh: run, failed (Gmsh's error, a crash, a time-out or no quads), of those the ones
// that ran out of their time budget, the ones not started because the quad stage's budget was spent, and those not
// run because a try with the same patch angles had failed to make its patches (they would fail the same way), and
// those not run on a faired surface whose patches had failed at too many angles (patchFailuresToGiveUp).
struct QuadTries {
  std::size_t run = 0, failed = 0, timedOut = 0, skipped = 0, samePatches = 0, givenUp = 0;
  QuadTries& operator+=(const QuadTries& o);
};

// How the quads were laid out: by Gmsh on its patches (some of them structured, the rest
// unstructured), or as structured block grids in a map of the surface (block_grids.hpp: holedGrid, sharedGrid,
// oGrid, ringGrid), or one grid per patch between its creases (patch_grids.hpp).
enum class QuadLayout { Gmsh, Grid, SharedGrid, OGrid, Ring, PatchGrid, TriangleGrid };

struct QuadMesh {
  std::vector<Vec3> nodes;                // on the chordal surface
  std::vector<std::array<int, 4>> quads;  // orientation as Gmsh made it (the sweep orients them)
  std::size_t pairedTriangles = 0;        // Gmsh's leftover triangles turned into quads (quad_completion)
  std::size_t splitTriangles = 0;         // the others, split into quads with the strips from them
  std::size_t holes = 0;                  // leftover triangles neither could handle: each is a hole
  int doubletsRemoved = 0;                // before smoothing (quad_smoothing)
  std::size_t structuredPatches = 0;      // patches (or blocks) meshed with a structured grid
  QuadLayout layout = QuadLayout::Gmsh;
  QuadTries tries;      // the Gmsh tries that led to these quads
  std::string failure;  // no quads: why (the last Gmsh failure, or where it failed)
};

// How Gmsh cuts the chordal surface into patches it can parametrize, in degrees: chordal edges
// sharper than featureAngle bound the patches, and their boundary curves are split where they turn
// more than curveAngle (180: never). Splitting at the rim's corners keeps them sharp; not splitting
// the feature curves of a noisy bend keeps Gmsh from filling it with tiny quads.
// `structured`: the patches bounded by four curves get a structured grid (structurePatches).
// `recombination`: Gmsh's full-quad recombination, 3 Blossom (fewer irregular nodes) or 2 simple
// (more robust on badly parametrized patches).
// `ownPatches`: the patches are chordalPatches' (chordal_patches.hpp), cut at featureAngle, instead of Gmsh's
// classification (which pinches patches on sharply bent sheets); curveAngle is not used then.
struct PatchSplit {
  double featureAngle, curveAngle;
  bool structured = false;
  int recombination = 3;
  bool ownPatches = false;
};

// Where a wall standing on the sheet has a foot node: on quad node `quadNode`'s sweep column, at `at`.
struct FootEnd {
  int quadNode = -1;
  Vec3 at = Vec3::Zero();
  bool lap = false;  // a node of a wall lying along the sheet's wall (a boss merged into it: a lap)
};

struct QuadMeshOptions {
  double size = 0;                 // target edge length (uniform sizing)
  int ringAround = 0;              // the ring grid's quads round (ringGrid), 0: from the size
  std::vector<double> vertexSize;  // adaptive sizing: target edge length per chordal vertex (sizing.hpp)
  // Adaptive sizing of the own-patch tries (PatchSplit::ownPatches) and of the patch grid (patch_grids.hpp), if not
  // empty: without the curvature term, since the sharp creases they are for are their patches' curves (refining a
  // crease does not make the surface turn less across a quad there; in a patch grid it would refine every quad
  // along it, as far as the grid's rows run).
  std::vector<double> ownPatchSize;
  // The structured block grids are tried first (block_grids.hpp); Gmsh, one split after the other,
  // unless one of them is good with a mean quad of at least 0.98. Gmsh's reparametrization of a
  // patch can fail: the next split is tried then, or when the quads change the chordal surface's
  // topology (close a hole; a pinhole, a rim loop shorter than the smallest size, may close) or some
  // are inverted or below acceptableQuad once smoothed. Of the tries, the one that keeps the topology, then with the
  // fewest holes, then the fewest inverted (or folded), then the fewest creases not followed (creases), then the fewest
  // below acceptableQuad, then the best mean quad, then the best worst is kept. The last two splits cut HexLayer's own
  // patches (PatchSplit::ownPatches): they run only while no try has given quads (a fallback where Gmsh's
  // classification pinches every patch), and the quad stage gives them to the unfaired chordal surface only, whose
  // sharp bends they follow.
  std::vector<PatchSplit> patchSplits{{60, 60, true},
                                      {60, 180},
                                      {40, 40},
                                      {40, 180},
                                      {80, 80},
                                      {25, 25},
                                      {60, 60, true, 2},
                                      {60, 180, false, 2},
                                      {40, 40, false, 2},
                                      {40, 180, false, 2},
                                      {80, 80, false, 2},
                                      {25, 25, false, 2},
                                      {60, 60, false, 3, true},
                                      {40, 40, false, 3, true}};
  // Creases the quads' edges must follow (crease_chains.hpp: a lap's, issue 18), polylines near the chordal surface:
  // a try whose chain along one is dropped (its quads cross it where no chain of their edges runs along it: a block
  // grid's pocket corner beside a boss's flat) ranks after one that follows them all. Empty: none.
  std::vector<std::vector<Vec3>> creases;
  double acceptableQuad = 0.1;   // quad scaled Jacobian, smoothed
  int smoothingIterations = 10;  // of every try (quad_smoothing)
  // Time budget of one Gmsh try (killed when it runs out: a failed try); 0: gmshTryBudget of the chordal
  // surface's area over the size squared once a try (or block grid) gave quads, before that what is left of the
  // deadline (a try that is needed may take what the stage has left).
  double timeoutSeconds = 0;
  // No Gmsh try starts after this (quad_stage.hpp: the stage's budget), and a try gets at most the time left:
  // the tries not started are skipped, the best so far kept. (The default: none.)
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Called after each try (the block grids as one, then each Gmsh try) with the tries done and the most there
  // can be; may be empty.
  std::function<void(std::size_t done, std::size_t total)> tried;
  // If > 0: once this many patch splits with different angles have failed to make their patches and no try (nor
  // block grid) has given quads, the rest are not run (QuadTries::givenUp): on a faired chordal surface whose sharp
  // bends are rounded off, Gmsh's classification then fails at every angle (a sharply bent sheet: its patches touch
  // themselves), and the less faired surface is the one to try. 0: every split is tried.
  std::size_t patchFailuresToGiveUp = 0;
};

// The default time budget of one Gmsh try: 60 s plus a second per 200 quads the surface will get (Gmsh 4.8
// meshes tens of thousands of quads a second, a try of the real parts took 0.5-1.5 s, the U-channel's last one
// 170 s on a loaded machine; one that takes far longer has hung or is lost in a reparametrization). Generous, so
// that a loaded machine does not change which tries finish: the output stays the same. [in] quads: the estimated quad
// count. Returns seconds.
double gmshTryBudget(double quads);

// For every node, the nodes it shares a rim edge with (an edge of a single quad); empty inside.
std::vector<std::vector<int>> rimEdgeNeighbours(const QuadMesh& quads);

// The mean length of the quads' edges (0 without quads).
double meanEdge(const QuadMesh& quads);

// How many of the chordal surface's rim loops the quads close: their Euler characteristic less the surface's (a
// pinhole, a loop shorter than the smallest quad: a bend relief where sheets meet at a corner). [in] quads; [in]
// chordal: the surface they mesh.
long holesClosed(const QuadMesh& quads, const ChordalSurface& chordal);

// Meshes the chordal surface with quads only, doublets removed and smoothed. Holes and the outer
// rim are the boundary curves of the discrete surface, so they are kept. Of the tries (one per
// patch split) whose nodes all lie on the chordal surface, the best (QuadMeshOptions) is kept.
// [in] chordal: the surface; [in] options. Returns the best quads with their tries; no quads (and `failure`
// saying why) if no try gave any.
QuadMesh tryQuadMeshes(const ChordalLocator& chordal, const QuadMeshOptions& options);

// Opens Gmsh's session (gmsh::initialize, quiet, one thread: deterministic output): a fork server's preparation for
// its children (child_process.hpp), which run in it.
void openGmshSession();

// Runs work(), Gmsh 4.8's own errors (its error code thrown, the message in its logger) made geometryError.
// [in] work. Returns its bytes.
std::string namingGmshErrors(const std::function<std::string()>& work);

// Runs work() between gmsh::initialize and gmsh::finalize (quiet, one thread: deterministic output), finalizing
// whatever happens; Gmsh 4.8's own errors (its error code thrown, the message in its logger) become geometryError.
// Meant for a child process (child_process.hpp): Gmsh is one session per process. [in] work. Returns its bytes.
std::string inGmshSession(const std::function<std::string()>& work);

// A quad mesh as bytes and back, to cross from a child process that runs Gmsh (child_process.hpp). fromBytes throws
// internalError if the bytes are not a whole mesh.
std::string toBytes(const QuadMesh& q);
QuadMesh fromBytes(const std::string& bytes);

// One Gmsh try of `split` (in a child process, within the try's budget): its quads as Gmsh made them, triangles
// paired or split, not smoothed or ranked; none, with `failure` set, if it failed. [in] chordal, options, split.
QuadMesh gmshQuads(const ChordalLocator& chordal, const QuadMeshOptions& options, const PatchSplit& split);

// tryQuadMeshes, but throws geometryError (with the failure) if no try gave quads.
QuadMesh meshChordalSurface(const ChordalLocator& chordal, const QuadMeshOptions& options);

}  // namespace hexlayer
