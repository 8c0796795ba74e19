#include "geometry/sheet_junctions.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/union_find.hpp"
#include "geometry/face_sampling.hpp"

namespace hexlayer {
namespace {

Vec3 faceCentre(const TopoDS_Shape& face, double area) {
  Vec3 c = Vec3::Zero();
  for (const FaceSample& s : sampleFace(face, std::sqrt(std::max(area, 1e-30) / 16))) c += s.area * s.point;
  return c;
}

}  // namespace

std::string sheetPlace(const CadSolid& cad, const Sheet& s) {
  std::ostringstream out;
  const Vec3 c = s.centre / cad.unit;
  out << "(" << c.x() << ", " << c.y() << ", " << c.z() << ")";
  return out.str();
}

Sheet sheetOf(const CadSolid& cad, const WallSides& sides, const std::vector<int>& faces) {
  Sheet s;
  for (int f : faces) {
    s.faces.push_back(f);
    s.area += sides.faces[f].area;
    s.volume += 0.5 * sides.faces[f].area * sides.faces[f].thickness;
    s.centre += faceCentre(cad.faces(f + 1), sides.faces[f].area);
  }
  s.centre /= std::max(s.area, 1e-30);
  return s;
}

std::vector<Sheet> findSheets(const CadSolid& cad, const WallSides& sides) {
  const int n = static_cast<int>(sides.faces.size());
  auto isWall = [&](int f) { return f >= 0 && sides.faces[f].side != Side::Lateral; };
  UnionFind uf(n);
  for (const SheetJoin& j : sides.sheetJoins)
    if (isWall(j.a) && isWall(j.b)) uf.unite(j.a, j.b);
  for (int f = 0; f < n; ++f)
    if (isWall(f) && isWall(sides.faces[f].opposite)) uf.unite(f, sides.faces[f].opposite);
  std::map<int, std::vector<int>> byRoot;
  for (int f = 0; f < n; ++f)
    if (isWall(f)) byRoot[uf.find(f)].push_back(f);
  std::vector<Sheet> sheets;
  for (const auto& [root, faces] : byRoot) sheets.push_back(sheetOf(cad, sides, faces));
  std::stable_sort(sheets.begin(), sheets.end(), [](const Sheet& a, const Sheet& b) { return a.area > b.area; });
  return sheets;
}

std::vector<int> wallSheetOfFaces(const std::vector<Sheet>& sheets, std::size_t faces) {
  std::vector<int> sheet(faces, -1);
  for (std::size_t s = 0; s < sheets.size(); ++s)
    for (int f : sheets[s].faces) sheet[f] = static_cast<int>(s);
  return sheet;
}

void keepFirstSheet(const std::vector<Sheet>& sheets, WallSides& sides) {
  for (std::size_t s = 1; s < sheets.size(); ++s)
    for (int f : sheets[s].faces) sides.faces[f].side = Side::Lateral;
}

}  // namespace hexlayer
