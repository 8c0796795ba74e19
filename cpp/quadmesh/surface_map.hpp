// A map of the chordal surface onto the plane, for the structured block grids (block_grids.hpp):
// Gmsh 4.8 meshes a patch that is not bounded by four curves unstructured (its Frontal-Delaunay
// for quads crashes), with irregular nodes and sheared regions. In the plane, a disc or a
// rectangle with holes can be covered by a few structured blocks instead.
#pragma once
#include <array>
#include <vector>

#include "chordal/chordal_surface.hpp"
#include "core/box_grid.hpp"
#include "core/types.hpp"

namespace hexlayer {

// What the outer rim is mapped onto: the square [-1, 1]^2 or the unit circle. Its four corners go
// to 45, 135, 225 and 315 degrees (the square's corners), the rim between them by arc length.
// Annulus: a surface with two rims (a tube, a ring) is cut open from rim to rim and mapped conformally onto
// the rectangle [0, 2 pi] x [log(inner radius), 0] of the logarithmic polar plane: the height between the rims
// harmonic, the angle its harmonic conjugate (free on both rims, 2 pi more on one side of the cut than on the
// other), so a flat ring gets its log-polar map.
enum class MapBoundary { Circle, Square, Annulus };

// The chordal surface with each hole filled by a fan of triangles around one added point (its
// rim's centroid), mapped by Floater's mean value weights: each point inside is the weighted mean
// of its neighbours, which embeds the surface in the plane without folds (the rim is convex).
struct SurfaceMap {
  std::vector<Vec3> points;                   // the chordal vertices, then one centre per hole
  std::vector<std::array<int, 3>> triangles;  // the chordal facets (quads split on a diagonal), then the fans
  std::vector<Eigen::Vector2d> uv;            // per point
  // Rim loops as points, each counter-clockwise in the plane.
  std::vector<int> rim;                 // the outer rim (the longest loop), starting at corner 0
  std::array<int, 4> corners{};         // positions in rim of the four corners, ascending
  std::vector<std::vector<int>> holes;  // the other rim loops
  MapBoundary boundary = MapBoundary::Circle;
  bool sharpCorners = false;  // the four corners are the rim's sharpest, all sharp
  int sideMiddle = -1;        // a triangle (a rim with three sharp corners): the corner that halves its longest side
  double innerRadius = 0;     // Annulus: the rectangle runs from log(innerRadius) to 0
  bool empty() const { return triangles.empty(); }
};

// Empty unless the chordal surface is a sphere with holes (connected, V - E + F = 2 - loops, rims
// that do not touch); for the Annulus, unless it has exactly two rims. The annulus's inner radius is
// exp(-M), M its conformal modulus: 2 pi over the Dirichlet energy of the height (a tube's is about 2 pi H / C,
// H the distance between the rims and C their length); the cut is the shortest path between two points of the
// rims facing each other. The rectangle is
// convex, so the mean value map has no fold, and a grid evenly spaced in it has near-square quads. The four corners are
// the rim's four sharpest (turning more than 50 degrees in the surface), or if it has fewer, its points farthest out
// along the diagonals of its principal axes; the rim's turning is measured over `window` (about a quad) on either side.
SurfaceMap mapToPlane(const ChordalSurface& chordal, double window, MapBoundary boundary);

// A patch of triangles mapped onto the square as mapToPlane maps the chordal surface, its rim and corners given (a
// face of the patch grid, whose sides are the creases and rim curves round it). [in] points; [in] triangles: a disc
// with holes, any orientation; [in] rim: the outer rim's points in order round it, from corner 0; [in] corners: the
// positions in rim of the four corners, ascending from 0; [in] holes: the holes' rim loops, either way round.
// Returns the map (corners[k] at the square's corner k, the holes filled and walked counter-clockwise in the
// plane); empty if the corners are not four ascending positions or the solve fails.
SurfaceMap mapOntoSquare(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles, std::vector<int> rim,
                         const std::array<int, 4>& corners, const std::vector<std::vector<int>>& holes);

// A loop of points closed by a fan of triangles round its centroid (a hole filled for the map, a pinhole the quads
// close). [in,out] points: the centroid added; [in,out] triangles: the fan added, each turning as the loop runs
// (reverse: against it); [in] loop: indices into points.
void closeByFan(std::vector<Vec3>& points, std::vector<std::array<int, 3>>& triangles, const std::vector<int>& loop,
                bool reverse);

// The triangles unfolded onto the plane by the least-squares conformal map (LSCM, Lévy, Petitjean, Ray and Maillot
// 2002, Eq. 5): the boundary free, every triangle's angles kept as far as the surface allows (a strip across a bend,
// a piece of a cylinder unfold exactly), two points pinned, then scaled to the triangles' area. [in] points;
// [in] triangles: a connected patch, any orientation. Returns the map (the triangles turned to one orientation,
// counter-clockwise in uv; no rim loops); empty if the patch is not connected and orientable, or a triangle folds.
SurfaceMap unfoldConformally(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles);

// A ring of triangles (two rims: the gap round walls standing all round a boss) unfolded onto a flat annulus: the
// annulus map's rectangle (mapToPlane's MapBoundary::Annulus: the angle and the log-radius, conformal) taken through
// the exponential, (angle, s) -> e^s (cos angle, sin angle), which is conformal too, then scaled to the triangles'
// area. [in] points; [in] triangles: a connected ring, any orientation. Returns the map (the triangles turned
// counter-clockwise in uv, cut open from rim to rim: the cut's copies at their points' places); empty if the
// triangles are not a ring the annulus map takes (unfoldConformally takes a disc).
SurfaceMap unfoldRing(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles);

// 3D arc length along a loop from its first point: up to point i at [i], the whole loop at [size].
std::vector<double> arcLength(const std::vector<int>& loop, const std::vector<Vec3>& x);

// The four points of a loop farthest out along the diagonals (+,+), (-,+), (-,-), (+,-) of the axes
// e1, e2 around `centre`, as positions in the loop.
std::array<int, 4> diagonalExtremes(const std::vector<Vec3>& loop, const Vec3& centre, const Vec3& e1, const Vec3& e2);

// A point of a loop where a measure accumulated along it (cumulative, one more entry than the loop
// has points: arc length, or the quads the target size needs) reaches s.
struct LoopPoint {
  Vec3 x;
  Eigen::Vector2d uv;
};
LoopPoint loopPoint(const SurfaceMap& map, const std::vector<int>& loop, const std::vector<double>& measure, double s);

// The 3D point of the chordal surface at a point of the plane (on the nearest mapped triangle).
class MapLocator {
 public:
  explicit MapLocator(const SurfaceMap& map);
  Vec3 operator()(const Eigen::Vector2d& uv) const;
  // The same for a map periodic in u (an annulus cut open): uv, or uv shifted by one period either way,
  // whichever lies in the map.
  Vec3 periodic(const Eigen::Vector2d& uv, double period) const;

 private:
  struct Found {
    Vec3 point;
    double miss;  // squared distance in the plane from uv to the triangle it was found in (0: inside)
  };
  Found find(const Eigen::Vector2d& uv) const;
  Vec3 at(int point) const { return Vec3(map_.uv[point].x(), map_.uv[point].y(), 0); }
  const SurfaceMap& map_;
  BoxGrid triangles_;                                // by their bounding boxes in the plane
  std::vector<std::array<Eigen::Vector2d, 2>> box_;  // per triangle, its box's corners (lo, hi)
};

}  // namespace hexlayer
