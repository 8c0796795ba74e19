#include "geometry/wall_sides.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "core/error.hpp"
#include "geometry/face_sampling.hpp"

namespace hexlayer {
namespace {

constexpr int kRaysPerFace = 150;

struct Ray {
  double length;
  int hitFace;
  double weight;
};

double weightedMedian(std::vector<Ray> rays) {
  if (rays.empty()) return 0;
  std::sort(rays.begin(), rays.end(), [](const Ray& a, const Ray& b) { return a.length < b.length; });
  const double total = std::accumulate(rays.begin(), rays.end(), 0.0, [](double s, const Ray& r) { return s + r.weight; });
  double acc = 0;
  for (const Ray& r : rays)
    if ((acc += r.weight) >= 0.5 * total) return r.length;
  return rays.back().length;
}

double perimeter(const TopoDS_Shape& face) {
  double p = 0;  // a seam edge is met twice, as the face's boundary runs along it twice
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    BRepAdaptor_Curve curve(TopoDS::Edge(it.Current()));
    p += GCPnts_AbscissaPoint::Length(curve);
  }
  return p;
}

// Casts rays from the face's samples inward and records how far the opposite wall is.
std::vector<Ray> castInwardRays(const CadSolid& cad, IntCurvesFace_ShapeIntersector& rays, int f, Vec3& meanNormal) {
  const TopoDS_Shape& face = cad.faces(f + 1);
  const double spacing = std::sqrt(std::max(triangulatedArea(face), 1e-30) / kRaysPerFace);
  const double skip = 1e-5 * cad.diagonal;
  std::vector<Ray> out;
  meanNormal = Vec3::Zero();
  for (const FaceSample& s : sampleFace(face, spacing)) {
    meanNormal += s.area * s.normal;
    const gp_Lin line(gp_Pnt(s.point.x(), s.point.y(), s.point.z()), gp_Dir(-s.normal.x(), -s.normal.y(), -s.normal.z()));
    rays.PerformNearest(line, skip, 2 * cad.diagonal);
    if (!rays.IsDone() || rays.NbPnt() == 0) continue;
    out.push_back({rays.WParameter(1), cad.faces.FindIndex(rays.Face(1)) - 1, s.area});
  }
  return out;
}

int dominantHit(const std::vector<Ray>& rays) {
  std::map<int, double> weight;
  for (const Ray& r : rays) weight[r.hitFace] += r.weight;
  int best = -1;
  double bestWeight = 0;
  for (const auto& [face, w] : weight)
    if (w > bestWeight) best = face, bestWeight = w;
  return best;
}

// Union-find whose links carry a parity: 0 = same side, 1 = opposite sides.
struct ParityUnionFind {
  std::vector<int> parent, parity;
  explicit ParityUnionFind(int n) : parent(n), parity(n, 0) { std::iota(parent.begin(), parent.end(), 0); }
  std::pair<int, int> find(int a) {
    int p = 0;
    while (parent[a] != a) p ^= parity[a], a = parent[a];
    return {a, p};
  }
  // Returns false when the constraint contradicts the ones before.
  bool unite(int a, int b, int relation) {
    auto [ra, pa] = find(a);
    auto [rb, pb] = find(b);
    if (ra == rb) return (pa ^ pb) == relation;
    parent[std::max(ra, rb)] = std::min(ra, rb);
    parity[std::max(ra, rb)] = pa ^ pb ^ relation;
    return true;
  }
};

std::string faceName(int f) { return "Face" + std::to_string(f + 1); }

void requireThin(const WallSides& w, const CadSolid& cad) {
  std::ostringstream msg;
  if (w.thickness <= 0) {
    msg << "not a thin section: no face has an opposite wall closer than its own width";
    throw geometryError(msg.str());
  }
  const double slenderness = w.thickness / cad.diagonal;
  if (w.sheetAreaShare < 0.5 || slenderness > 0.25) {
    msg << "not a thin section: wall thickness " << w.thickness << " over part size " << cad.diagonal
        << " = " << slenderness << " (at most 0.25), top+bottom area share " << w.sheetAreaShare
        << " (at least 0.5)";
    throw geometryError(msg.str());
  }
}

// Same side across shared edges, opposite sides across the wall; returns (group, parity) per face.
std::vector<std::pair<int, int>> solveSides(const CadSolid& cad, const WallSides& w) {
  const int n = static_cast<int>(w.faces.size());
  ParityUnionFind uf(n);
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(cad.solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  auto isWall = [&](int f) { return w.faces[f].side != Side::Lateral; };
  for (int e = 1; e <= edgeFaces.Extent(); ++e) {
    std::vector<int> wallFaces;
    for (const TopoDS_Shape& f : edgeFaces(e))
      if (int i = cad.faces.FindIndex(f) - 1; isWall(i)) wallFaces.push_back(i);
    for (size_t k = 1; k < wallFaces.size(); ++k)
      if (!uf.unite(wallFaces[0], wallFaces[k], 0))
        throw geometryError("top and bottom cannot be told apart: " + faceName(wallFaces[0]) + " and " +
                            faceName(wallFaces[k]) + " share an edge but lie on opposite sides of the wall");
  }
  for (int f = 0; f < n; ++f)
    if (isWall(f) && w.faces[f].opposite >= 0 && isWall(w.faces[f].opposite))
      uf.unite(f, w.faces[f].opposite, 1);  // a contradicting stray ray is outvoted by the edges
  std::vector<std::pair<int, int>> rootParity(n);
  for (int f = 0; f < n; ++f) rootParity[f] = uf.find(f);
  return rootParity;
}

}  // namespace

WallSides classifyWallSides(const CadSolid& cad) {
  const int n = cad.faces.Extent();
  WallSides w;
  w.faces.resize(n);
  IntCurvesFace_ShapeIntersector rays;
  rays.Load(cad.solid, 1e-7 * cad.diagonal);
  std::vector<Vec3> meanNormal(n);
  double totalArea = 0;
  for (int f = 0; f < n; ++f) {
    FaceSide& fs = w.faces[f];
    const std::vector<Ray> hits = castInwardRays(cad, rays, f, meanNormal[f]);
    fs.area = triangulatedArea(cad.faces(f + 1));
    fs.width = 2 * fs.area / std::max(perimeter(cad.faces(f + 1)), 1e-30);
    fs.thickness = weightedMedian(hits);
    fs.opposite = dominantHit(hits);
    fs.side = (!hits.empty() && fs.thickness < fs.width) ? Side::Top : Side::Lateral;  // Top = "wall" for now
    totalArea += fs.area;
  }
  std::vector<Ray> wallThickness;
  double wallArea = 0;
  for (const FaceSide& fs : w.faces)
    if (fs.side != Side::Lateral) wallThickness.push_back({fs.thickness, 0, fs.area}), wallArea += fs.area;
  w.thickness = weightedMedian(wallThickness);
  w.sheetAreaShare = wallArea / std::max(totalArea, 1e-30);
  requireThin(w, cad);

  const std::vector<std::pair<int, int>> rootParity = solveSides(cad, w);
  // In each group of connected wall faces, the parity class that faces +z more is Top.
  std::map<int, double> up;
  for (int f = 0; f < n; ++f)
    if (w.faces[f].side != Side::Lateral)
      up[rootParity[f].first] += (rootParity[f].second == 0 ? 1 : -1) * meanNormal[f].z();
  for (int f = 0; f < n; ++f)
    if (w.faces[f].side != Side::Lateral)
      w.faces[f].side = ((rootParity[f].second == 0) == (up[rootParity[f].first] >= 0)) ? Side::Top : Side::Bottom;
  return w;
}

}  // namespace hexlayer
