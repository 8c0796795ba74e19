#include "tets/tet_mesh.hpp"

#include <tetgen.h>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <TopoDS_Shell.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "geometry/boundary_triangles.hpp"
#include "geometry/ray_caster.hpp"

namespace hexlayer {

namespace {

constexpr double kJitter = 1e-6;    // of the nodes' bounding box diagonal
constexpr double kCoplanar = 1e-4;  // isCoplanarTet: 6 V below this x shortest edge x longest edge squared

// A fixed pseudo-random number in [-1, 1] for (node, coordinate): the same input gives the same tets.
double jitter(std::size_t node, int coordinate) {
  std::uint64_t h = node * 3 + coordinate + 0x9E3779B97F4A7C15ull;  // splitmix64
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  h ^= h >> 31;
  return 2.0 * static_cast<double>(h >> 11) / static_cast<double>(1ull << 53) - 1.0;
}

bool isCoplanar(const TetMesh& mesh, const std::array<int, 4>& t) {
  return isCoplanarTet({mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]});
}

// Whether the coplanar tet lies in the rim: its centre closer to the solid's boundary than a quarter
// of its shortest top-bottom edge (about the wall thickness; a bend's coplanar tet is half of it away).
// A centre clearly farther than that from the triangulation is not measured on the exact shell.
// [in,out] boundary: the distance tool with the solid's outer shell loaded once, at its first use (LoadS2: its faces'
// boxes are made once; Perform recomputes the rest, the same bits as a tool built per query).
bool onTheRim(const TetMesh& mesh, const std::array<int, 4>& t, const CadSolid& cad,
              std::optional<BRepExtrema_DistShapeShape>& boundary, const BoundaryTriangles& triangles) {
  double shortest = std::numeric_limits<double>::infinity();
  Vec3 c = Vec3::Zero();
  for (int a : t) {
    c += 0.25 * mesh.nodes[a];
    for (int b : t)
      if (mesh.side[a] == Side::Top && mesh.side[b] == Side::Bottom)
        shortest = std::min(shortest, (mesh.nodes[a] - mesh.nodes[b]).norm());
  }
  if (triangles.fartherThan(c, 0.25 * shortest)) return false;
  if (!boundary) boundary.emplace(), boundary->LoadS2(BRepClass3d::OuterShell(cad.solid));
  boundary->LoadS1(BRepBuilderAPI_MakeVertex(gp_Pnt(c.x(), c.y(), c.z())).Vertex());
  boundary->Perform();
  return boundary->IsDone() && boundary->Value() < 0.25 * shortest;
}

// Whether p is inside the solid: the triangulation decides where it can, rays on the exact faces near the
// boundary, and OpenCASCADE's classifier where no ray gives a clean count (each made on first use: one per
// thread, as they keep state).
bool insideSolid(const Vec3& p, const BoundaryTriangles& triangles, const CadSolid& cad, std::optional<RayCaster>& rays,
                 std::optional<BRepClass3d_SolidClassifier>& exact) {
  const Containment quick = triangles.classify(p);
  if (quick != Containment::kUndecided) return quick == Containment::kInside;
  const double tolerance = 1e-7 * cad.diagonal;
  if (!rays) rays.emplace(cad, tolerance);
  if (const std::optional<bool> in = rays->inside(p, tolerance, 2 * cad.diagonal)) return *in;
  if (!exact) exact.emplace(cad.solid);
  exact->Perform(gp_Pnt(p.x(), p.y(), p.z()), 1e-7 * cad.diagonal);
  return exact->State() == TopAbs_IN;
}

enum Verdict : char { kKept, kKeptCoplanar, kFlat, kOutside };

// Coplanar tets that lie on the hull of the kept tets: two of their faces are shared with no other kept
// tet, so the sliver stands in the plane where the tets end (a round or filleted rim, whose hull plane runs
// inside the solid, away from its boundary), instead of between tets on both sides (a sharp bend). Peeled
// until none is left, as dropping one can lay open another behind it.
// [in,out] verdict: per tet; peeled slivers become kOutside.
// Face `skip` of tet t (the other three corners), its corners sorted. [in] t, skip.
std::array<int, 3> sortedFace(const std::array<int, 4>& t, int skip) {
  std::array<int, 3> f{};
  for (int k = 0, j = 0; k < 4; ++k)
    if (k != skip) f[j++] = t[k];
  std::sort(f.begin(), f.end());
  return f;
}

void peelHullSlivers(const TetMesh& mesh, std::vector<char>& verdict) {
  auto kept = [&](std::size_t i) { return verdict[i] == kKept || verdict[i] == kKeptCoplanar; };
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::array<int, 3>> sliverFaces;  // the faces of the coplanar tets, sorted: how many kept tets use each
    for (std::size_t i = 0; i < mesh.tets.size(); ++i)
      if (verdict[i] == kKeptCoplanar)
        for (int skip = 0; skip < 4; ++skip) sliverFaces.push_back(sortedFace(mesh.tets[i], skip));
    if (sliverFaces.empty()) return;
    std::sort(sliverFaces.begin(), sliverFaces.end());
    sliverFaces.erase(std::unique(sliverFaces.begin(), sliverFaces.end()), sliverFaces.end());
    std::vector<int> uses(sliverFaces.size(), 0);
    for (std::size_t i = 0; i < mesh.tets.size(); ++i)
      if (kept(i))
        for (int skip = 0; skip < 4; ++skip) {
          const std::array<int, 3> f = sortedFace(mesh.tets[i], skip);
          const auto at = std::lower_bound(sliverFaces.begin(), sliverFaces.end(), f);
          if (at != sliverFaces.end() && *at == f) ++uses[at - sliverFaces.begin()];
        }
    for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
      if (verdict[i] != kKeptCoplanar) continue;
      int open = 0;  // faces shared with no other kept tet
      for (int skip = 0; skip < 4; ++skip) {
        const auto at = std::lower_bound(sliverFaces.begin(), sliverFaces.end(), sortedFace(mesh.tets[i], skip));
        open += uses[at - sliverFaces.begin()] == 1;
      }
      if (open >= 2) verdict[i] = kOutside, changed = true;
    }
  }
}

}  // namespace

