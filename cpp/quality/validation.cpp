#include "quality/validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/box_tree.hpp"

namespace hexlayer {
namespace {

// Relative to the mesh's extent: nodes this close are one node written twice.
constexpr double kCoincidentTolerance = 1e-7;

std::string where(const Vec3& p) {
  std::ostringstream s;
  s << std::setprecision(6) << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

ValidationFailure failure(const std::string& check, std::size_t count, const Vec3& at, const std::string& what) {
  std::ostringstream s;
  s << check << ": " << count << " " << what << " at " << where(at);
  return {check, count, at, s.str()};
}

// A hex whose 8 corners are not 8 distinct nodes of the mesh.
bool degenerate(std::array<int, 8> hex, std::size_t nodes) {
  std::sort(hex.begin(), hex.end());
  return std::adjacent_find(hex.begin(), hex.end()) != hex.end() || hex.front() < 0 ||
         static_cast<std::size_t>(hex.back()) >= nodes;
}

std::optional<ValidationFailure> checkHexes(const HexMesh& mesh) {
  std::size_t bad = 0, first = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    if (degenerate(mesh.hexes[h], mesh.nodes.size()) && bad++ == 0) first = h;
  if (bad == 0) return std::nullopt;
  Vec3 at = Vec3::Zero();
  for (int v : mesh.hexes[first])
    if (v >= 0 && static_cast<std::size_t>(v) < mesh.nodes.size()) at += mesh.nodes[v] / 8;
  return failure("hexes", bad, at, "elements without 8 distinct corner nodes, the first");
}

std::optional<ValidationFailure> checkConformal(const HexMesh& mesh) {
  if (mesh.nodes.empty()) return std::nullopt;
  const CoincidentNodes c = findCoincidentNodes(mesh, kCoincidentTolerance * boxDiagonal(mesh.nodes));
  if (c.pairs == 0) return std::nullopt;
  return failure("conformal", c.pairs, mesh.nodes[c.firstNode],
                 "pairs of duplicate nodes (the hexes there are not joined), the first");
}

std::optional<ValidationFailure> checkWatertight(const HexMesh& mesh, const BoundaryCheck& b) {
  const std::size_t bad = b.openEdges + b.nonManifoldEdges + b.inconsistentlyOrientedEdges;
  if (bad == 0) return std::nullopt;
  std::ostringstream what;
  what << "boundary edges not shared by exactly two boundary faces in opposite directions (" << b.openEdges << " open, "
       << b.nonManifoldEdges << " non-manifold, " << b.inconsistentlyOrientedEdges << " flipped), the first";
  const Vec3 at = 0.5 * (mesh.nodes[b.firstBadEdge[0]] + mesh.nodes[b.firstBadEdge[1]]);
  return failure("watertight", bad, at, what.str());
}

std::optional<ValidationFailure> checkVolume(const QualityReport& q, double cadVolume) {
  const double error = (q.volume - cadVolume) / cadVolume;
  if (std::abs(error) <= kMaxVolumeError) return std::nullopt;
  std::ostringstream s;
  s << std::setprecision(6) << "volume: the mesh's " << q.volume << " differs from the CAD's " << cadVolume << " by "
    << std::showpos << 100 * error << std::noshowpos << " % (at most " << 100 * kMaxVolumeError << " %)";
  return ValidationFailure{"volume", 1, std::nullopt, s.str()};
}

// A boundary face lies on another when the other's plane is this near its middle, relative to its size (the lesser of
// the square root of its area and its hex's depth across it, so that the two walls of one thin layer of wide hexes
// are not taken for one face): two pieces' faces on one cut face, apart by the sagitta of their chords at most where
// it is curved.
constexpr double kFaceOnFace = 0.05;

// A boundary face, its middle, unit outward normal and size (as kFaceOnFace measures it).
struct FacePlane {
  Vec3 middle, normal;
  double size;
};

// The middle of local face `face` of hex h.
Vec3 faceMiddle(const HexMesh& mesh, int h, int face) {
  Vec3 middle = Vec3::Zero();
  for (int c : kHexFaces[face]) middle += mesh.nodes[mesh.hexes[h][c]] / 4;
  return middle;
}

FacePlane facePlane(const HexMesh& mesh, const BoundaryFace& f) {
  const auto& p = mesh.nodes;
  const Vec3 cross = (p[f.nodes[2]] - p[f.nodes[0]]).cross(p[f.nodes[3]] - p[f.nodes[1]]);
  const double area = 0.5 * cross.norm();
  const Vec3 middle = faceMiddle(mesh, f.hex, f.localFace);
  const int across = f.localFace < 2 ? 1 - f.localFace : 2 + f.localFace % 4;  // kHexFaces' pairs: 0-1, 2-4, 3-5
  const double depth = (faceMiddle(mesh, f.hex, across) - middle).norm();
  return {middle, area > 0 ? Vec3(cross.normalized()) : Vec3::Zero(), std::min(std::sqrt(area), depth)};
}

// Whether q, in the plane of the triangle a b c, lies in it (barycentric coordinates above -1e-6).
bool inTriangle(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double twice = n.squaredNorm();
  if (twice <= 0) return false;
  const double u = (c - b).cross(q - b).dot(n) / twice, v = (a - c).cross(q - c).dot(n) / twice;
  return u >= -1e-6 && v >= -1e-6 && 1 - u - v >= -1e-6;
}

// Whether face f's middle lies on face g (within kFaceOnFace of its size from the plane of one of g's four triangles,
// inside it), that triangle facing it (their normals opposite), not at the same four places (nodes written twice:
// checkConformal's). Each triangle of both diagonals: a face folded along one (a wall's quad with two opposite
// corners put on a sharp edge, half of it on either face) faces the face lying on its half along neither's mean plane.
bool liesOn(const HexMesh& mesh, const BoundaryFace& f, const FacePlane& pf, const BoundaryFace& g) {
  const auto& p = mesh.nodes;
  const double same = kCoincidentTolerance * pf.size;
  if (std::all_of(f.nodes.begin(), f.nodes.end(), [&](int a) {
        return std::any_of(g.nodes.begin(), g.nodes.end(), [&](int b) { return (p[a] - p[b]).norm() < same; });
      }))
    return false;
  constexpr std::array<std::array<int, 3>, 4> kTriangles{{{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}}};
  return std::any_of(kTriangles.begin(), kTriangles.end(), [&](const std::array<int, 3>& t) {
    const Vec3 &a = p[g.nodes[t[0]]], &b = p[g.nodes[t[1]]], &c = p[g.nodes[t[2]]];
    const Vec3 cross = (b - a).cross(c - a);
    if (cross.norm() <= 0) return false;
    const Vec3 normal = cross.normalized();
    if (pf.normal.dot(normal) > -0.9) return false;
    const double height = (pf.middle - a).dot(normal);
    return std::abs(height) <= kFaceOnFace * pf.size && inTriangle(pf.middle - height * normal, a, b, c);
  });
}

// Boundary faces lying face to face on other boundary faces: two pieces side by side inside the part, not joined
// (no node in common, so the checks of conformity and of the boundary's edges and Euler characteristic pass them).
std::optional<ValidationFailure> checkJoined(const HexMesh& mesh) {
  const std::vector<BoundaryFace> faces = boundaryFaces(mesh);
  std::vector<FacePlane> planes;
  std::vector<Box> boxes(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    planes.push_back(facePlane(mesh, faces[f]));
    for (int n : faces[f].nodes) boxes[f].add(mesh.nodes[n]);
    const Vec3 reach = Vec3::Constant(kFaceOnFace * planes[f].size);
    boxes[f].lo -= reach, boxes[f].hi += reach;
  }
  const BoxTree tree(boxes);
  std::size_t lying = 0, first = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    bool on = false;
    tree.traverse([&](const Box& b) { return squaredDistanceToBox(planes[f].middle, b) <= 0; },
                  [&](int g) {
                    on = g != static_cast<int>(f) && liesOn(mesh, faces[f], planes[f], faces[g]);
                    return on;
                  });
    if (on && lying++ == 0) first = f;
  }
  if (lying == 0) return std::nullopt;
  return failure("joined", lying, planes[first].middle,
                 "boundary faces lying face to face on others inside the part (pieces not joined there), the first");
}

// Only on a watertight boundary: an open one's Euler characteristic says nothing of its holes.
std::optional<ValidationFailure> checkTopology(const BoundaryCheck& b, std::optional<long> cadEuler) {
  const long apart = cadEuler ? *cadEuler - b.eulerCharacteristic : 0;  // chi = 2 - 2 genus per closed shell
  if (apart <= 0 || !b.watertight()) return std::nullopt;
  const std::size_t holes = static_cast<std::size_t>((apart + 1) / 2);
  std::ostringstream s;
  s << "topology: the mesh has " << holes << " hole(s) the part does not have (its boundary's Euler characteristic "
    << b.eulerCharacteristic << ", the part's " << *cadEuler << ")";
  return ValidationFailure{"topology", holes, std::nullopt, s.str()};
}

}  // namespace

std::vector<ValidationFailure> validateMesh(const HexMesh& mesh, const QualityReport& q, const BoundaryCheck& b,
                                            double cadVolume, std::optional<long> cadEuler) {
  std::vector<ValidationFailure> failures;
  if (mesh.hexes.empty()) return {{"hexes", 0, std::nullopt, "hexes: the mesh has no hex"}};
  for (auto f : {checkHexes(mesh),
                 q.inverted == 0 ? std::nullopt
                                 : std::optional(failure("inverted", q.inverted, q.worstAt,
                                                         "inverted hexes (scaled Jacobian <= 0), the worst")),
                 checkConformal(mesh), checkJoined(mesh), checkWatertight(mesh, b), checkVolume(q, cadVolume),
                 checkTopology(b, cadEuler)})
    if (f) failures.push_back(*f);
  return failures;
}

}  // namespace hexlayer
