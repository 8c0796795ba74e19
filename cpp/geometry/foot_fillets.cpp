#include "geometry/foot_fillets.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Defeaturing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepTools.hxx>
#include <BRepTools_History.hxx>
#include <BRep_Tool.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <set>

#include "geometry/sheet_edges.hpp"

namespace hexlayer {
namespace {

constexpr double kPlanar = 1e-7;  // x the part's diagonal: a B-spline face this near a plane is one (a chamfer)

// The width of a chamfer face at a foot: a plane (also written as a B-spline) of the rim (no wall), whose edges
// with walls are all concave (a chamfer between a rib and the plate meets both in 135-degree concave edges; a rim
// face, or a chamfer on a rim's outside, meets its walls in convex edges); none for any other face.
// [in] cad, sides; [in] concavePairs: the faces (0-based, lower first) that meet in a concave edge; [in] f; [in] next:
// the faces next to f.
std::optional<double> chamferWidth(const CadSolid& cad, const WallSides& sides,
                                   const std::set<std::pair<int, int>>& concavePairs, int f,
                                   const std::set<int>& next) {
  if (sides.faces[f].side != Side::Lateral) return std::nullopt;
  const TopoDS_Face& face = TopoDS::Face(cad.faces(f + 1));
  if (BRepAdaptor_Surface(face).GetType() != GeomAbs_Plane &&
      !GeomLib_IsPlanarSurface(BRep_Tool::Surface(face), kPlanar * cad.diagonal).IsPlanar())
    return std::nullopt;
  bool walls = false;
  for (int g : next)
    if (sides.faces[g].side != Side::Lateral) {
      if (!concavePairs.count(std::minmax(f, g))) return std::nullopt;
      walls = true;
    }
  if (!walls) return std::nullopt;
  return sides.faces[f].width;
}

// Whether sheet s meets a wall of an earlier sheet in a concave edge (the edge of a foot). [in] sheetOf: per face,
// its sheet or -1.
bool standsOnEdges(const std::vector<FacePairEdge>& concave, const std::vector<int>& sheetOf, int s) {
  return std::any_of(concave.begin(), concave.end(), [&](const FacePairEdge& c) {
    const int a = sheetOf[c.a], b = sheetOf[c.b];
    return (a == s && b >= 0 && b < s) || (b == s && a >= 0 && a < s);
  });
}

// What the fillets are looked for in.
struct FilletSearch {
  const CadSolid& cad;
  std::vector<int> sheetOf;                   // per face, its sheet or -1
  std::vector<std::set<int>> next;            // faceNeighbours
  std::vector<std::optional<double>> radius;  // filletRadius per face
  double largest;                             // a fillet's radius is below it
};

// The fillets at sheet s's foot: concave fillet faces below the largest radius next to its faces, and next to
// those (a fillet split in pieces, the fillets round its ends mitred to those along its sides); none unless one of
// them belongs to or is next to a face of an earlier sheet. [in] f; [in] s. Returns them, 0-based.
std::set<int> filletsAtFoot(const FilletSearch& f, int s) {
  auto isFillet = [&](int g) { return f.sheetOf[g] != s && f.radius[g] && *f.radius[g] < f.largest; };
  std::set<int> found;
  std::vector<int> front;
  for (int w = 0; w < static_cast<int>(f.sheetOf.size()); ++w)
    if (f.sheetOf[w] == s)
      for (int g : f.next[w])
        if (isFillet(g) && found.insert(g).second) front.push_back(g);
  while (!front.empty()) {
    const int g = front.back();
    front.pop_back();
    for (int h : f.next[g])
      if (isFillet(h) && found.insert(h).second) front.push_back(h);
  }
  const bool onEarlier = std::any_of(found.begin(), found.end(), [&](int g) {
    auto earlier = [&](int h) { return f.sheetOf[h] >= 0 && f.sheetOf[h] < s; };
    return earlier(g) || std::any_of(f.next[g].begin(), f.next[g].end(), earlier);
  });
  return onEarlier ? found : std::set<int>{};
}

// The part without some of its faces, and those of its faces merged into a neighbour on the same surface first.
struct Defeatured {
  CadSolid smooth;          // its inputFace: the input's face each face is (of those merged, the first's)
  std::vector<int> merged;  // the part's faces (0-based) whose input face no face of smooth names
};

// The images of `face` in a history (itself if unchanged, none if removed). [in] history (may be null); [in] face.
std::vector<TopoDS_Shape> imagesIn(const Handle(BRepTools_History) & history, const TopoDS_Shape& face) {
  if (history.IsNull()) return {face};
  if (history->IsRemoved(face)) return {};
  const TopTools_ListOfShape& modified = history->Modified(face);
  if (modified.IsEmpty()) return {face};
  return std::vector<TopoDS_Shape>(modified.cbegin(), modified.cend());
}

// Smooth's inputFace set through the histories of the unifying (if any) and of the defeaturing: false if a face of
// smooth comes from none of the part's. [in] cad; [in] removed: the part's faces removed (0-based); [in] unified: the
// unifying's history, or null; [in] defeat; [in,out] out: smooth's inputFace set (the first of the part's faces a face
// comes from names it), the part's faces no longer named listed in merged.
bool traceFaces(const CadSolid& cad, const std::set<int>& removed, const Handle(BRepTools_History) & unified,
                BRepAlgoAPI_Defeaturing& defeat, Defeatured& out) {
  CadSolid& smooth = out.smooth;
  smooth.inputFace.assign(smooth.faces.Extent(), -1);
  for (int f = 1; f <= cad.faces.Extent(); ++f) {
    if (removed.count(f - 1)) continue;
    for (const TopoDS_Shape& face : imagesIn(unified, cad.faces(f))) {
      if (defeat.IsDeleted(face)) continue;
      const TopTools_ListOfShape& modified = defeat.Modified(face);
      std::vector<TopoDS_Shape> images(modified.cbegin(), modified.cend());
      if (images.empty()) images.push_back(face);
      for (const TopoDS_Shape& image : images)
        if (const int i = smooth.faces.FindIndex(image); i > 0 && smooth.inputFace[i - 1] < 0)
          smooth.inputFace[i - 1] = inputFaceOf(cad, f - 1);
    }
  }
  std::set<int> named(smooth.inputFace.begin(), smooth.inputFace.end());
  for (int f = 0; f < cad.faces.Extent(); ++f)
    if (!named.count(inputFaceOf(cad, f)) && !removed.count(f)) out.merged.push_back(f);
  return !named.count(-1);
}

// The part without `faces` (defeatured), the part's faces on one surface merged first if `unify`; none if OpenCASCADE
// cannot remove them, or leaves them where they were (it warns: then `warned`).
std::optional<Defeatured> defeatured(const CadSolid& cad, const std::set<int>& faces, bool unify, bool& warned) {
  try {
    TopoDS_Shape part = cad.solid;
    Handle(BRepTools_History) unified;
    if (unify) {
      ShapeUpgrade_UnifySameDomain same(cad.solid, false, true, false);
      same.Build();
      part = same.Shape(), unified = same.History();
    }
    BRepAlgoAPI_Defeaturing defeat;
    defeat.SetShape(part);
    for (int f : faces)
      for (const TopoDS_Shape& image : imagesIn(unified, cad.faces(f + 1))) defeat.AddFaceToRemove(image);
    defeat.SetRunParallel(false);
    defeat.Build();
    warned = defeat.IsDone() && defeat.HasWarnings();
    if (!defeat.IsDone() || warned) return std::nullopt;
    TopExp_Explorer solid(defeat.Shape(), TopAbs_SOLID);
    if (!solid.More() || !BRepCheck_Analyzer(solid.Current()).IsValid()) return std::nullopt;
    Defeatured out{prepareSolid(TopoDS::Solid(solid.Current())), {}};
    out.smooth.unit = cad.unit, out.smooth.cutInput = cad.cutInput;
    if (!traceFaces(cad, faces, unified, defeat, out)) return std::nullopt;
    return out;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

// The part without `faces` (defeatured), or none if OpenCASCADE cannot remove them. Where it leaves them (a fillet
// along a plate written in pieces: it warns and keeps the part as it is), the part's faces on one surface are merged
// first (ShapeUpgrade_UnifySameDomain) and the fillets removed from that.
std::optional<Defeatured> withoutFaces(const CadSolid& cad, const std::set<int>& faces) {
  bool warned = false;
  if (std::optional<Defeatured> smooth = defeatured(cad, faces, false, warned); smooth || !warned) return smooth;
  return defeatured(cad, faces, true, warned);
}

// Whether the walls fall into two sheets or more once the faces are taken for rims (nothing joins walls through
// them): else removing them (defeaturing and classifying the part again, a few tenths of a second on a real part)
// cannot part a boss from its plate. [in] cad, sides, faces.
bool sheetsApartWithout(const CadSolid& cad, WallSides sides, const std::set<int>& faces) {
  for (int f : faces) sides.faces[f].side = Side::Lateral;
  return findSheets(cad, sides).size() >= 2;
}

}  // namespace

std::optional<FootFillets> removeFootFillets(const CadSolid& cad, const WallSides& sides,
                                             const std::vector<Sheet>& sheets) {
  FilletSearch search{cad, wallSheetOfFaces(sheets, cad.faces.Extent()), faceNeighbours(cad), {}, sides.thickness};
  const std::vector<FacePairEdge> concave = concaveEdges(cad);
  std::set<std::pair<int, int>> concavePairs;
  for (const FacePairEdge& c : concave) concavePairs.insert(std::minmax(c.a, c.b));
  for (int f = 1; f <= cad.faces.Extent(); ++f) {  // a fillet's radius, or a chamfer's width
    std::optional<double> size = filletRadius(cad.faces(f));
    if (!size) size = chamferWidth(cad, sides, concavePairs, f - 1, search.next[f - 1]);
    search.radius.push_back(size);
  }
  std::set<int> fillets;
  for (int s = 1; s < static_cast<int>(sheets.size()); ++s)
    if (!standsOnEdges(concave, search.sheetOf, s)) fillets.merge(filletsAtFoot(search, s));
  if (fillets.empty()) return std::nullopt;
  std::optional<Defeatured> smooth = withoutFaces(cad, fillets);
  if (!smooth) return std::nullopt;
  FootFillets out{
      std::move(smooth->smooth), std::vector<int>(fillets.begin(), fillets.end()), 0, {}, std::move(smooth->merged)};
  for (int f : fillets) out.largestRadius = std::max(out.largestRadius, *search.radius[f]);
  out.sides = classifyWallSides(out.smooth);
  return out;
}

std::optional<FootFillets> removeRootFillets(const CadSolid& cad, const WallSides& sides) {
  std::vector<std::optional<double>> radius;
  for (int f = 1; f <= cad.faces.Extent(); ++f) {
    radius.push_back(filletRadius(cad.faces(f)));
    if (radius.back() && !(*radius.back() < sides.thickness)) radius.back().reset();
  }
  std::vector<std::set<int>> smoothly(radius.size());  // the faces each meets in a tangent edge
  for (const SheetJoin& j : sides.sheetJoins)
    if (j.smooth) smoothly[j.a].insert(j.b), smoothly[j.b].insert(j.a);
  std::vector<char> concave(radius.size(), 0);  // meets a face in a concave sharp edge (a bore at a plate's top)
  for (const FacePairEdge& c : concaveEdges(cad)) concave[c.a] = concave[c.b] = 1;
  std::set<int> fillets;  // rounding a corner between two faces it meets tangentially, no sharp concave edge
  double largest = 0;
  for (std::size_t f = 0; f < radius.size(); ++f) {
    if (!radius[f] || concave[f]) continue;
    const auto others = std::count_if(smoothly[f].begin(), smoothly[f].end(), [&](int g) { return !radius[g]; });
    if (others >= 2) fillets.insert(static_cast<int>(f)), largest = std::max(largest, *radius[f]);
  }
  if (fillets.empty() || !sheetsApartWithout(cad, sides, fillets)) return std::nullopt;
  std::optional<Defeatured> smooth = withoutFaces(cad, fillets);
  if (!smooth) return std::nullopt;
  WallSides smoothSides = classifyWallSides(smooth->smooth);
  if (!smoothSides.ownSideFaces.empty() || findSheets(smooth->smooth, smoothSides).size() < 2) return std::nullopt;
  return FootFillets{std::move(smooth->smooth), std::vector<int>(fillets.begin(), fillets.end()), largest,
                     std::move(smoothSides), std::move(smooth->merged)};
}

}  // namespace hexlayer
