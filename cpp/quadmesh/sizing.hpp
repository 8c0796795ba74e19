// Sizing function of the quad mesh (paper §6.1): uniform, or geometry-adaptive from the radius
// function (the local half-thickness) and the curvature of the chordal surface.
#pragma once
#include <vector>

#include "chordal/chordal_locator.hpp"
#include "chordal/chordal_surface.hpp"

namespace hexlayer {

struct SizingOptions {
  double size = 0;     // quad size where the wall has its median thickness
  double minSize = 0;  // bounds of the adaptive size (0: size / 4 and 4 x size)
  double maxSize = 0;
  double gradation = 0.3;    // the size grows by at most this much per unit length
  double turnPerQuad = 0.5;  // radians the chordal surface may turn across one quad
};

// Target quad size at every chordal vertex (§6.1): size x r / median r (quads as many wall
// thicknesses wide everywhere), at most turnPerQuad / curvature where the surface bends no tighter than its wall
// is thick (a crease is not refined: sizing.cpp's isCrease), within [minSize, maxSize], at most an eighth of the rim
// loop a rim vertex lies on (a hole keeps eight quad edges round it: fewer, and the quad mesh closes a small hole;
// not below minSize, and a loop shorter than minSize is a pinhole, left alone), at most half the gap across the
// surface to the rim facing a rim vertex (a ligament between holes, a hole near the rim, a slot: two quads across it;
// not below minSize), then smoothed so that neighbours differ by at most gradation x their distance.
std::vector<double> adaptiveSizes(const ChordalSurface& chordal, const SizingOptions& options);

// Curvature of the chordal surface at every vertex: the mean over its edges of the angle between
// the two end normals over the edge length.
std::vector<double> chordalCurvature(const ChordalSurface& chordal);

// The target size at points of the chordal surface (§6.1), interpolated from the corners of the facet each lies on,
// for points asked one after another, each near the one before (Gmsh asks along its mesh): each search starts from
// the facet found before. A point beyond the surface's box grown by its diagonal (Gmsh asks at (1e21, 1e21, 1e21)
// where its patch's parametrization has no point, in a hole's gap: the nearest facet to it took a scan of every facet)
// takes the mean size at the corners of the facet found before, or the largest size if there was none.
class ChordalSizeField {
 public:
  // [in] chordal: the surface and its locator, kept by reference; [in] vertexSize: the size at each chordal vertex
  // (adaptiveSizes), kept by reference, not empty.
  ChordalSizeField(const ChordalLocator& chordal, const std::vector<double>& vertexSize);
  // [in] p: the point; [in,out] facet: the facet found for the point asked before (-1: none), then p's. Returns the
  // size at p. Thread-safe.
  double at(const Vec3& p, int& facet) const;
  // at(p) after the point asked before of this field (not thread-safe).
  double operator()(const Vec3& p) { return at(p, facet_); }

 private:
  const ChordalLocator* chordal_;
  const std::vector<double>* vertexSize_;
  Vec3 reachLo_, reachHi_;  // the surface's box grown by its diagonal
  int facet_ = -1;
};

}  // namespace hexlayer
