#include "geometry/bend_rounds.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "geometry/sheet_edges.hpp"

namespace hexlayer {
namespace {

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

// A rim face narrow enough to be a bend's outside round or chamfer.
bool narrowRim(const WallSides& w, const std::vector<bool>& wall, int f) {
  return !wall[f] && w.faces[f].width <= w.thickness;
}

// Whether wall faces a and b are the outsides of one bend: their rays cross the wall to two distinct faces that share
// a concave edge (the bend's sharp inside edge), neither of them a or b (a rim's round joins a top to its bottom).
bool outsidesOfOneBend(const std::vector<std::map<int, double>>& across, const std::set<std::pair<int, int>>& concave,
                       int a, int b) {
  for (const auto& [x, areaX] : across[a])
    for (const auto& [y, areaY] : across[b])
      if (x != y && x != a && x != b && y != a && y != b && concave.count(std::minmax(x, y))) return true;
  return false;
}

// Whether walls a and b face each other across the wall (a top and its bottom).
bool facing(const std::vector<std::map<int, double>>& across, int a, int b) {
  return across[a].count(b) > 0 || across[b].count(a) > 0;
}

// Whether a face joins two walls tangent to it that are the outsides of one bend (a round), and no wall to the wall
// facing it (a rim does: a rim face across the wall joins the outsides of two walls at a corner, but their insides
// too). [in] joined: the face's joins.
bool joinsBend(const std::vector<Joined>& joined, const std::vector<bool>& wall,
               const std::vector<std::map<int, double>>& across, const std::set<std::pair<int, int>>& concave) {
  bool bend = false;
  for (std::size_t i = 0; i < joined.size(); ++i)
    for (std::size_t k = i + 1; k < joined.size(); ++k) {
      const Joined &a = joined[i], &b = joined[k];
      if (!wall[a.face] || !wall[b.face]) continue;
      if (facing(across, a.face, b.face)) return false;
      bend = bend || (a.smooth && b.smooth && outsidesOfOneBend(across, concave, a.face, b.face));
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
  std::set<std::pair<int, int>> concave;
  bool candidates = false;
  for (int f = 0; f < n && !candidates; ++f) candidates = narrowRim(w, wall, f) && joined[f].size() >= 2;
  if (!candidates) return {};
  for (const ConcaveEdge& e : concaveEdges(cad)) concave.insert({e.a, e.b});
  for (int f = 0; f < n; ++f) round[f] = narrowRim(w, wall, f) && joinsBend(joined[f], wall, across, concave);
  for (bool grew = true; grew;) {  // corners: blends between bend rounds
    grew = false;
    for (int f = 0; f < n; ++f)
      if (!round[f] && narrowRim(w, wall, f) && joinsOnlyBends(joined[f], wall, round)) round[f] = grew = true;
  }
  std::vector<int> rounds;
  for (int f = 0; f < n; ++f)
    if (round[f]) rounds.push_back(f);
  return rounds;
}

}  // namespace hexlayer
