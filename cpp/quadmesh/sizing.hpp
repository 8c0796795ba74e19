// Sizing function of the quad mesh (paper §6.1): uniform, or geometry-adaptive from the radius
// function (the local half-thickness) and the curvature of the chordal surface.
#pragma once
#include <vector>

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
// not below minSize, and a loop shorter than minSize is a pinhole, left alone), then smoothed so that neighbours
// differ by at most gradation x their distance.
std::vector<double> adaptiveSizes(const ChordalSurface& chordal, const SizingOptions& options);

// Curvature of the chordal surface at every vertex: the mean over its edges of the angle between
// the two end normals over the edge length.
std::vector<double> chordalCurvature(const ChordalSurface& chordal);

}  // namespace hexlayer
