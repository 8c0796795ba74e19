// Strips of quads halved lengthwise, rim to rim: the one way to change the parity of a quad mesh's boundary loops
// while it stays all quads and conformal (every quad's boundary has an even number of edges, so a region's boundary
// loops have an even number in all). Used where a loop must be even because another mesh fixes its nodes: the gap
// round a foot inside a sheet (footprint_insert), the rim on which a standing wall's foot lies (junction_mesh).
#pragma once
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "quadmesh/quad_mesh.hpp"

namespace hexlayer {

// A strip of quads: each quad with the corner k where its edge on the strip's way in starts (the edge from corner k
// to k + 1, crossed to the edge from k + 2 to k + 3).
using QuadStrip = std::vector<std::pair<int, int>>;

// Per undirected edge (lower node first), the quads that have it.
using QuadsOfEdges = std::map<std::pair<int, int>, std::vector<int>>;
// [in] quads. Returns their edges' quads, built once for every strip looked for in them.
QuadsOfEdges quadsOfEdges(const std::vector<std::array<int, 4>>& quads);

// The strip from the edge (a, b) across the quads to the rim (an edge of one quad only): into the one quad on (a, b)
// not `blocked` (at the rim, the one quad there). Empty if the strip meets a blocked quad or runs round in a ring.
// [in] quads; [in] on: quadsOfEdges(quads); [in] blocked: per quad (empty: none); [in] a, b: an edge.
QuadStrip stripToRim(const std::vector<std::array<int, 4>>& quads, const QuadsOfEdges& on,
                     const std::vector<char>& blocked, int a, int b);

// Halves the strip's quads lengthwise, each into two, from `first` (the node in the middle of its edge in): the
// midpoints of the edges it crosses appended to `nodes`, the second halves to `quads`. [in,out] quads, nodes;
// [in] strip; [in] first.
void halveStrip(std::vector<std::array<int, 4>>& quads, std::vector<Vec3>& nodes, const QuadStrip& strip, int first);

// Every rim loop of the quads whose nodes all satisfy `mustBeEven` and that has an odd number of edges made even: the
// shortest strip from one of its edges to a rim edge of another loop, one that need not be even (it becomes odd) or
// another odd one (both become even), halved; no strip runs through a `blocked` quad (another wall's footprint).
// [in,out] q; [in] mustBeEven; [in] blocked: per quad (may be shorter: the rest not). Returns the loops that stay odd
// (no such strip).
std::size_t evenRimLoops(QuadMesh& q, const std::function<bool(const Vec3&)>& mustBeEven, std::vector<char> blocked);

// A corner of a block grid (a rim node in one quad) on a smooth stretch of the outer rim: a corner of the square map
// put where the rim does not turn (a rounded or straight rim, no four sharp corners), its quad flattened towards
// 180 degrees there. Such a grid gets a ring of quads along its outer rim (pillowing): each outer rim node is copied,
// the copy stays on the rim, the node moves half way towards the mean of the corners of its quads off the rim, and a
// quad joins each rim edge to its copy. Every corner becomes an inner node of three quads (about 120 degrees each),
// every outer rim node lies in two. Pillowed only if a corner's quad is flatter than kFlatCorner there (one quad is
// nearer square below it than a third of the angle would be: 135 - 90 = 90 - 135 / 3). An acute corner (sharper than
// kKeptCorner, in one quad: a gusset's 45-degree tip, whose halves would be 22.5 degrees) keeps its quad: the ring
// runs round it, along its two inner edges (a square corner is split: 45-degree halves are better than the ring's
// quads round a kept one).
constexpr double kFlatCorner = 135 * M_PI / 180;
constexpr double kKeptCorner = 75 * M_PI / 180;
// [in,out] q: its outer rim (the longest rim loop) pillowed if a corner on it is flat. Returns whether it was.
bool pillowFlatCorners(QuadMesh& q);

}  // namespace hexlayer
