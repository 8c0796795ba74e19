#include "quadmesh/quad_stage.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iterator>
#include <limits>
#include <sstream>
#include <vector>

#include "chordal/chordal_fairing.hpp"
#include "chordal/chordal_locator.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"

namespace hexlayer {
namespace {

// Where top and bottom walls meet at a knife edge, the chordal surface ends where the wall is thinner than
// this share of its median thickness.
constexpr double kKnifeRadius = 0.3;
// On a faired level, the Gmsh tries stop once this many angles have failed to make their patches without quads: on a
// sharply bent sheet every angle fails there (the U-channel's 12 tries on its two faired levels, 13 s).
constexpr std::size_t kPatchFailuresToGiveUp = 2;

// The quad mesh options every fairing level starts from: the size and the budgets (a try's, and the stage's
// deadline, stageBudget seconds from now).
QuadMeshOptions triesWithin(const QuadStageOptions& o, double stageBudget) {
  QuadMeshOptions qo;
  qo.size = o.size, qo.ringAround = o.ringAround, qo.creases = o.creases;
  qo.timeoutSeconds = o.tryBudget;
  qo.deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                       std::chrono::duration<double>(stageBudget));
  return qo;
}

// One fairing level: the chordal surface faired, its normals and radius, knife edges trimmed, its quads tried.
// Its tries are the stage's progress, level k's after the k levels before it.
// [in] cut, tets, o; [in] base: the levels' options; [in] fairing: Taubin steps; [in] level: its place in
// kFairingIterations; [out] stage: the faired surface and its knife facets. Returns the quads (none: q.failure).
QuadMesh meshFairedLevel(const ChordalSurface& cut, const TetMesh& tets, const QuadStageOptions& o,
                         const QuadMeshOptions& base, int fairing, std::size_t level, QuadStage& stage) {
  stage.chordal = cut;
  fairChordalSurface(stage.chordal, fairing);
  computeNormalsAndRadius(stage.chordal, tets);
  stage.knifeFacets = o.knifeEdges ? trimKnifeEdges(stage.chordal, kKnifeRadius * median(stage.chordal.radius)) : 0;
  const ChordalLocator locator(stage.chordal);
  QuadMeshOptions qo = base;
  if (fairing > 0) {
    qo.patchFailuresToGiveUp = kPatchFailuresToGiveUp;
    // HexLayer's own patches follow the creases of sharp bends, which fairing rounds off
    qo.patchSplits.erase(std::remove_if(qo.patchSplits.begin(), qo.patchSplits.end(),
                                        [](const PatchSplit& split) { return split.ownPatches; }),
                         qo.patchSplits.end());
  }
  if (o.adaptive) {  // §6.1's sizes, and its radius term only for the own patches and the patch grid (their creases
                     // are their curves), side by side
    SizingOptions withoutCurvature = o.sizing;
    withoutCurvature.turnPerQuad = std::numeric_limits<double>::infinity();
    sideBySide({[&] { qo.vertexSize = adaptiveSizes(stage.chordal, o.sizing); },
                [&] { qo.ownPatchSize = adaptiveSizes(stage.chordal, withoutCurvature); }});
  }
  const double levels = static_cast<double>(std::size(kFairingIterations));
  if (o.progress)
    qo.tried = [&](std::size_t done, std::size_t total) {
      o.progress(progressAdvance("quad_mesh", static_cast<double>(level * total + done), levels * total));
    };
  return tryQuadMeshes(locator, qo);
}

// The tries of a failed stage, for its message: " (N Gmsh tries, F failed, T out of their time budget, S not
// started: ...)". [in] stage. Returns the text.
std::string triesSummary(const QuadStage& stage) {
  const QuadTries& t = stage.tries;
  std::ostringstream s;
  s << " (" << t.run << " Gmsh tries, " << t.failed << " failed, " << t.timedOut << " out of their time budget";
  if (t.samePatches > 0) s << ", " << t.samePatches << " not run: their patches had failed in an earlier try";
  if (t.givenUp > 0) s << ", " << t.givenUp << " not run on faired surfaces whose patches failed at every angle tried";
  if (t.skipped > 0)
    s << ", " << t.skipped << " not started: the stage's budget of " << std::setprecision(3) << stage.budgetSeconds
      << " s was spent";
  s << ")";
  return s.str();
}

}  // namespace

const char* layoutName(QuadLayout layout) {
  switch (layout) {
    case QuadLayout::Grid:
      return "grid";
    case QuadLayout::SharedGrid:
      return "shared-grid";
    case QuadLayout::OGrid:
      return "o-grid";
    case QuadLayout::Ring:
      return "ring";
    case QuadLayout::PatchGrid:
      return "patch-grid";
    case QuadLayout::TriangleGrid:
      return "triangle-grid";
    default:
      return "gmsh";
  }
}

double quadStageBudget(double quads) { return 300 + quads / 100; }

std::size_t sliverEdges(const ChordalSurface& s) {
  std::vector<double> lengths;
  for (const auto& [edge, count] : facetEdgeUses(s))
    lengths.push_back((s.vertices[edge.first] - s.vertices[edge.second]).norm());
  const double shortest = kSliverEdge * median(lengths);
  return static_cast<std::size_t>(
      std::count_if(lengths.begin(), lengths.end(), [&](double length) { return length < shortest; }));
}

QuadStage meshFairedChordalSurface(const ChordalSurface& cut, const TetMesh& tets, const QuadStageOptions& o) {
  const double quads = chordalArea(cut) / (o.size * o.size);
  QuadStage stage;
  stage.budgetSeconds = o.stageBudget > 0 ? o.stageBudget : quadStageBudget(quads);
  const QuadMeshOptions qo = triesWithin(o, stage.budgetSeconds);
  stage.sliverEdges = sliverEdges(cut);
  std::string failure;
  for (std::size_t level = 0; level < std::size(kFairingIterations); ++level) {
    const int fairing = kFairingIterations[level];
    if (fairing > 0 && stage.sliverEdges > 0) continue;  // not faired round slivers
    QuadMesh q = meshFairedLevel(cut, tets, o, qo, fairing, level, stage);
    stage.tries += q.tries;
    if (!q.quads.empty()) {
      stage.quads = std::move(q);
      stage.quads.tries = stage.tries;
      stage.fairingIterations = fairing;
      return stage;
    }
    if (q.tries.run > 0 || failure.empty()) failure = q.failure;  // a level without a try keeps the last's reason
    if (q.tries.skipped > 0) break;  // out of time: a less faired surface would get no try either
    if (level + 1 < std::size(kFairingIterations))
      reportProgress(o.progress, progressNote("quad_mesh", failure + "; trying a less faired chordal surface"));
  }
  throw geometryError("could not quad-mesh the chordal surface: " + failure + triesSummary(stage));
}

}  // namespace hexlayer
