#include "quadmesh/quad_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "core/child_process.hpp"
#include "core/error.hpp"
#include "core/union_find.hpp"
#include "quadmesh/quad_completion.hpp"
#include "quadmesh/quad_smoothing.hpp"

namespace hexlayer {
namespace {

// Gmsh's nodes stray from the chordal triangles by up to half a quad in strongly bent patches (its
// smoothing and recombination move them in 3D); farther than this x size means a failed reparametrization.
constexpr double kOffSurface = 1.0;
constexpr int kMaxStrip = 20;  // quads between two leftover triangles that are paired (quad_completion)

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

double smallestSize(const QuadMeshOptions& o) {
  return o.vertexSize.empty() ? o.size : *std::min_element(o.vertexSize.begin(), o.vertexSize.end());
}

// The target size at a point of the chordal surface, interpolated from its facet's corners.
double sizeAt(const ChordalLocator& chordal, const std::vector<double>& vertexSize, const Vec3& p) {
  const ChordalPoint at = chordal.locate(p);
  const auto& f = chordal.surface().facets[at.facet];
  double h = 0;
  for (int k = 0; k < (f[3] < 0 ? 3 : 4); ++k) h += at.weights[k] * vertexSize[f[k]];
  return h;
}

void setQuadOptions(const QuadMeshOptions& o, const ChordalLocator& chordal) {
  const bool adaptive = !o.vertexSize.empty();
  gmsh::option::setNumber("Mesh.MeshSizeMin", smallestSize(o));
  gmsh::option::setNumber("Mesh.MeshSizeMax", adaptive ? *std::max_element(o.vertexSize.begin(), o.vertexSize.end()) : o.size);
  if (adaptive)  // §6.1: geometry-adaptive quads
    gmsh::model::mesh::setSizeCallback([&](int, int, double x, double y, double z) { return sizeAt(chordal, o.vertexSize, Vec3(x, y, z)); });
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  // Frontal-Delaunay triangles (Frontal-Delaunay for quads, algorithm 8, crashes in Debian's Gmsh 4.8.4),
  // then Blossom full-quad recombination: all quads without the §6.2 templates, which in Gmsh 4.8 leave
  // far more distorted quads on a reparametrized discrete surface.
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 2);
  gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
  gmsh::option::setNumber("Mesh.Smoothing", 5);
  gmsh::option::setNumber("Mesh.RandomFactor", 1e-9);
}

// Gmsh's elements of one type (3: triangles, 4: quads), as node tags.
template <int N>
std::vector<std::array<std::size_t, N>> elementsOfType(int type) {
  std::vector<std::size_t> tags, nodeTags;
  gmsh::model::mesh::getElementsByType(type, tags, nodeTags);
  std::vector<std::array<std::size_t, N>> out(tags.size());
  for (std::size_t e = 0; e < tags.size(); ++e)
    for (int k = 0; k < N; ++k) out[e][k] = nodeTags[N * e + k];
  return out;
}

// Gmsh's quads, and its leftover triangles paired into quads, the rest split (quad_completion).
QuadMesh collectQuads() {
  const auto quadTags = elementsOfType<4>(3);
  const auto triangleTags = elementsOfType<3>(2);
  std::vector<std::size_t> nodeTags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(nodeTags, coord, param, -1, -1, true, false);
  std::map<std::size_t, Vec3> position;
  for (size_t i = 0; i < nodeTags.size(); ++i) position[nodeTags[i]] = Vec3(coord[3 * i], coord[3 * i + 1], coord[3 * i + 2]);
  QuadMesh q;
  std::map<std::size_t, int> index;  // Gmsh node tag -> our node id, in order of first use
  auto node = [&](std::size_t tag) {
    const auto [it, added] = index.emplace(tag, static_cast<int>(q.nodes.size()));
    if (added) {
      const auto p = position.find(tag);
      if (p == position.end()) throw std::runtime_error("Gmsh gave no coordinates for node " + std::to_string(tag));
      q.nodes.push_back(p->second);
    }
    return it->second;
  };
  for (const auto& e : quadTags) q.quads.push_back({node(e[0]), node(e[1]), node(e[2]), node(e[3])});
  std::vector<std::array<int, 3>> triangles;
  for (const auto& e : triangleTags) triangles.push_back({node(e[0]), node(e[1]), node(e[2])});
  const QuadCompletion done = pairTriangles(q.quads, triangles, kMaxStrip);
  q.pairedTriangles = done.paired;
  q.splitTriangles = splitTriangles(q.nodes, q.quads, triangles);
  q.holes = triangles.size();
  return q;
}

// A quad mesh as bytes and back, to cross from the child process that runs Gmsh.
std::string toBytes(const QuadMesh& q) {
  const std::size_t counts[5] = {q.nodes.size(), q.quads.size(), q.pairedTriangles, q.splitTriangles, q.holes};
  std::string bytes(reinterpret_cast<const char*>(counts), sizeof counts);
  for (const Vec3& p : q.nodes) bytes.append(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
  bytes.append(reinterpret_cast<const char*>(q.quads.data()), q.quads.size() * sizeof(q.quads[0]));
  return bytes;
}

QuadMesh fromBytes(const std::string& bytes) {
  std::size_t counts[5];
  if (bytes.size() < sizeof counts) throw std::runtime_error("truncated quad mesh");
  std::memcpy(counts, bytes.data(), sizeof counts);
  QuadMesh q;
  q.nodes.resize(counts[0]);
  q.quads.resize(counts[1]);
  q.pairedTriangles = counts[2];
  q.splitTriangles = counts[3];
  q.holes = counts[4];
  const std::size_t nodeBytes = counts[0] * 3 * sizeof(double), quadBytes = counts[1] * sizeof(q.quads[0]);
  if (bytes.size() != sizeof counts + nodeBytes + quadBytes) throw std::runtime_error("truncated quad mesh");
  const char* at = bytes.data() + sizeof counts;
  for (Vec3& p : q.nodes) std::memcpy(p.data(), at, 3 * sizeof(double)), at += 3 * sizeof(double);
  std::memcpy(static_cast<void*>(q.quads.data()), at, quadBytes);
  return q;
}


double gmshTimeout(const ChordalSurface& chordal, double size) {
  return 60 + chordalArea(chordal) / (size * size) / 2000;
}

// One Gmsh run: split the chordal surface into patches, reparametrize, mesh.
// Gmsh runs in a child process: its crashes and hangs (both seen on real parts with Gmsh 4.8) end
// that try only. Returns no quads, and why in `error`, if Gmsh fails.
QuadMesh gmshQuads(const ChordalLocator& locator, const QuadMeshOptions& o, const PatchSplit& split, std::string& error) {
  const ChordalSurface& chordal = locator.surface();
  const ChildResult run = runInChildProcess([&] {
    GmshSession session;
    try {
      gmsh::model::add("chordal_surface");
      addChordalTriangles(chordal);
      const double toRadians = M_PI / 180.0;
      gmsh::model::mesh::classifySurfaces(split.featureAngle * toRadians, true, true, split.curveAngle * toRadians);
      gmsh::model::mesh::createGeometry();
      setQuadOptions(o, locator);
      gmsh::model::mesh::generate(2);
      return toBytes(collectQuads());
    } catch (const std::exception&) {
      throw;
    } catch (...) {  // Gmsh 4.8 throws its error code; the message is in its logger
      std::string last;
      gmsh::logger::getLastError(last);
      throw std::runtime_error(last.empty() ? "unknown Gmsh error" : last);
    }
  }, o.timeoutSeconds > 0 ? o.timeoutSeconds : gmshTimeout(chordal, smallestSize(o)));
  if (!run.ok) {
    error = "Gmsh " + run.failure;
    return {};
  }
  return fromBytes(run.output);
}

// How far the quad mesh is from the chordal surface it should lie on (a failed reparametrization
// puts nodes far away), and its worst quad.
struct QuadCheck {
  double worstQuad = -1;
  std::size_t poorQuads = std::numeric_limits<std::size_t>::max();  // below acceptableQuad
  double farthest = 0;
  Vec3 farthestNode = Vec3::Zero();
  std::vector<Vec3> onSurface;  // every node moved to its nearest point of the chordal surface
};

QuadCheck checkQuads(const QuadMesh& q, const ChordalLocator& chordal, double acceptableQuad) {
  QuadCheck c;
  if (q.quads.empty()) return c;
  c.worstQuad = 1;
  c.poorQuads = 0;
  for (const auto& quad : q.quads) {
    const double sj = quadScaledJacobian({q.nodes[quad[0]], q.nodes[quad[1]], q.nodes[quad[2]], q.nodes[quad[3]]});
    c.worstQuad = std::min(c.worstQuad, sj);
    c.poorQuads += sj < acceptableQuad;
  }
  for (const Vec3& p : q.nodes) {
    c.onSurface.push_back(p.allFinite() ? chordal.locate(p).point : p);
    const double d = p.allFinite() ? (c.onSurface.back() - p).norm() : std::numeric_limits<double>::infinity();
    if (d > c.farthest) c.farthest = d, c.farthestNode = p;
  }
  return c;
}

}  // namespace

std::vector<std::vector<int>> rimEdgeNeighbours(const QuadMesh& q) {
  std::unordered_map<std::uint64_t, int> use;
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k) ++use[edgeKey(quad[k], quad[(k + 1) % 4])];
  std::vector<std::vector<int>> around(q.nodes.size());
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k)
      if (int a = quad[k], b = quad[(k + 1) % 4]; use[edgeKey(a, b)] == 1) around[a].push_back(b), around[b].push_back(a);
  return around;
}