bool isCoplanarTet(const std::array<Vec3, 4>& p) {
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      shortest = std::min(shortest, (p[b] - p[a]).norm()), longest = std::max(longest, (p[b] - p[a]).norm());
  const double sixVolume = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
  return sixVolume <= kCoplanar * shortest * longest * longest;
}

TetMesh delaunayTets(const std::vector<SurfaceNode>& nodes) {
  if (nodes.size() < 4)
    throw geometryError("too few surface nodes (" + std::to_string(nodes.size()) + ") to build tets");
  TetMesh mesh;
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(nodes.size());
  in.pointlist = new REAL[3 * nodes.size()];  // freed by tetgenio's destructor
  // Bubbles packed alike on a flat top and bottom face sit in mirrored pairs, and many nodes are
  // cospherical: TetGen's tie-breaking then joined nodes across a hole (the Ender-3 motor bracket
  // lost 4 of its 10 holes). TetGen gets the nodes moved by a tiny fixed jitter, which decides
  // every tie; the tets keep the exact nodes.
  for (const SurfaceNode& n : nodes) mesh.nodes.push_back(n.point), mesh.side.push_back(n.side);
  const double shift = kJitter * boxDiagonal(mesh.nodes);
  for (size_t i = 0; i < nodes.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = nodes[i].point[k] + shift * jitter(i, k);
  char switches[] = "zQ";  // z: zero-based indices, Q: quiet; no 'p': Delaunay of the point set
  try {
    tetrahedralize(switches, &in, &out);
  } catch (int code) {
    throw geometryError("TetGen failed to tetrahedralize the surface nodes (TetGen error " + std::to_string(code) +
                        ")");
  }
  mesh.tets.resize(out.numberoftetrahedra);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
    for (int k = 0; k < 4; ++k) mesh.tets[t][k] = out.tetrahedronlist[4 * t + k];
  return mesh;
}

TetFilterCounts keepSpanningTetsInside(TetMesh& mesh, const CadSolid& cad) {
  return keepSpanningTetsInside(mesh, cad, BoundaryTriangles(cad));
}

TetFilterCounts keepSpanningTetsInside(TetMesh& mesh, const CadSolid& cad, const BoundaryTriangles& triangles) {
  std::vector<char> verdict(mesh.tets.size());
  ParallelErrors errors;
#pragma omp parallel
  {
    std::optional<RayCaster> rays;
    std::optional<BRepClass3d_SolidClassifier> exact;
#pragma omp for schedule(dynamic, 256)  // flat tets cost nothing, those near the boundary most
    for (long i = 0; i < static_cast<long>(mesh.tets.size()); ++i)
      errors.run([&] {
        const auto& t = mesh.tets[i];
        int top = 0;
        for (int v : t) top += mesh.side[v] == Side::Top;
        const Vec3 c = 0.25 * (mesh.nodes[t[0]] + mesh.nodes[t[1]] + mesh.nodes[t[2]] + mesh.nodes[t[3]]);
        if (top == 0 || top == 4)
          verdict[i] = kFlat;
        else if (!insideSolid(c, triangles, cad, rays, exact))
          verdict[i] = kOutside;
        else
          verdict[i] = isCoplanar(mesh, t) ? kKeptCoplanar : kKept;
      });
  }
  errors.rethrow();
  TetFilterCounts counts;
  counts.delaunay = mesh.tets.size();
  counts.flat = std::count(verdict.begin(), verdict.end(), kFlat);
  std::optional<BRepExtrema_DistShapeShape> boundary;
  for (std::size_t i = 0; i < mesh.tets.size(); ++i)
    if (verdict[i] == kKeptCoplanar && onTheRim(mesh, mesh.tets[i], cad, boundary, triangles)) verdict[i] = kOutside;
  peelHullSlivers(mesh, verdict);
  counts.coplanar = std::count(verdict.begin(), verdict.end(), kKeptCoplanar);
  counts.outside = std::count(verdict.begin(), verdict.end(), kOutside);
  std::vector<std::array<int, 4>> kept;
  for (std::size_t i = 0; i < mesh.tets.size(); ++i)
    if (verdict[i] == kKept || verdict[i] == kKeptCoplanar) kept.push_back(mesh.tets[i]);
  mesh.tets.swap(kept);
  return counts;
}

}  // namespace hexlayer
