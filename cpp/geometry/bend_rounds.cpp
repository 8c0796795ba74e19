#include "geometry/bend_rounds.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "geometry/sheet_edges.hpp"

namespace hexlayer {
namespace {

constexpr double kMaxChamferWidth = 1.1 * 1.41421356;  // x the thicker wall: a 45-degree chamfer of it, and 10 %

// A face joined to another by a smooth (tangent) or convex edge.
struct Joined {
  int face;
  bool smooth;
};

// Per face, the faces it shares a smooth or convex edge with.
std::vector<std::vector<Joined>> joinedFaces(const WallSides& w) {
  std::vector<std::vector<Joined>> joined(w.faces.size());
  for (const SheetJoin& j : w.sheetJoins)
    joined[j.a].push_back({j.b, j.smooth}), joined[j.b].push_back({j.a, j.smooth});
  return joined;
}

// A rim face narrow enough to be a bend's outside round.
bool narrowRim(const WallSides& w, const std::vector<bool>& wall, int f) {
  return !wall[f] && w.faces[f].width <= w.thickness;
}

// A rim face narrow enough to be a bend's outside chamfer: at most as wide as a 45-degree chamfer taking the whole
// thickness of the thicker wall it joins off the corner (sqrt 2 x that wall, with a margin).
bool chamferWide(const WallSides& w, const std::vector<bool>& wall, const std::vector<Joined>& joined, int f) {
  double thickest = w.thickness;
  for (const Joined& j : joined)
    if (wall[j.face]) thickest = std::max(thickest, w.faces[j.face].thickness);
  return !wall[f] && w.faces[f].width <= kMaxChamferWidth * thickest;
}

// The inside of a bend: two faces sharing a concave edge (a sharp inside edge), or two faces each sharing a concave
// edge with a third, narrower than the wall (a small inside chamfer or round between them).
struct BendInside {
  const std::set<std::pair<int, int>>& concave;
  const std::vector<std::set<int>>& concaveNext;  // per face, the faces it shares a concave edge with
  const WallSides& w;

  // The inside faces x and y meet at (x, y and any narrow face between them; empty: they do not).
  std::vector<int> between(int x, int y) const {
    if (concave.count(std::minmax(x, y))) return {x, y};
    for (int z : concaveNext[x])
      if (z != y && concaveNext[y].count(z) && w.faces[z].width <= w.thickness) return {x, y, z};
    return {};
  }
};

// The inside faces of the bend whose outsides are wall faces a and b: every pair of distinct faces that their rays
// cross the wall to and that meet in the bend's inside (BendInside), none of them a or b (a rim's round joins a top to
// its bottom), with the narrow faces between. Empty: a and b are not the outsides of one bend.
std::set<int> insideOfOneBend(const std::vector<std::map<int, double>>& across, const BendInside& inside, int a,
                              int b) {
  std::set<int> faces;
  for (const auto& [x, areaX] : across[a])
    for (const auto& [y, areaY] : across[b])
      if (x != y && x != a && x != b && y != a && y != b)
        for (int f : inside.between(x, y)) faces.insert(f);
  return faces;
}

// Whether walls a and b face each other across the wall (a top and its bottom).
bool facing(const std::vector<std::map<int, double>>& across, int a, int b) {
  return across[a].count(b) > 0 || across[b].count(a) > 0;
}

// Whether most of face f's inward rays land on the given faces.
bool raysLandOn(const FaceSide& f, const std::set<int>& faces) {
  double on = 0, all = 0;
  for (const RayMark& m : f.marks) {
    all += m.area;
    if (faces.count(m.hitFace)) on += m.area;
  }
  return on > 0.5 * all;
}

// Whether face f joins two walls that are the outsides of one bend, and no wall to the wall facing it (a rim does: a
// rim face across the wall joins the outsides of two walls at a corner, but their insides too): tangent to both (a
// round), or, a chamfer, meeting both in convex sharp edges with its own rays landing on the bend's inside (a rim cut
// across a corner, as a channel's end face, looks along the bend instead). [in] joined: the face's joins.
bool joinsBend(const WallSides& w, int f, const std::vector<Joined>& joined, const std::vector<bool>& wall,
               const std::vector<std::map<int, double>>& across, const BendInside& inside) {
  const bool round = narrowRim(w, wall, f), chamfer = chamferWide(w, wall, joined, f);
  bool bend = false;
  for (std::size_t i = 0; i < joined.size(); ++i)
    for (std::size_t k = i + 1; k < joined.size(); ++k) {
      const Joined &a = joined[i], &b = joined[k];
      if (!wall[a.face] || !wall[b.face]) continue;
      if (facing(across, a.face, b.face)) return false;
      if (bend || a.smooth != b.smooth || !(a.smooth ? round : chamfer)) continue;
      const std::set<int> in = insideOfOneBend(across, inside, a.face, b.face);
      bend = !in.empty() && (a.smooth || raysLandOn(w.faces[f], in));
    }
  return bend;
}

// Whether a face is joined only to walls and bend rounds, tangent to at least two bend rounds (a corner's blend).
bool joinsOnlyBends(const std::vector<Joined>& joined, const std::vector<bool>& wall, const std::vector<bool>& round) {
  int rounds = 0;
  for (const Joined& j : joined) {
    if (!wall[j.face] && !round[j.face]) return false;
    rounds += round[j.face] && j.smooth ? 1 : 0;
  }
  return rounds >= 2;
}

}  // namespace

std::vector<int> findBendRounds(const CadSolid& cad, const WallSides& w,
                                const std::vector<std::map<int, double>>& across) {
  const int n = static_cast<int>(w.faces.size());
  std::vector<bool> wall(n), round(n, false);
  for (int f = 0; f < n; ++f) wall[f] = w.faces[f].side != Side::Lateral;
  const std::vector<std::vector<Joined>> joined = joinedFaces(w);
  auto candidate = [&](int f) { return narrowRim(w, wall, f) || chamferWide(w, wall, joined[f], f); };
  bool candidates = false;
  for (int f = 0; f < n && !candidates; ++f) candidates = candidate(f) && joined[f].size() >= 2;
  if (!candidates) return {};
  std::set<std::pair<int, int>> concave;
  std::vector<std::set<int>> concaveNext(n);
  for (const FacePairEdge& e : concaveEdges(cad))
    concave.insert({e.a, e.b}), concaveNext[e.a].insert(e.b), concaveNext[e.b].insert(e.a);
  const BendInside inside{concave, concaveNext, w};
  for (int f = 0; f < n; ++f) round[f] = candidate(f) && joinsBend(w, f, joined[f], wall, across, inside);
  for (bool grew = true; grew;) {  // corners: blends between bend rounds or chamfers
    grew = false;
    for (int f = 0; f < n; ++f)
      if (!round[f] && candidate(f) && joinsOnlyBends(joined[f], wall, round)) round[f] = grew = true;
  }
  std::vector<int> rounds;
  for (int f = 0; f < n; ++f)
    if (round[f]) rounds.push_back(f);
  return rounds;
}

}  // namespace hexlayer
