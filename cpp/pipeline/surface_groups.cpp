#include "pipeline/surface_groups.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "writers/writers.hpp"

namespace hexlayer {
namespace {

std::string faceName(int face) { return "Face" + std::to_string(face + 1); }

Side sideOf(const HexMesh& mesh, int i) {
  if (mesh.nodeOnRim[i]) return Side::Lateral;
  return mesh.nodeLayer[i] == 0 ? Side::Bottom : Side::Top;
}

// Local wall thickness at every hex: its four sweep edges' mean length times the layers.
std::vector<double> hexThickness(const HexMesh& mesh) {
  std::vector<double> t(mesh.hexes.size());
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    double sum = 0;
    for (int c = 0; c < 4; ++c) sum += (mesh.nodes[mesh.hexes[h][c + 4]] - mesh.nodes[mesh.hexes[h][c]]).norm();
    t[h] = 0.25 * sum * mesh.layers;
  }
  return t;
}

// The CAD face of a boundary hex face: the one its corners all lie on, else the nearest to its centre
// of those several (or, if none is shared, all) of its corners lie on. Counts the faces that share none.
int faceOfQuad(const HexMesh& mesh, CadFaceProbe& probe, const BoundaryFace& quad,
               const std::vector<std::vector<int>>& facesOf, std::size_t& across) {
  std::vector<int> shared = facesOf[quad.nodes[0]], all = shared;
  std::sort(shared.begin(), shared.end());
  for (int c = 1; c < 4; ++c) {
    std::vector<int> next = facesOf[quad.nodes[c]], both;
    std::sort(next.begin(), next.end());
    std::set_intersection(shared.begin(), shared.end(), next.begin(), next.end(), std::back_inserter(both));
    shared.swap(both);
    all.insert(all.end(), next.begin(), next.end());
  }
  if (shared.size() == 1) return shared[0];
  if (shared.empty()) ++across;
  const std::vector<int>& candidates = shared.empty() ? all : shared;
  Vec3 centre = Vec3::Zero();
  for (int n : quad.nodes) centre += 0.25 * mesh.nodes[n];
  int best = candidates[0];
  double nearest = std::numeric_limits<double>::infinity();
  for (int f : candidates)
    if (const double d = probe.distance(f, centre); d < nearest) nearest = d, best = f;
  return best;
}

struct NodeKinds {
  std::vector<char> midEdge;      // a mid-edge node of a 20-node hex
  std::vector<double> thickness;  // local wall thickness at a boundary node
};

NodeKinds nodeKinds(const HexMesh& mesh, const std::vector<BoundaryFace>& quads) {
  NodeKinds k{std::vector<char>(mesh.nodes.size(), 0), std::vector<double>(mesh.nodes.size(), 0)};
  for (const auto& mids : mesh.midEdges)
    for (int n : mids) k.midEdge[n] = 1;
  const std::vector<double> t = hexThickness(mesh);
  for (const BoundaryFace& q : quads)
    for (int n : boundaryFaceNodes(mesh, q))
      if (k.thickness[n] == 0) k.thickness[n] = t[q.hex];
  return k;
}

// The off-face count of a boundary node's kind: on the rim or a wall, corner or mid-edge node.
int& offFaceCount(OffFaceCounts& c, bool rim, bool midEdge) {
  if (rim) return midEdge ? c.rimMidEdge : c.rimCorners;
  return midEdge ? c.wallMidEdge : c.wallCorners;
}

// Max and mean distance of the boundary nodes to their faces, and per kind of node how many are not on
// their face to its tolerance (FreeCAD's getNodesByFace would not find them).
BoundaryDeviation measureDeviation(const HexMesh& mesh, const CadFaces& faces, const std::vector<int>& boundary,
                                   const std::vector<double>& distance, const NodeKinds& kinds) {
  BoundaryDeviation r;
  double sum = 0, sumRelative = 0;
  int worst = boundary.empty() ? -1 : boundary[0];
  for (int i : boundary) {
    const double d = distance[i], relative = kinds.thickness[i] > 0 ? d / kinds.thickness[i] : 0;
    sum += d, sumRelative += relative;
    if (d > r.max) r.max = d, worst = i;
    r.maxRelative = std::max(r.maxRelative, relative);
    if (d >= faces.tolerance(mesh.nodeFace[i])) ++offFaceCount(r.offFaceTolerance, mesh.nodeOnRim[i], kinds.midEdge[i]);
  }
  const double n = boundary.empty() ? 1 : static_cast<double>(boundary.size());
  r.nodes = boundary.size();
  r.mean = sum / n, r.meanRelative = sumRelative / n;
  if (worst >= 0) {
    r.worstAt = mesh.nodes[worst];
    r.worstFace = faces.face(mesh.nodeFace[worst]).name;
  }
  return r;
}

}  // namespace

