// A face's boundary in its parameter plane, for a quick inside/outside test of a parameter point:
// polylines of the edges' pcurves, sampled to a quarter of a margin. A point nearer the boundary
// than the margin is left undecided (an exact classifier, BRepClass_FaceClassifier, decides it).
#pragma once
#include <TopoDS_Face.hxx>
#include <gp_Circ2d.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

namespace hexlayer {

class UvBoundary {
 public:
  enum class Side { Inside, Outside, Undecided };
  // A point of a pcurve: its parameter t and (u / marginU, v / marginV), where the margin is 1.
  struct Sample {
    double t, x, y;
  };
  // A pcurve in closed form, if it is a line segment a-b or an arc of `circle` on [first, last].
  struct ExactPcurve {
    enum class Kind { Other, Line, Circle } kind = Kind::Other;
    gp_Pnt2d a, b;  // its ends
    gp_Circ2d circle;
    double first = 0, last = 0;
    double distance(const gp_Pnt2d& p) const;
  };

  // `marginU`, `marginV`: how far (in u and v) a point must be from every pcurve to be decided.
  UvBoundary(const TopoDS_Face& face, double marginU, double marginV);
  // Inside or outside the face's wires; Undecided near a pcurve, or if the boundary could not be sampled.
  Side side(double u, double v) const;
  // A lower bound on the distance from (u, v) to the face's pcurves, in margins (times margin(): in (u, v)); 0 if the
  // boundary could not be sampled.
  double clearance(double u, double v) const;
  // True if (u, v) lies within `tolerance` (in u, v) of a pcurve that is a line segment or a circular arc, the distance
  // computed in closed form: BRepClass_FaceClassifier calls a point ON an edge whose pcurve is within its tolerance of
  // it (CheckOn). False elsewhere, and on the face's other pcurves: undecided by this test.
  // [in] u, v: the point; [in] tolerance: in (u, v).
  bool onLineOrCircle(double u, double v, double tolerance) const;
  // The smaller of the two margins (u, v) given at construction.
  double margin() const { return std::min(1 / scaleU_, 1 / scaleV_); }

 private:
  // A run of at most 16 segments of one pcurve's polyline, with its bounding box and its pcurve (into pcurves_).
  struct Chunk {
    std::vector<Sample> points;
    double xMin, xMax, yMin, yMax;
    int pcurve;
  };
  void addPolyline(const std::vector<Sample>& line, int pcurve);
  // The chunks by bands of y: each in every band its y-range, widened by 1 (the undecided band), overlaps. Only those
  // can cross the line through a point parallel to u or lie within a margin of it.
  void binChunks();
  std::size_t bin(double y) const;
  // How far (x, y) (scaled) lies from the chunk's box along x and along y (0 within its range).
  static std::pair<double, double> gaps(const Chunk& c, double x, double y);

  double scaleU_, scaleV_;
  bool sampled_ = true;  // false if a pcurve is missing or would need too many segments
  std::vector<Chunk> chunks_;
  std::vector<ExactPcurve> pcurves_;  // in the face's edge order
  double binLow_ = 0, binWidth_ = 1;  // band b covers y in [binLow_ + b binWidth_, binLow_ + (b + 1) binWidth_)
  std::vector<std::vector<int>> bins_;
};

// The distance from an edge within which UvBoundary::onLineOrCircle's ON is the exact classifiers' for a classifier
// given `tolerance`: half the smaller of it and Precision::Confusion() (BRepClass refines the tolerance on a cylinder,
// never below Confusion; IntCurvesFace_Intersector classifies with at least its own).
double onEdgeBand(double tolerance);

// A face's UvBoundary with the margins the exact classifiers' callers use: max(1e-5 x the part's diagonal,
// 3 x the face's largest tolerance) in 3D, turned into (u, v) by the surface's resolution (at least 3 x that
// tolerance): beyond the band in which BRepClass_FaceClassifier calls a point ON an edge.
// [in] face: the face; [in] diagonal: the part's bounding-box diagonal; [in] leastMargin: the least margin in u and
// in v (a caller's classifier whose ON band in (u, v) is wider). Returns the boundary (built here).
std::unique_ptr<UvBoundary> faceUvBoundary(const TopoDS_Face& face, double diagonal, double leastMargin = 0);

}  // namespace hexlayer
