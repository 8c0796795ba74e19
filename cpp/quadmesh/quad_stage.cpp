#include "quadmesh/quad_stage.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

#include "chordal/chordal_fairing.hpp"
#include "chordal/chordal_locator.hpp"
#include "core/error.hpp"

namespace hexlayer {
namespace {

// Where top and bottom walls meet at a knife edge, the chordal surface ends where the wall is thinner than
// this share of its median thickness.
constexpr double kKnifeRadius = 0.3;

double medianRadius(const ChordalSurface& chordal) {
  std::vector<double> r = chordal.radius;
  if (r.empty()) return 0;
  std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
  return r[r.size() / 2];
}

}  // namespace

const char* layoutName(QuadLayout layout) {
  switch (layout) {
    case QuadLayout::Grid:
      return "grid";
    case QuadLayout::OGrid:
      return "o-grid";
    case QuadLayout::Ring:
      return "ring";
    default:
      return "gmsh";
  }
}

QuadStage meshFairedChordalSurface(const ChordalSurface& cut, const TetMesh& tets, const QuadStageOptions& o) {
  QuadMeshOptions qo;
  qo.size = o.size;
  QuadStage stage;
  for (const int fairing : kFairingIterations) {
    stage.chordal = cut;
    fairChordalSurface(stage.chordal, fairing);
    computeNormalsAndRadius(stage.chordal, tets);
    stage.knifeFacets = o.knifeEdges ? trimKnifeEdges(stage.chordal, kKnifeRadius * medianRadius(stage.chordal)) : 0;
    const ChordalLocator locator(stage.chordal);
    if (o.adaptive) qo.vertexSize = adaptiveSizes(stage.chordal, o.sizing);
    try {
      stage.quads = meshChordalSurface(locator, qo);
    } catch (const Error& e) {
      if (fairing == kFairingIterations[std::size(kFairingIterations) - 1]) throw;
      if (o.progress) o.progress("quad_mesh: " + std::string(e.what()) + "; trying a less faired chordal surface");
      continue;
    }
    stage.fairingIterations = fairing;
    return stage;
  }
  return stage;  // not reached: the last level returns or throws
}

}  // namespace hexlayer
