#include "quadmesh/quad_mesh.hpp"

#include <gmsh.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "core/error.hpp"

namespace hexlayer {
namespace {

// Gmsh is one process-wide session: open it for this stage only, and always close it.
struct GmshSession {
  GmshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);  // deterministic output
  }
  ~GmshSession() { gmsh::finalize(); }
};

// The chordal facets as one discrete Gmsh surface of triangles (each quad split on a diagonal).
void addChordalTriangles(const ChordalSurface& chordal) {
  const int surface = gmsh::model::addDiscreteEntity(2);
  std::vector<std::size_t> tags(chordal.vertices.size());
  std::vector<double> coords;
  coords.reserve(3 * chordal.vertices.size());
  for (size_t i = 0; i < chordal.vertices.size(); ++i) {
    tags[i] = i + 1;
    coords.insert(coords.end(), chordal.vertices[i].data(), chordal.vertices[i].data() + 3);
  }
  gmsh::model::mesh::addNodes(2, surface, tags, coords);
  std::vector<std::size_t> triangles;
  auto add = [&](int a, int b, int c) { triangles.insert(triangles.end(), {std::size_t(a) + 1, std::size_t(b) + 1, std::size_t(c) + 1}); };
  for (const auto& f : chordal.facets) {
    add(f[0], f[1], f[2]);
    if (f[3] >= 0) add(f[0], f[2], f[3]);
  }
  gmsh::model::mesh::addElementsByType(surface, 2, {}, triangles);
}

void setQuadOptions(const QuadMeshOptions& o) {
  // The templates halve every edge (§6.2: "the initial quad dominant mesh is made coarser").
  gmsh::option::setNumber("Mesh.MeshSizeMin", 2 * o.size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 2 * o.size);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  // Frontal-Delaunay. (Frontal-Delaunay for quads, algorithm 8, crashes in Debian's Gmsh 4.8.4.)
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);  // blossom: quad-dominant
  gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);    // all quads by templates (§6.2)
  gmsh::option::setNumber("Mesh.Smoothing", 5);
  gmsh::option::setNumber("Mesh.RandomFactor", 1e-9);
}

QuadMesh collectQuads() {
  std::vector<std::size_t> tags, nodeTags;
  gmsh::model::mesh::getElementsByType(3, tags, nodeTags);
  QuadMesh q;
  std::map<std::size_t, int> index;  // Gmsh node tag -> our node id, in order of first use
  std::vector<std::size_t> order;
  for (std::size_t t : nodeTags)
    if (index.emplace(t, static_cast<int>(order.size())).second) order.push_back(t);
  std::vector<std::size_t> allTags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(allTags, coord, param, -1, -1, true, false);
  q.nodes.resize(order.size());
  for (size_t i = 0; i < allTags.size(); ++i)
    if (const auto it = index.find(allTags[i]); it != index.end())
      q.nodes[it->second] = Vec3(coord[3 * i], coord[3 * i + 1], coord[3 * i + 2]);
  q.quads.resize(tags.size());
  for (size_t e = 0; e < tags.size(); ++e)
    for (int k = 0; k < 4; ++k) q.quads[e][k] = index.at(nodeTags[4 * e + k]);
  return q;
}

}  // namespace

QuadMesh meshChordalSurface(const ChordalSurface& chordal, const QuadMeshOptions& o) {
  if (!(o.size > 0)) throw usageError("quad size must be positive");
  GmshSession session;
  gmsh::model::add("chordal_surface");
  addChordalTriangles(chordal);
  QuadMesh q;
  try {
    const double angle = o.featureAngle * M_PI / 180.0;
    gmsh::model::mesh::classifySurfaces(angle, true, true, angle);  // split into patches Gmsh can parametrize
    gmsh::model::mesh::createGeometry();
    setQuadOptions(o);
    gmsh::model::mesh::generate(2);
    q = collectQuads();
  } catch (const std::exception& e) {
    throw geometryError(std::string("Gmsh could not quad-mesh the chordal surface: ") + e.what());
  } catch (...) {
    throw geometryError("Gmsh could not quad-mesh the chordal surface");
  }
  if (q.quads.empty()) throw geometryError("Gmsh produced no quads on the chordal surface");
  return q;
}

}  // namespace hexlayer