std::vector<int> boundaryNodes(const HexMesh& mesh, const std::vector<BoundaryFace>& quads) {
  std::vector<char> on(mesh.nodes.size(), 0);
  for (const BoundaryFace& q : quads)
    for (int n : boundaryFaceNodes(mesh, q)) on[n] = 1;
  std::vector<int> nodes;
  for (std::size_t i = 0; i < on.size(); ++i)
    if (on[i]) nodes.push_back(static_cast<int>(i));
  return nodes;
}

std::size_t faceUnplacedNodes(HexMesh& mesh, const WallProjector& walls, const std::vector<int>& boundary) {
  std::size_t given = 0;
  for (int i : boundary) {
    if (mesh.nodeFace[i] >= 0) continue;
    const std::optional<FacePoint> p = walls.project(sideOf(mesh, i), mesh.nodes[i]);
    if (!p) throw Error(ExitCode::Internal, "no CAD face for the boundary node " + std::to_string(i + 1));
    mesh.nodeFace[i] = p->face;
    ++given;
  }
  return given;
}

SurfaceGroups surfaceGroups(const HexMesh& mesh, const CadFaces& faces, const std::vector<BoundaryFace>& quads,
                            const std::vector<int>& boundary) {
  SurfaceGroups out;
  for (int f = 0; f < faces.count(); ++f) out.groups.push_back({faces.face(f).name, {}, {}});
  std::vector<std::vector<int>> facesOf(mesh.nodes.size());
  std::vector<double> distance(mesh.nodes.size(), 0);
  for (int i : boundary)
    if (mesh.nodeFace[i] < 0)
      throw Error(ExitCode::Internal, "boundary node " + std::to_string(i + 1) + " has no CAD face");
  // The distance queries in parallel, each thread with its own probe (OpenCASCADE's extrema tools on the
  // shared, read-only faces); the groups are filled afterwards in the nodes' order, the same for any thread count.
  const long nBoundary = static_cast<long>(boundary.size());
  ParallelErrors errors;
#pragma omp parallel
  {
    CadFaceProbe probe(faces);
#pragma omp for schedule(static)
    for (long k = 0; k < nBoundary; ++k)
      errors.run([&] {
        const int i = boundary[k];
        FacesAtPoint at = probe.facesAt(mesh.nodeFace[i], mesh.nodes[i]);
        facesOf[i] = std::move(at.faces);
        distance[i] = at.distance;
      });
  }
  errors.rethrow();
  std::size_t several = 0;
  for (int i : boundary) {  // ascending: the groups' nodes come out sorted
    for (int f : facesOf[i]) out.groups[f].nodes.push_back(i);
    several += facesOf[i].size() > 1;
  }
  const long nQuads = static_cast<long>(quads.size());
  std::vector<int> faceOf(quads.size());
  std::vector<char> isAcross(quads.size(), 0);
#pragma omp parallel
  {
    CadFaceProbe probe(faces);
#pragma omp for schedule(static)
    for (long k = 0; k < nQuads; ++k)
      errors.run([&] {
        std::size_t a = 0;
        faceOf[k] = faceOfQuad(mesh, probe, quads[k], facesOf, a);
        isAcross[k] = a > 0;
      });
  }
  errors.rethrow();
  std::size_t across = 0;
  for (std::size_t k = 0; k < quads.size(); ++k) {
    out.groups[faceOf[k]].hexFaces.push_back({quads[k].hex, quads[k].localFace});
    across += isAcross[k];
  }
  SurfaceGroupStats& stats = out.stats;
  for (const SurfaceGroup& g : out.groups) stats.meshedCadFaces += !g.hexFaces.empty();
  stats.cadFaces = faces.count(), stats.boundaryNodes = boundary.size(), stats.nodesOnSeveralFaces = several;
  stats.elementFaces = quads.size(), stats.elementFacesAcrossCadEdges = across;
  out.deviation = measureDeviation(mesh, faces, boundary, distance, nodeKinds(mesh, quads));
  return out;
}

void appendSurfaceGroups(std::vector<SurfaceGroup>& all, const std::vector<SurfaceGroup>& part, int nodeOffset,
                         int hexOffset) {
  for (SurfaceGroup g : part) {
    g.name = faceName(static_cast<int>(all.size()));
    for (int& n : g.nodes) n += nodeOffset;
    for (HexFace& f : g.hexFaces) f.hex += hexOffset;
    all.push_back(std::move(g));
  }
}

}  // namespace hexlayer