QuadMesh meshChordalSurface(const ChordalLocator& chordal, const QuadMeshOptions& o) {
  if (!(o.size > 0)) throw usageError("quad size must be positive");
  QuadMesh best;
  best.holes = std::numeric_limits<std::size_t>::max();
  QuadCheck bestCheck;
  Vec3 failedAt = Vec3::Zero();
  std::string gmshError;
  for (const PatchSplit& split : o.patchSplits) {
    QuadMesh q = gmshQuads(chordal, o, split, gmshError);
    const QuadCheck c = checkQuads(q, chordal, o.acceptableQuad);
    if (q.quads.empty() || !(c.farthest < kOffSurface * o.size)) {
      if (!q.quads.empty()) failedAt = c.farthestNode, gmshError.clear();
      continue;
    }
    if (std::make_tuple(q.holes, c.poorQuads, -c.worstQuad) < std::make_tuple(best.holes, bestCheck.poorQuads, -bestCheck.worstQuad))
      best = std::move(q), bestCheck = c;
    if (best.holes == 0 && bestCheck.poorQuads == 0) break;
  }
  if (best.quads.empty()) {
    std::ostringstream msg;
    msg << "could not quad-mesh the chordal surface: ";
    if (!gmshError.empty())
      msg << gmshError;
    else
      msg << "its reparametrization failed near (" << failedAt.x() << ", " << failedAt.y() << ", " << failedAt.z() << ")";
    throw geometryError(msg.str());
  }
  best.nodes = std::move(bestCheck.onSurface);  // back onto the chordal surface
  return best;
}

}  // namespace hexlayer
