#include "pipeline/mesh_report.hpp"

#include <cmath>

#include "quadmesh/quad_stage.hpp"

namespace hexlayer {

FaceCounts countFaces(const WallSides& sides) {
  FaceCounts c;
  for (const FaceSide& f : sides.faces) (f.side == Side::Top ? c.top : f.side == Side::Bottom ? c.bottom : c.lateral)++;
  return c;
}

ChordalRecord countChordal(const ChordalSurface& cut) {
  ChordalRecord c;
  c.triangles = cut.triangles, c.quads = cut.quads, c.vertices = cut.vertices.size();
  c.pinchedFacetsDropped = cut.pinchedFacetsDropped;
  c.islandFacetsDropped = cut.islandFacetsDropped;
  return c;
}

QuadMeshCounts countQuadMesh(const QuadMesh& q) {
  QuadMeshCounts c;
  c.quads = q.quads.size(), c.nodes = q.nodes.size();
  c.pairedTriangles = q.pairedTriangles, c.splitTriangles = q.splitTriangles, c.holes = q.holes;
  c.doubletsRemoved = q.doubletsRemoved, c.structuredPatches = q.structuredPatches;
  c.layout = layoutName(q.layout);
  c.tries = q.tries;
  return c;
}

void toInputUnits(MeshReport& r, double unit) {
  r.thickness /= unit;
  r.size /= unit;
  r.smallFeatures.firstAt /= unit;
  r.chordal.rim.largestMove /= unit;
  for (JunctionRecord& j : r.junctions) j.at /= unit, j.area /= std::pow(unit, 2), j.volume /= std::pow(unit, 3);
  BoundaryDeviation& d = r.boundaryDeviation;
  d.max /= unit, d.mean /= unit;
  if (d.worstAt) *d.worstAt /= unit;
  if (r.quadratic) r.quadratic->maxProjectionMove /= unit;
}

MeshReport mergeSolids(std::vector<MeshReport> solids, MeshMeasures whole) {
  whole.cadVolume = 0, whole.cadEuler = 0, whole.failures.clear();
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const MeshMeasures& one = solids[i].mesh;
    whole.cadVolume += one.cadVolume;
    whole.cadEuler += one.cadEuler;
    for (ValidationFailure f : one.failures) {
      f.message = "solid " + std::to_string(i + 1) + ": " + f.message;
      whole.failures.push_back(std::move(f));
    }
  }
  MeshReport merged;
  merged.mesh = std::move(whole);
  merged.solids = std::move(solids);
  return merged;
}

}  // namespace hexlayer
