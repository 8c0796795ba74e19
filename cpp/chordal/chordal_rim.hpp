// The rim of the chordal surface (beyond the paper). §5 cuts the top-bottom tet edges at their midpoints; at a
// rim, an edge joins the last top node and the last bottom node, which along a straight rim stand one above
// the other, but round a concave rim (a hole, and more so one whose edges are rounded or chamfered) they may be
// far apart round it, so the edge's midpoint falls into the rim's profile: the chordal rim zigzags into the
// hole, the quad mesh cannot lay a ring of rows round it, and the sweep folds. Here each rim vertex is put
// midway between the nearest points of the two walls' rim edges (the edges where the top and the bottom wall
// meet the lateral faces): on a rim normal to the walls that is its middle line, on a round rim the axis of
// its round, on an oblique cut the middle of the cut.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>

#include "chordal/chordal_surface.hpp"
#include "core/types.hpp"

namespace hexlayer {

// The point midway between the top and the bottom wall's rim edges nearest to p (on the lateral face nearest
// to p where it meets both walls), if any. Called from every thread at once (each vertex is asked on its own).
using RimMiddle = std::function<std::optional<Vec3>(const Vec3& p)>;

struct RimSnapStats {
  std::size_t rimVertices = 0;    // vertices on the chordal surface's rim
  std::size_t moved = 0;          // of those, put midway between the walls' rim edges
  std::size_t spikesDropped = 0;  // facets on the rim that the move would turn over, ending a narrow spike, or of an
                                  // island that only they held to the rest (dropIslands)
  double largestMove = 0;         // in the surface's units
  std::size_t tearsFilled = 0;    // rim loops filled as tears (fillTears), before the snap
};

// Whether a point lies near the lateral faces ω_l (the part's rims, holes' walls included).
using NearRim = std::function<bool(const Vec3& p)>;

// Whether a point lies inside the part's material (not within its boundary's tolerance of a face).
using InMaterial = std::function<bool(const Vec3& p)>;

// Fills the tears of the chordal surface: rim loops no longer than maxLength fewer than half of whose vertices are near
// a lateral face. A hole or rim of the part runs along its lateral faces; a small loop in a wall is where tets spanning
// a sharp inside corner were dropped as outside (their centre in the corner's empty side), and the quads would carry it
// into the mesh as a hole the part does not have (on a wall lower than a few thicknesses some of its vertices are
// near the wall's rim: the spike drops then opened it into a notch). A loop with half its vertices or more near a
// lateral face is a tear too where it is a hole of the surface (walked the facets' way, it turns against their
// normal) round material: its middle, and the points halfway from it to each vertex, inside the part (a facet or two
// missing under a lip's rim, 1 to 2 walls above its step: a hole's middle is air). A loop longer than maxLength, up to
// 3 times it, is a tear only where it is such a hole round material (a lip half as thick as the wall it stands on has
// bubbles twice as dense on its own face as on the face it shares with the wall: a few facets missing over its step, a
// loop several walls long). Each is closed by a fan of triangles from the first of its vertices from which no triangle
// repeats an edge the surface has (a loop passing both ends of one), turned as its neighbours; a loop with none stays.
// [in,out] chordal: before its normals and radius are computed; [in] nearRim, inMaterial, maxLength. Returns the number
// of loops filled.
std::size_t fillTears(ChordalSurface& chordal, const NearRim& nearRim, const InMaterial& inMaterial, double maxLength);

// [in,out] chordal: its rim vertices moved (normals and radius are computed afterwards);
// [in] middle: the point between the walls' rim edges; [in] reach: the longest move (about the wall thickness).
// A vertex stays where it is if the midpoint is farther than `reach`, or if moving it would turn a facet
// around it over (its normal against the one it had) or shrink it below a tenth of its area; but a facet
// that ends a spike of the rim (its tip in that facet only: a tet cut reaching into a rounded rim's profile)
// and that the move would turn over is dropped, and the rim measured again. Then the facets that end a narrow
// spike of the rim (its tip in that facet only, the rim turning back there by more than 165 degrees) go.
RimSnapStats snapRimBetweenWallEdges(ChordalSurface& chordal, const RimMiddle& middle, double reach);

}  // namespace hexlayer
