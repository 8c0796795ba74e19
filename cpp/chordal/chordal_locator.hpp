// Point location on the chordal surface: the nearest facet and the point's weights there
// (barycentric on triangles, inverse bilinear on quads), used by the quad smoothing and the sweep.
#pragma once
#include <array>
#include <vector>

#include "chordal/chordal_surface.hpp"
#include "core/box_grid.hpp"
#include "core/types.hpp"

namespace hexlayer {

// Barycentric weights w_i = A_i / A of the point of triangle (a, b, c) nearest to p (Eq. 6-7);
// a point on an edge or a vertex gets zero weights for the others, which is Eq. 4-5.
Eigen::Vector3d triangleWeights(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p);

// Inverse bilinear map: (u, v) in [0,1]^2 of the point of the bilinear quad
// P(u,v) = (1-u)(1-v) p0 + u(1-v) p1 + u v p2 + (1-u) v p3 nearest to p (Gauss-Newton).
Eigen::Vector2d inverseBilinear(const std::array<Vec3, 4>& p, const Vec3& x);

struct ChordalPoint {
  int facet = -1;
  std::array<double, 4> weights{};  // of the facet's corners (the 4th is 0 on a triangle)
  Vec3 point = Vec3::Zero();        // the nearest point on the chordal surface
};

// The vertex normals interpolated at a point of the chordal surface (Eq. 7; Eq. 4 on an edge):
// shorter than 1 where they differ.
Vec3 normalAt(const ChordalSurface& chordal, const ChordalPoint& at);

class ChordalLocator {
 public:
  explicit ChordalLocator(const ChordalSurface& chordal);
  ChordalPoint locate(const Vec3& p) const;  // nearest point of the chordal surface
  // The same point, found sooner where the facet `hint` (the answer for a point near p) is near p. [in] hint: a
  // facet, or -1.
  ChordalPoint locate(const Vec3& p, int hint) const;
  const ChordalSurface& surface() const { return chordal_; }

 private:
  ChordalPoint project(int facet, const Vec3& p) const;
  const ChordalSurface& chordal_;
  BoxGrid facets_;             // facets by bounding box
  std::vector<Vec3> lo_, hi_;  // each facet's bounding box
};

}  // namespace hexlayer
