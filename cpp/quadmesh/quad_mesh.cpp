#include "quadmesh/quad_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "core/child_process.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "core/union_find.hpp"
#include "quadmesh/block_grids.hpp"
#include "quadmesh/chordal_patches.hpp"
#include "quadmesh/crease_chains.hpp"
#include "quadmesh/patch_grids.hpp"
#include "quadmesh/quad_completion.hpp"
#include "quadmesh/quad_smoothing.hpp"
#include "quadmesh/quad_strips.hpp"
#include "quadmesh/sizing.hpp"

namespace hexlayer {
namespace {

// Gmsh's nodes stray from the chordal triangles by up to half a quad in strongly bent patches (its
// smoothing and recombination move them in 3D); farther than this x size means a failed reparametrization.
constexpr double kOffSurface = 1.0;
constexpr int kMaxStrip = 20;      // quads between two leftover triangles that are paired (quad_completion)
constexpr int kCurveSamples = 64;  // points along a patch curve to measure it
// Mean quad scaled Jacobian of a good try (no poor quad) that needs no other: a block grid that good is not matched
// against Gmsh's quads (was 0.98: on the ski part, the 200-hole plate and the periodic shell, grids of mean
// 0.966-0.977, one Gmsh try of 5-12 s each was run and lost to the grid; on none of 66 parts did Gmsh beat a good
// grid).
constexpr double kStructuredMean = 0.95;
// The shared grid round many holes is kept only with no quad below this (issue 19's bar for the hexes): where its
// layout fits the surface badly (a rounded rim's corner in a grid cell, a hole by a crooked rim), Gmsh meshes it
// as before.
constexpr double kSharedWorst = 0.5;
constexpr double kCreaseAngle = 40;  // degrees: the patch grid cuts the surface where it turns more
constexpr double kMinCorner = 45 * M_PI / 180, kMaxCorner = 135 * M_PI / 180;  // of a structured patch
// A block grid whose quad has its centre farther than this x size from the chordal surface cuts across a crease (a
// bend with a sharp inside edge, which its grid lines do not follow) and is refused: the hexes would cut the bend's
// corner off. A bend of the radius of the sizing's curvature term strays a tenth of this.
constexpr double kChordAcross = 0.25;
// The patch grid's quads end at the creases by construction; where three faces meet (a box's corner) the chordal
// surface cuts the corner off with a facet or two, and the quads round it lie off it by up to a third of a quad.
constexpr double kPatchChordAcross = 0.5;
// Beside an acceptable patch grid, a grid with a quad's centre farther than this x size from the chordal surface has
// quads across a sharp bend (the patch grid's rows run along it): the patch grid is kept in its place (a hat section
// bent sharply: the single grid's rows across its bends left 2.3 % of its volume out). A quad on a cylinder of radius
// R strays s / 8R of its size s: R >= 0.8 s passes.
constexpr double kCutsCrease = 0.15;

// Nodes of a discrete Gmsh entity: the given vertices (ids + 1 as tags). [in] dim, tag, ids, points.
void addEntityNodes(int dim, int tag, const std::vector<int>& ids, const std::vector<Vec3>& points) {
  if (ids.empty()) return;
  std::vector<std::size_t> tags;
  std::vector<double> coords;
  for (int v : ids) {
    tags.push_back(std::size_t(v) + 1);
    coords.insert(coords.end(), points[v].data(), points[v].data() + 3);
  }
  gmsh::model::mesh::addNodes(dim, tag, tags, coords);
}

// The chordal triangles as Gmsh's discrete model of HexLayer's own patches (chordal_patches.hpp): a point per
// corner, a curve per chain between them, a surface per patch bounded by its curves, each with its own nodes
// and elements, as Gmsh's classification would leave them. [in] points, triangles; [in] patch: per triangle.
void addOwnPatches(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                   const std::vector<int>& patch) {
  const PatchTopology topology = patchTopology(triangles, patch);
  std::vector<char> placed(points.size(), 0);  // the vertex is a node of an entity already
  std::map<int, int> pointTag;
  for (int v : topology.corners) {
    const int tag = gmsh::model::addDiscreteEntity(0);
    pointTag[v] = tag, placed[v] = 1;
    addEntityNodes(0, tag, {v}, points);
    gmsh::model::mesh::addElementsByType(tag, 15, {}, {std::size_t(v) + 1});
  }
  std::vector<int> curveTag;
  for (const PatchCurve& c : topology.curves) {
    const int tag = gmsh::model::addDiscreteEntity(1, -1, {pointTag[c.vertices.front()], pointTag[c.vertices.back()]});
    curveTag.push_back(tag);
    const std::vector<int> inside(c.vertices.begin() + 1, c.vertices.end() - 1);
    for (int v : inside) placed[v] = 1;
    addEntityNodes(1, tag, inside, points);
    std::vector<std::size_t> lines;
    for (std::size_t k = 0; k + 1 < c.vertices.size(); ++k)
      lines.insert(lines.end(), {std::size_t(c.vertices[k]) + 1, std::size_t(c.vertices[k + 1]) + 1});
    gmsh::model::mesh::addElementsByType(tag, 1, {}, lines);
  }
  for (std::size_t p = 0; p < topology.bounding.size(); ++p) {
    std::vector<int> bounding;
    for (int c : topology.bounding[p]) bounding.push_back(curveTag[c]);
    const int tag = gmsh::model::addDiscreteEntity(2, -1, bounding);
    std::vector<int> inside;
    std::vector<std::size_t> nodes;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      if (patch[t] == static_cast<int>(p))
        for (int v : triangles[t]) {
          nodes.push_back(std::size_t(v) + 1);
          if (!placed[v]) placed[v] = 1, inside.push_back(v);
        }
    addEntityNodes(2, tag, inside, points);
    gmsh::model::mesh::addElementsByType(tag, 2, {}, nodes);
  }
}

// The chordal facets as discrete Gmsh triangles (each quad split on a diagonal): one surface for Gmsh's
// classification, or with ownPatches HexLayer's patches (addOwnPatches). [in] chordal; [in] split.
void addChordalTriangles(const ChordalSurface& chordal, const PatchSplit& split) {
  const std::vector<std::array<int, 3>> triangles = chordalTriangles(chordal);
  if (split.ownPatches) {
    addOwnPatches(chordal.vertices, triangles, chordalPatches(chordal.vertices, triangles, split.featureAngle));
    return;
  }
  const int surface = gmsh::model::addDiscreteEntity(2);
  std::vector<int> all(chordal.vertices.size());
  std::iota(all.begin(), all.end(), 0);
  addEntityNodes(2, surface, all, chordal.vertices);
  std::vector<std::size_t> nodes;
  for (const auto& t : triangles)
    for (int v : t) nodes.push_back(std::size_t(v) + 1);
  gmsh::model::mesh::addElementsByType(surface, 2, {}, nodes);
}

double smallestSize(const QuadMeshOptions& o) {
  return o.vertexSize.empty() ? o.size : *std::min_element(o.vertexSize.begin(), o.vertexSize.end());
}

void setQuadOptions(const QuadMeshOptions& o, const PatchSplit& split, const ChordalLocator& chordal) {
  const bool adaptive = !o.vertexSize.empty();
  gmsh::option::setNumber("Mesh.MeshSizeMin", smallestSize(o));
  gmsh::option::setNumber("Mesh.MeshSizeMax",
                          adaptive ? *std::max_element(o.vertexSize.begin(), o.vertexSize.end()) : o.size);
  if (adaptive)  // §6.1: geometry-adaptive quads
    gmsh::model::mesh::setSizeCallback(
        [size = ChordalSizeField(chordal, o.vertexSize)](int, int, double x, double y, double z) mutable {
          return size(Vec3(x, y, z));
        });
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  // Frontal-Delaunay triangles (Frontal-Delaunay for quads, algorithm 8, crashes in Debian's Gmsh 4.8.4),
  // then Blossom full-quad recombination (a perfect matching, each quad split in four): all quads
  // without the §6.2 templates, and half the irregular nodes of the simple full-quad (algorithm 2),
  // whose leftover triangles become three quads around a 3-valent node.
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", split.recombination);
  gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
  gmsh::option::setNumber("Mesh.Smoothing", 5);
  gmsh::option::setNumber("Mesh.RandomFactor", 1e-9);
}

// A curve of Gmsh's patches, sampled from its start, with the point tags at its two ends.
struct SampledCurve {
  int tag = 0;
  std::array<int, 2> ends{-1, -1};
  std::vector<Vec3> points;
};

SampledCurve sampleCurve(int tag) {
  SampledCurve c;
  c.tag = tag;
  gmsh::vectorpair ends;
  gmsh::model::getBoundary({{1, tag}}, ends, false, false, false);
  if (ends.size() != 2 || std::abs(ends[0].second) == std::abs(ends[1].second)) return c;
  std::vector<double> lo, hi, params, xyz;
  gmsh::model::getParametrizationBounds(1, tag, lo, hi);
  for (int i = 0; i <= kCurveSamples; ++i) params.push_back(lo[0] + (hi[0] - lo[0]) * i / kCurveSamples);
  gmsh::model::getValue(1, tag, params, xyz);
  for (size_t i = 0; i + 2 < xyz.size(); i += 3) c.points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  std::vector<double> first;
  gmsh::model::getValue(0, std::abs(ends[0].second), {}, first);
  const bool firstIsStart = (Vec3(first[0], first[1], first[2]) - c.points.front()).norm() <=
                            (Vec3(first[0], first[1], first[2]) - c.points.back()).norm();
  c.ends = {std::abs(ends[firstIsStart ? 0 : 1].second), std::abs(ends[firstIsStart ? 1 : 0].second)};
  return c;
}

// The four curves of a patch bounded by four curves meeting at four corners of 45 to 135 degrees,
// ordered around it (curve k is opposite curve k + 2); empty for any other patch.
std::vector<SampledCurve> fourSides(int surface, std::map<int, SampledCurve>& curves) {
  gmsh::vectorpair bounds;
  gmsh::model::getBoundary({{2, surface}}, bounds, false, false, false);
  std::vector<SampledCurve> sides;
  for (const auto& [dim, tag] : bounds) {
    auto it = curves.find(std::abs(tag));
    if (it == curves.end()) it = curves.emplace(std::abs(tag), sampleCurve(std::abs(tag))).first;
    if (it->second.ends[0] < 0) return {};
    sides.push_back(it->second);
  }
  if (sides.size() != 4) return {};
  for (int k = 1; k < 4; ++k) {  // chain them: side k starts or ends where side k - 1 ends
    const int joint = sides[k - 1].ends[1];
    auto next = std::find_if(sides.begin() + k, sides.end(),
                             [&](const SampledCurve& c) { return c.ends[0] == joint || c.ends[1] == joint; });
    if (next == sides.end()) return {};
    std::swap(sides[k], *next);
    if (sides[k].ends[1] == joint)
      std::reverse(sides[k].points.begin(), sides[k].points.end()), std::swap(sides[k].ends[0], sides[k].ends[1]);
  }
  if (sides[3].ends[1] != sides[0].ends[0]) return {};
  for (int k = 0; k < 4; ++k) {  // the corner where side k ends and side k + 1 starts
    const auto& in = sides[k].points;
    const auto& out = sides[(k + 1) % 4].points;
    const double angle = std::acos(
        std::clamp((in[in.size() - 2] - in.back()).normalized().dot((out[1] - out[0]).normalized()), -1.0, 1.0));
    if (angle < kMinCorner || angle > kMaxCorner) return {};
  }
  return sides;
}

// A quad size at a point: uniform (`size`) if vertexSize is empty, else interpolated from it (the field is built once
// and keeps a pointer to vertexSize, which must outlive it).
SizeField sizeField(const ChordalLocator& chordal, double size, const std::vector<double>& vertexSize) {
  if (vertexSize.empty()) return [size](const Vec3&) { return size; };
  return [field = std::make_shared<const ChordalSizeField>(chordal, vertexSize)](const Vec3& p) {
    int facet = -1;  // the field may be asked from several threads: no facet kept between points
    return field->at(p, facet);
  };
}

// The target quad size at a point (uniform, or the adaptive sizing's), for the structured patches and the block
// grids.
SizeField targetSize(const ChordalLocator& chordal, const QuadMeshOptions& o) {
  return sizeField(chordal, o.size, o.vertexSize);
}

// Number of segments a curve needs at the target size.
double segmentsNeeded(const SampledCurve& c, const SizeField& size) {
  double segments = 0;
  for (size_t i = 0; i + 1 < c.points.size(); ++i) {
    const Vec3 mid = 0.5 * (c.points[i] + c.points[i + 1]);
    segments += (c.points[i + 1] - c.points[i]).norm() / size(mid);
  }
  return std::max(1.0, std::round(segments));
}

// The patches bounded by four curves get a structured (transfinite) grid: no irregular node, so
// the quads are as square as the patch's corners allow. Opposite curves get the same number of
// evenly spaced nodes, the most any of them needs (§6.1 sizing) along a chain of such patches: a
// structured patch takes the finest size it needs across it. (Spacing graded along the curves is
// interpolated in Gmsh's parametrization of the patch, which squeezes the rows along the rim.)
std::size_t structurePatches(const QuadMeshOptions& o, const ChordalLocator& chordal) {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::map<int, SampledCurve> curves;
  std::map<int, int> index;  // curve tag -> union-find element
  std::vector<std::pair<int, std::vector<SampledCurve>>> patches;
  for (const auto& [dim, surface] : surfaces) {
    std::vector<SampledCurve> sides = fourSides(surface, curves);
    if (sides.empty()) continue;
    for (const auto& c : sides) index.emplace(c.tag, static_cast<int>(index.size()));
    patches.emplace_back(surface, std::move(sides));
  }
  UnionFind opposite(index.size());
  for (const auto& [surface, sides] : patches)
    for (int k = 0; k < 2; ++k) opposite.unite(index[sides[k].tag], index[sides[k + 2].tag]);
  std::map<int, double> segments;  // union-find root -> segments of every curve in it
  const SizeField size = targetSize(chordal, o);
  for (const auto& [tag, at] : index) {
    double& s = segments[opposite.find(at)];
    s = std::max(s, segmentsNeeded(curves[tag], size));
  }
  for (const auto& [tag, at] : index)
    gmsh::model::mesh::setTransfiniteCurve(tag, static_cast<int>(segments[opposite.find(at)]) + 1);
  for (const auto& [surface, sides] : patches) {
    gmsh::model::mesh::setTransfiniteSurface(surface);
    gmsh::model::mesh::setRecombine(2, surface);
  }
  return patches.size();
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
  // The elements' own nodes: every node a quad or triangle uses, whichever entity holds it (with Gmsh's
  // createTopology, tried for the own patches, getNodes missed one that the elements held).
  std::map<std::size_t, Vec3> position;
  for (const int type : {3, 2}) {
    std::vector<std::size_t> nodeTags;
    std::vector<double> coord, param;
    gmsh::model::mesh::getNodesByElementType(type, nodeTags, coord, param, -1, false);
    for (size_t i = 0; i < nodeTags.size(); ++i)
      position.emplace(nodeTags[i], Vec3(coord[3 * i], coord[3 * i + 1], coord[3 * i + 2]));
  }
  QuadMesh q;
  std::map<std::size_t, int> index;  // Gmsh node tag -> our node id, in order of first use
  // Gmsh's nodes at one place are one node: its full-quad subdivision can give a curve's midpoint twice where two
  // patches meet at a rounded corner (a slit in the quads, another topology).
  std::map<std::array<double, 3>, int> at;
  auto node = [&](std::size_t tag) {
    const auto [it, added] = index.emplace(tag, -1);
    if (added) {
      const auto p = position.find(tag);
      if (p == position.end()) throw internalError("Gmsh gave no coordinates for node " + std::to_string(tag));
      const auto [same, isNew] = at.emplace(std::array<double, 3>{p->second.x(), p->second.y(), p->second.z()},
                                            static_cast<int>(q.nodes.size()));
      if (isNew) q.nodes.push_back(p->second);
      it->second = same->second;
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

// One Gmsh try: its quads, or why it failed (Gmsh's error, crash or hang).
struct GmshTry {
  QuadMesh quads;
  std::string failure;    // empty if the try gave quads
  bool timedOut = false;  // it ran out of its time budget
};

// The time budget of the next Gmsh try: at most what is left before the deadline, and the try's own (given, or
// gmshTryBudget of the surface's area over the size squared) once there are quads to fall back on: until then a
// try is not an improvement but needed, and may take what the stage has left. [in] chordal, o; [in] needed: no
// quads yet. Returns seconds (<= 0: none left).
double tryBudget(const ChordalSurface& chordal, const QuadMeshOptions& o, bool needed) {
  const double own = o.timeoutSeconds > 0 ? o.timeoutSeconds : gmshTryBudget(chordalArea(chordal) / (o.size * o.size));
  if (o.deadline == std::chrono::steady_clock::time_point::max()) return own;
  const double left = std::chrono::duration<double>(o.deadline - std::chrono::steady_clock::now()).count();
  return needed && o.timeoutSeconds <= 0 ? left : std::min(own, left);
}

// How a failure in making the patches begins (the tries with the same angles would fail the same way).
const std::string kPatchesFailed = "failed to make the patches: ";

// The message of the Gmsh error just thrown: Gmsh 4.8 throws its error code, the message is in its logger.
std::string lastGmshError() {
  std::string last;
  gmsh::logger::getLastError(last);
  return last.empty() ? "unknown Gmsh error" : last;
}

// Gmsh's patches of the chordal surface, reparametrized (classify, createGeometry): what depends on the split's
// angles only. Throws geometryError starting with kPatchesFailed if Gmsh fails there. [in] split.
void makePatches(const PatchSplit& split) {
  const double toRadians = M_PI / 180.0;
  try {
    if (!split.ownPatches)  // HexLayer's own patches come with their curves and points (addOwnPatches)
      gmsh::model::mesh::classifySurfaces(split.featureAngle * toRadians, true, true, split.curveAngle * toRadians);
    gmsh::model::mesh::createGeometry();
  } catch (...) {
    throw geometryError(kPatchesFailed + lastGmshError());
  }
}

// One Gmsh run: split the chordal surface into patches, reparametrize, mesh.
// Gmsh runs in a child process: its crashes and hangs (both seen on real parts with Gmsh 4.8) end
// that try only.
// [in] locator: the chordal surface; [in] o: sizes; [in] split; [in] budget: seconds the try may take.
// Returns the running child (finishGmshQuads waits for its quads).
StartedChild startGmshQuads(const ChordalLocator& locator, const QuadMeshOptions& o, const PatchSplit& split,
                            double budget) {
  const ChordalSurface& chordal = locator.surface();
  return startChildProcess(
      [&] {
        return inGmshSession([&] {
          gmsh::model::add("chordal_surface");
          addChordalTriangles(chordal, split);
          makePatches(split);
          // Gmsh 4.8 caps every mesh size by the model's size, which is only computed on a synchronize:
          // without it, the discrete model's default of 1 caps the adaptive sizes (§6.1).
          gmsh::model::geo::synchronize();
          QuadMeshOptions sized = o;
          if (split.ownPatches && !o.ownPatchSize.empty()) sized.vertexSize = o.ownPatchSize;
          setQuadOptions(sized, split, locator);
          const std::size_t structured = split.structured ? structurePatches(sized, locator) : 0;
          gmsh::model::mesh::generate(2);
          QuadMesh q = collectQuads();
          q.structuredPatches = structured;
          return toBytes(q);
        });
      },
      budget);
}

// [in,out] child: a started try, waited for. Returns its quads, or why none.
GmshTry finishGmshQuads(StartedChild& child) {
  const ChildResult run = waitForChild(child);
  if (!run.ok) return {{}, "Gmsh " + run.failure, run.timedOut};
  GmshTry done{fromBytes(run.output), "", false};
  if (done.quads.quads.empty()) done.failure = "Gmsh made no quads";
  return done;
}

// How far the quad mesh is from the chordal surface it should lie on (a failed reparametrization
// puts nodes far away).
struct SurfaceCheck {
  double farthest = 0;
  Vec3 farthestNode = Vec3::Zero();
  std::vector<Vec3> onSurface;  // every node moved to its nearest point of the chordal surface
};

SurfaceCheck onChordalSurface(const QuadMesh& q, const ChordalLocator& chordal) {
  SurfaceCheck c;
  c.onSurface = q.nodes;
  const long n = static_cast<long>(q.nodes.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i)
    if (q.nodes[i].allFinite()) c.onSurface[i] = chordal.locate(q.nodes[i]).point;
  for (long i = 0; i < n; ++i) {
    const Vec3& p = q.nodes[i];
    const double d = p.allFinite() ? (c.onSurface[i] - p).norm() : std::numeric_limits<double>::infinity();
    if (d > c.farthest) c.farthest = d, c.farthestNode = p;
  }
  return c;
}

// Every use of a quad edge: the edge, the quad, and whether the quad runs it from its lower node.
struct EdgeUse {
  std::uint64_t edge;
  int quad;
  bool fromLower;
  bool operator<(const EdgeUse& o) const { return std::tie(edge, quad) < std::tie(o.edge, o.quad); }
};

// The quads' edge uses, sorted by edge (the uses of one edge side by side).
std::vector<EdgeUse> quadEdgeUses(const QuadMesh& q) {
  std::vector<EdgeUse> uses;
  uses.reserve(4 * q.quads.size());
  for (std::size_t e = 0; e < q.quads.size(); ++e)
    for (int k = 0; k < 4; ++k) {
      const int a = q.quads[e][k], b = q.quads[e][(k + 1) % 4];
      uses.push_back({edgeKey(a, b), static_cast<int>(e), a < b});
    }
  std::sort(uses.begin(), uses.end());
  return uses;
}

// Euler characteristic V - E + F of the quad mesh: Gmsh's quads too coarse for a small hole close it.
long eulerCharacteristic(const QuadMesh& q, const std::vector<EdgeUse>& uses) {
  long edges = 0;
  for (std::size_t i = 0; i < uses.size(); ++i) edges += i == 0 || uses[i].edge != uses[i - 1].edge;
  return static_cast<long>(q.nodes.size()) - edges + static_cast<long>(q.quads.size());
}

long eulerCharacteristic(const ChordalSurface& s) {
  return static_cast<long>(s.vertices.size()) - static_cast<long>(facetEdgeUses(s).size()) +
         static_cast<long>(s.facets.size());
}

// The Euler characteristic the quads should have: the chordal surface's with its pinholes closed (rim loops shorter
// than the smallest quad edge, left between facets where sheets meet at a corner: no quad mesh keeps one, and closing
// it is no change of the part's topology). [in] s, smallest: the smallest target size.
long eulerWithoutPinholes(const ChordalSurface& s, double smallest) {
  const RimLoops loops = rimLoops(s);
  return eulerCharacteristic(s) +
         std::count_if(loops.length.begin(), loops.length.end(), [&](double length) { return length < smallest; });
}

// A smoothed try's quads, best first: the chordal surface's topology, fewest holes, fewest
// inverted quads (and folded edges), fewest poor quads, best mean quad, best worst quad.
struct QuadScore {
  bool topologyChanged = true;
  std::size_t holes = std::numeric_limits<std::size_t>::max(), inverted = std::numeric_limits<std::size_t>::max(),
              poor = std::numeric_limits<std::size_t>::max();
  double worst = -1, mean = -1;
  std::size_t creasesMissed = std::numeric_limits<std::size_t>::max();  // QuadMeshOptions::creases not followed
  auto key() const { return std::make_tuple(topologyChanged, holes, inverted, creasesMissed, poor, -mean, -worst); }
  bool operator<(const QuadScore& o) const { return key() < o.key(); }
  bool good() const { return !topologyChanged && holes == 0 && inverted == 0 && poor == 0; }
};

// Edges between quads the sweep will turn to face opposite ways: it turns every quad to face the
// chordal normal, so a quad folded over against its neighbour gives hexes with flipped faces.
std::size_t foldedEdges(const QuadMesh& q, const std::vector<EdgeUse>& uses, const ChordalLocator& chordal) {
  std::vector<char> facesNormal(q.quads.size());
  const long quads = static_cast<long>(q.quads.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long e = 0; e < quads; ++e) {
    const auto& quad = q.quads[e];
    const Vec3 centroid = 0.25 * (q.nodes[quad[0]] + q.nodes[quad[1]] + q.nodes[quad[2]] + q.nodes[quad[3]]);
    const Vec3 n = (q.nodes[quad[2]] - q.nodes[quad[0]]).cross(q.nodes[quad[3]] - q.nodes[quad[1]]);
    facesNormal[e] = n.dot(normalAt(chordal.surface(), chordal.locate(centroid))) >= 0;
  }
  std::size_t folded = 0;
  for (std::size_t i = 0; i + 1 < uses.size();
       ++i) {  // an inside edge: turned, its two quads must run it opposite ways
    const EdgeUse &a = uses[i], &b = uses[i + 1];
    const bool inside = a.edge == b.edge && (i == 0 || uses[i - 1].edge != a.edge) &&
                        (i + 2 == uses.size() || uses[i + 2].edge != a.edge);
    if (inside) folded += (a.fromLower != facesNormal[a.quad]) == (b.fromLower != facesNormal[b.quad]);
  }
  return folded;
}

QuadScore scoreQuads(const QuadMesh& q, const ChordalLocator& chordal, long chordalEuler, double acceptableQuad) {
  const std::vector<EdgeUse> uses = quadEdgeUses(q);
  QuadScore s{eulerCharacteristic(q, uses) != chordalEuler, q.holes, foldedEdges(q, uses, chordal), 0, 1, 0, 0};
  for (const auto& quad : q.quads) {
    const double sj = quadScaledJacobian({q.nodes[quad[0]], q.nodes[quad[1]], q.nodes[quad[2]], q.nodes[quad[3]]});
    s.worst = std::min(s.worst, sj), s.mean += sj / q.quads.size();
    s.inverted += sj <= 0, s.poor += sj < acceptableQuad;
  }
  return s;
}

// A try's quads made ready and ranked: doublets removed, smoothed, scored (its creases followed on a copy: those
// whose chain is dropped are counted).
QuadScore finishTry(QuadMesh& q, const ChordalLocator& chordal, const QuadMeshOptions& o, long chordalEuler) {
  q.doubletsRemoved = removeDoublets(q);
  smoothQuadMesh(q, chordal, o.smoothingIterations);
  QuadScore s = scoreQuads(q, chordal, chordalEuler, o.acceptableQuad);
  if (!o.creases.empty()) {
    QuadMesh followed = q;
    s.creasesMissed = followCreases(followed, chordal, o.creases).dropped;
  }
  return s;
}

// A block grid as a try, if it has quads, pillowed where a corner lies on a smooth stretch of its rim
// (pillowFlatCorners). [in,out] tries; [in] grid, layout.
void addBlockGrid(std::vector<QuadMesh>& tries, BlockGrid grid, QuadLayout layout) {
  if (grid.empty()) return;
  QuadMesh q;
  q.nodes = std::move(grid.nodes), q.quads = std::move(grid.quads), q.structuredPatches = grid.blocks,
  q.layout = layout;
  q.structuredPatches += pillowFlatCorners(q);  // the ring is a block
  tries.push_back(std::move(q));
}

// The target size of the patch grid: the own patches' (without the curvature term) where the sizing is adaptive.
SizeField creaseSize(const ChordalLocator& chordal, const QuadMeshOptions& o) {
  return sizeField(chordal, o.size, o.ownPatchSize.empty() ? o.vertexSize : o.ownPatchSize);
}

// The structured block grids of the chordal surface (block_grids.hpp): a grid with a pocket round each hole (where
// the pockets would meet or reach the rim, the shared grid round all the holes), and if its rim has no four sharp
// corners, an O-grid too (if it is a disc; if it is a triangle, the triangle grid), and a ring grid if it has two rims
// (a tube, a ring). Each is a disc with
// the map's holes: none is made where that is not the topology the quads must have (a pinhole the quads close).
// [in] chordal; [in] square: its map onto the square; [in] o; [in] chordalEuler. Returns the tries.
std::vector<QuadMesh> blockGridQuads(const ChordalLocator& chordal, const SurfaceMap& square, const QuadMeshOptions& o,
                                     long chordalEuler) {
  if (1 - static_cast<long>(square.holes.size()) != chordalEuler) return {};
  const SizeField size = targetSize(chordal, o);
  std::vector<QuadMesh> tries;
  if (BlockGrid holed = holedGrid(square, size); !holed.empty())
    addBlockGrid(tries, std::move(holed), QuadLayout::Grid);
  else if (!square.holes.empty())
    addBlockGrid(tries, sharedGrid(square, size), QuadLayout::SharedGrid);
  if (!square.empty() && !square.sharpCorners && square.holes.empty())
    addBlockGrid(tries, oGrid(mapToPlane(chordal.surface(), o.size, MapBoundary::Circle), size), QuadLayout::OGrid);
  addBlockGrid(tries, triangleGrid(square, size, [&](const Vec3& p) { return chordal.locate(p).point; }),
               QuadLayout::TriangleGrid);
  if (!square.empty() && square.holes.size() == 1)
    addBlockGrid(tries, ringGrid(mapToPlane(chordal.surface(), o.size, MapBoundary::Annulus), size, o.ringAround),
                 QuadLayout::Ring);
  return tries;
}

// The best quads so far and their score; `failure` says why the Gmsh tries gave none.
struct Ranked {
  QuadMesh best;
  QuadScore score;
  Vec3 failedAt = Vec3::Zero();  // where the last reparametrization failed
  std::string gmshError;         // the last try's failure, if it failed in Gmsh
  void keep(QuadMesh& q, const QuadScore& s) {
    if (s < score) best = std::move(q), score = s;
  }
};

// The farthest a quad's centre (the mean of its corners) lies from the chordal surface. [in] q, chordal.
double farthestQuadCentre(const QuadMesh& q, const ChordalLocator& chordal) {
  double farthest = 0;
  for (const auto& quad : q.quads) {
    const Vec3 centre = 0.25 * (q.nodes[quad[0]] + q.nodes[quad[1]] + q.nodes[quad[2]] + q.nodes[quad[3]]);
    farthest = std::max(farthest, (chordal.locate(centre).point - centre).norm());
  }
  return farthest;
}

// Block grid tries finished side by side (a single try keeps its own parallel loops: an inactive region does not
// nest them), then ranked in order; one with an inverted quad (its layout does not fit the surface), another
// topology or a quad across a crease (kChordAcross; kPatchChordAcross for the patch grid) is refused, the shared grid
// also with a quad below kSharedWorst, and beside an acceptable patch grid any grid with quads across its bends
// (kCutsCrease).
// Another topology is refused before the try is finished (finishing keeps it: removing a doublet takes a node, two
// edges and a quad), and the smoothing it would have cost is saved.
// [in,out] blocks: the tries; [in,out] ranked. Returns whether the holed grid was refused or its quads' mean is under
// kStructuredMean (the pockets round off square cutouts that the shared grid's cells fit).
bool rankBlockGrids(std::vector<QuadMesh>& blocks, const ChordalLocator& chordal, const QuadMeshOptions& o,
                    long chordalEuler, Ranked& ranked) {
  std::vector<QuadScore> scores(blocks.size());
  std::vector<double> farthest(blocks.size(), 0.0);  // of a quad's centre from the surface, in sizes
#pragma omp parallel for schedule(dynamic) if (blocks.size() > 1)
  for (long i = 0; i < static_cast<long>(blocks.size()); ++i) {
    if (eulerCharacteristic(blocks[i], quadEdgeUses(blocks[i])) != chordalEuler) continue;  // refused unfinished
    blocks[i].nodes = onChordalSurface(blocks[i], chordal).onSurface;
    scores[i] = finishTry(blocks[i], chordal, o, chordalEuler);
    farthest[i] = farthestQuadCentre(blocks[i], chordal) / o.size;
  }
  auto acceptable = [&](std::size_t i) {
    const bool patch = blocks[i].layout == QuadLayout::PatchGrid;
    return !scores[i].topologyChanged && scores[i].inverted == 0 &&
           farthest[i] <= (patch ? kPatchChordAcross : kChordAcross) &&
           (blocks[i].layout != QuadLayout::SharedGrid || scores[i].worst >= kSharedWorst);
  };
  bool patchGrid = false;  // an acceptable patch grid: the grids whose quads cut its creases are not
  for (std::size_t i = 0; i < blocks.size(); ++i)
    patchGrid |= blocks[i].layout == QuadLayout::PatchGrid && acceptable(i);
  bool holedWanting = false;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const bool cutsCreases = patchGrid && blocks[i].layout != QuadLayout::PatchGrid && farthest[i] > kCutsCrease;
    const bool holed = blocks[i].layout == QuadLayout::Grid;
    if (acceptable(i) && !cutsCreases) {
      holedWanting |= holed && scores[i].mean < kStructuredMean;
      ranked.keep(blocks[i], scores[i]);
    } else {
      holedWanting |= holed;
    }
  }
  return holedWanting;
}

// Where the patch grid graded towards its creases lost or was refused, the one with even rows ranked.
// [in] graded: whether there was a graded one; [in,out] patch: its grids (the even one moved from); [in,out] ranked.
void rankEvenPatchGrid(bool graded, PatchGrids& patch, const ChordalLocator& chordal, const QuadMeshOptions& o,
                       long chordalEuler, Ranked& ranked) {
  if (!graded || ranked.best.layout == QuadLayout::PatchGrid) return;
  std::vector<QuadMesh> even;
  addBlockGrid(even, std::move(patch.even), QuadLayout::PatchGrid);
  rankBlockGrids(even, chordal, o, chordalEuler, ranked);
}

// The patch grid of faces grown and rimmed as `seeds` and `rims` say (patchGrids), ranked: graded towards its creases,
// and with even rows where that one is refused or outranked. [in] chordal, o, chordalEuler; [in] seeds, rims;
// [in,out] ranked.
void rankPatchGrid(const ChordalLocator& chordal, const QuadMeshOptions& o, long chordalEuler, PatchSeeds seeds,
                   PatchRims rims, Ranked& ranked, PatchSides sides = PatchSides::FourCorners) {
  PatchGrids patch = patchGrids(chordal.surface(), creaseSize(chordal, o), kCreaseAngle, seeds, rims, sides);
  if (patch.even.empty()) return;
  const bool graded = !patch.graded.empty();
  std::vector<QuadMesh> tries;
  addBlockGrid(tries, graded ? std::move(patch.graded) : patch.even, QuadLayout::PatchGrid);
  rankBlockGrids(tries, chordal, o, chordalEuler, ranked);
  rankEvenPatchGrid(graded, patch, chordal, o, chordalEuler, ranked);
}

// Structured block grids first, the patch grid (patch_grids.hpp) after them: where one has square enough quads, Gmsh
// is not needed. Where the holed grid is refused or its quads' mean is under kStructuredMean, the shared grid round all
// the holes is ranked too; where the patch grid graded towards its creases is refused or outranked, the patch grid
// with even rows. Where the faces as grown give no acceptable patch grid, those with their rims fitted to their normals
// (PatchRims::FittedToNormals) may. Where the faces grown in index order give no patch grid, those grown from their
// flat middles first (PatchSeeds::FlatFirst) may, ranked after the others: their cuts may lie where the surface only
// curves (a tube's), so they refuse no grid that crosses them. Where none is acceptable, the patch grids of faces whose
// loops have five or six corners, the gentlest left inside a side (PatchSides::KinksInSides), grown both ways (also
// where the best misses a crease the quads should follow: QuadMeshOptions::creases).
Ranked bestBlockGrid(const ChordalLocator& chordal, const QuadMeshOptions& o, long chordalEuler) {
  Ranked ranked;
  SurfaceMap square;
  PatchGrids patch;
  // the map onto the plane is on one thread: the patch grids beside it (the block grids after, on every thread)
  sideBySide({[&] { patch = patchGrids(chordal.surface(), creaseSize(chordal, o), kCreaseAngle); },
              [&] { square = mapToPlane(chordal.surface(), o.size, MapBoundary::Square); }});
  std::vector<QuadMesh> blocks = blockGridQuads(chordal, square, o, chordalEuler);
  const bool graded = !patch.graded.empty();
  const bool none = patch.even.empty();
  addBlockGrid(blocks, graded ? std::move(patch.graded) : patch.even, QuadLayout::PatchGrid);
  if (rankBlockGrids(blocks, chordal, o, chordalEuler, ranked)) {
    std::vector<QuadMesh> shared;
    addBlockGrid(shared, sharedGrid(square, targetSize(chordal, o)), QuadLayout::SharedGrid);
    rankBlockGrids(shared, chordal, o, chordalEuler, ranked);
  }
  rankEvenPatchGrid(graded, patch, chordal, o, chordalEuler, ranked);
  if (ranked.best.layout != QuadLayout::PatchGrid)
    rankPatchGrid(chordal, o, chordalEuler, PatchSeeds::InOrder, PatchRims::FittedToNormals, ranked);
  if (none) rankPatchGrid(chordal, o, chordalEuler, PatchSeeds::FlatFirst, PatchRims::AsGrown, ranked);
  for (const PatchSeeds seeds : {PatchSeeds::InOrder, PatchSeeds::FlatFirst})  // the last layouts before Gmsh's
    if (ranked.best.quads.empty() || ranked.score.creasesMissed > 0)
      rankPatchGrid(chordal, o, chordalEuler, seeds, PatchRims::AsGrown, ranked, PatchSides::KinksInSides);
  return ranked;
}

// One Gmsh try's quads checked (on the chordal surface), finished and ranked. [in,out] t: the try; [in,out]
// ranked: the best so far. Returns false if the try failed.
bool rankGmshTry(GmshTry& t, const ChordalLocator& chordal, const QuadMeshOptions& o, long chordalEuler,
                 Ranked& ranked) {
  if (!t.failure.empty()) {
    ranked.gmshError = t.failure;
    return false;
  }
  QuadMesh& q = t.quads;
  SurfaceCheck c = onChordalSurface(q, chordal);
  if (!(c.farthest < kOffSurface * o.size)) {
    ranked.failedAt = c.farthestNode, ranked.gmshError.clear();
    return false;
  }
  q.nodes = std::move(c.onSurface);
  ranked.keep(q, finishTry(q, chordal, o, chordalEuler));
  return true;
}

// Why no try gave quads. [in] ranked, tries. Returns the message.
std::string noQuadsReason(const Ranked& ranked, const QuadTries& tries) {
  if (!ranked.gmshError.empty()) return ranked.gmshError;
  if (tries.run == 0 && tries.skipped > 0) return "the quad stage's time budget was spent before a Gmsh try began";
  std::ostringstream msg;
  msg << "its reparametrization failed near (" << ranked.failedAt.x() << ", " << ranked.failedAt.y() << ", "
      << ranked.failedAt.z() << ")";
  return msg.str();
}

// Gmsh, one patch split after the other, until a try is good (or the block grid is good with a mean quad of
// kStructuredMean) or the deadline: each try gets its budget (tryBudget), one that runs out is a failed try.
// With more than one thread the next try that will run whatever this one gives (other angles: not waiting to learn
// whether this one's patches fail) is started beside it, and stopped unused if this one ends the tries: the same
// tries ranked in the same order, the same quads.
// [in,out] ranked: the best quads so far, and why none if so. Returns the tries.
QuadTries gmshTries(const ChordalLocator& chordal, const QuadMeshOptions& o, long chordalEuler, Ranked& ranked) {
  QuadTries tries;
  const std::size_t splits = o.patchSplits.size();
  std::set<std::tuple<double, double, bool>> failedPatches;  // angles (and whose patches) Gmsh could not make
  auto angles = [&](std::size_t i) {
    const PatchSplit& split = o.patchSplits[i];
    return std::make_tuple(split.featureAngle, split.curveAngle, split.ownPatches);
  };
  // The own patches are a fallback: not tried once a try has given quads.
  auto fallbackNotNeeded = [&](std::size_t i) { return o.patchSplits[i].ownPatches && !ranked.best.quads.empty(); };
  std::optional<std::pair<std::size_t, StartedChild>> ahead;  // the next try, started beside the current one
  auto startAhead = [&](std::size_t i) {
    if (threadCount() < 2) return;
    for (std::size_t k = i + 1; k < splits; ++k) {
      if (failedPatches.count(angles(k))) continue;  // skipped whatever try i gives
      if (fallbackNotNeeded(k)) return;
      if (angles(k) == angles(i)) return;  // to be skipped if try i's patches fail
      if (const double budget = tryBudget(chordal.surface(), o, ranked.best.quads.empty()); budget > 0)
        ahead.emplace(k, startGmshQuads(chordal, o, o.patchSplits[k], budget));
      return;
    }
  };
  for (std::size_t i = 0; i < splits && !(ranked.score.good() && ranked.score.mean >= kStructuredMean); ++i) {
    const PatchSplit& split = o.patchSplits[i];
    const bool samePatches = failedPatches.count(angles(i)) > 0;  // the same patches: the same failure
    if (samePatches || fallbackNotNeeded(i)) {
      tries.samePatches += samePatches;
      if (o.tried) o.tried(2 + i, 1 + splits);
      continue;
    }
    const double budget = tryBudget(chordal.surface(), o, ranked.best.quads.empty());
    if (budget <= 0) {  // the stage's budget is spent: the rest are skipped
      tries.skipped = splits - i;
      break;
    }
    StartedChild child =
        ahead && ahead->first == i ? std::move(ahead->second) : startGmshQuads(chordal, o, split, budget);
    if (ahead && ahead->first != i) stopChild(ahead->second);  // an own-patch try started ahead, skipped
    ahead.reset();
    startAhead(i);
    GmshTry t = finishGmshQuads(child);
    if (t.failure.find(kPatchesFailed) != std::string::npos) failedPatches.insert(angles(i));
    const bool meshed = rankGmshTry(t, chordal, o, chordalEuler, ranked);
    ++tries.run, tries.timedOut += t.timedOut, tries.failed += !meshed;
    if (o.tried) o.tried(2 + i, 1 + splits);
    if (meshed && ranked.score.good()) break;
    if (o.patchFailuresToGiveUp > 0 && failedPatches.size() >= o.patchFailuresToGiveUp && ranked.best.quads.empty()) {
      tries.givenUp = splits - i - 1;
      break;
    }
  }
  if (ahead) stopChild(ahead->second);
  if (ranked.best.quads.empty()) ranked.best.failure = noQuadsReason(ranked, tries);
  return tries;
}

}  // namespace

long holesClosed(const QuadMesh& quads, const ChordalSurface& chordal) {
  return eulerCharacteristic(quads, quadEdgeUses(quads)) - eulerCharacteristic(chordal);
}

std::vector<std::vector<int>> rimEdgeNeighbours(const QuadMesh& q) {
  std::unordered_map<std::uint64_t, int> use;
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k) ++use[edgeKey(quad[k], quad[(k + 1) % 4])];
  std::vector<std::vector<int>> around(q.nodes.size());
  for (const auto& quad : q.quads)
    for (int k = 0; k < 4; ++k)
      if (int a = quad[k], b = quad[(k + 1) % 4]; use[edgeKey(a, b)] == 1)
        around[a].push_back(b), around[b].push_back(a);
  return around;
}

double meanEdge(const QuadMesh& q) {
  double sum = 0;
  for (const auto& quad : q.quads)
    for (int c = 0; c < 4; ++c) sum += (q.nodes[quad[c]] - q.nodes[quad[(c + 1) % 4]]).norm();
  return q.quads.empty() ? 0 : sum / (4.0 * q.quads.size());
}

QuadTries& QuadTries::operator+=(const QuadTries& o) {
  run += o.run, failed += o.failed, timedOut += o.timedOut, skipped += o.skipped, samePatches += o.samePatches;
  givenUp += o.givenUp;
  return *this;
}

double gmshTryBudget(double quads) { return 60 + quads / 200; }

QuadMesh tryQuadMeshes(const ChordalLocator& chordal, const QuadMeshOptions& o) {
  if (!(o.size > 0)) throw usageError("quad size must be positive");
  const long chordalEuler = eulerWithoutPinholes(chordal.surface(), smallestSize(o));
  Ranked ranked = bestBlockGrid(chordal, o, chordalEuler);
  if (o.tried) o.tried(1, 1 + o.patchSplits.size());
  ranked.best.tries = gmshTries(chordal, o, chordalEuler, ranked);
  return std::move(ranked.best);
}

QuadMesh gmshQuads(const ChordalLocator& chordal, const QuadMeshOptions& o, const PatchSplit& split) {
  StartedChild child = startGmshQuads(chordal, o, split, tryBudget(chordal.surface(), o, true));
  GmshTry done = finishGmshQuads(child);
  done.quads.failure = done.failure;
  return done.quads;
}

QuadMesh meshChordalSurface(const ChordalLocator& chordal, const QuadMeshOptions& o) {
  QuadMesh q = tryQuadMeshes(chordal, o);
  if (q.quads.empty()) throw geometryError("could not quad-mesh the chordal surface: " + q.failure);
  return q;
}

std::string toBytes(const QuadMesh& q) {
  const std::size_t counts[6] = {q.nodes.size(),   q.quads.size(), q.pairedTriangles,
                                 q.splitTriangles, q.holes,        q.structuredPatches};
  std::string bytes(reinterpret_cast<const char*>(counts), sizeof counts);
  for (const Vec3& p : q.nodes) bytes.append(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
  bytes.append(reinterpret_cast<const char*>(q.quads.data()), q.quads.size() * sizeof(q.quads[0]));
  return bytes;
}

QuadMesh fromBytes(const std::string& bytes) {
  std::size_t counts[6];
  if (bytes.size() < sizeof counts) throw internalError("truncated quad mesh from the Gmsh process");
  std::memcpy(counts, bytes.data(), sizeof counts);
  QuadMesh q;
  q.nodes.resize(counts[0]);
  q.quads.resize(counts[1]);
  q.pairedTriangles = counts[2];
  q.splitTriangles = counts[3];
  q.holes = counts[4];
  q.structuredPatches = counts[5];
  const std::size_t nodeBytes = counts[0] * 3 * sizeof(double), quadBytes = counts[1] * sizeof(q.quads[0]);
  if (bytes.size() != sizeof counts + nodeBytes + quadBytes)
    throw internalError("truncated quad mesh from the Gmsh process");
  const char* at = bytes.data() + sizeof counts;
  for (Vec3& p : q.nodes) std::memcpy(p.data(), at, 3 * sizeof(double)), at += 3 * sizeof(double);
  std::memcpy(static_cast<void*>(q.quads.data()), at, quadBytes);
  return q;
}

namespace {

// Gmsh is one process-wide session: open it for one piece of work only, and always close it.
struct GmshSession {
  GmshSession() { openGmshSession(); }
  ~GmshSession() { gmsh::finalize(); }
};

}  // namespace

void openGmshSession() {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);  // deterministic output
}

std::string namingGmshErrors(const std::function<std::string()>& work) {
  try {
    return work();
  } catch (const std::exception&) {
    throw;
  } catch (...) {  // Gmsh's error code (lastGmshError)
    throw geometryError(lastGmshError());
  }
}

std::string inGmshSession(const std::function<std::string()>& work) {
  GmshSession session;
  return namingGmshErrors(work);
}

}  // namespace hexlayer
