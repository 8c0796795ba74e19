#include "geometry/uv_boundary.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <ElCLib.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_Curve.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/cad_solid.hpp"

namespace hexlayer {
namespace {

// The margin per tolerance of the face, its edges and vertices (was 1000: on a STEP written with 4e-3 mm tolerances,
// the margin then covered most of the face and the exact classifier was asked nearly everywhere).
constexpr double kToleranceMargin = 3;

using Sample = UvBoundary::Sample;

constexpr std::size_t kChunk = 16;  // segments per chunk
constexpr double kSag = 0.25;       // largest distance of a pcurve from its polyline, in margins
constexpr int kMaxDepth = 16;       // halvings of a pcurve interval at most
constexpr int kMinDepth = 2;        // halvings of a curved pcurve interval at least

// Distance from (x, y) to the segment a-b, squared.
double squaredDistance(double x, double y, const Sample& a, const Sample& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  const double s = length2 > 0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
  const double ex = a.x + s * dx - x, ey = a.y + s * dy - y;
  return ex * ex + ey * ey;
}

// Samples a pcurve in the scaled plane (u * scaleU, v * scaleV).
struct PcurveSampler {
  const Geom2dAdaptor_Curve& curve;
  double scaleU, scaleV;
  bool curved;

  Sample at(double t) const {
    const gp_Pnt2d p = curve.Value(t);
    return {t, p.X() * scaleU, p.Y() * scaleV};
  }
  // Appends the samples after a up to b, halving while the midpoint is more than kSag off the chord;
  // false if kMaxDepth halvings do not get there.
  bool refine(const Sample& a, const Sample& b, int depth, std::vector<Sample>& out) const {
    const Sample m = at(0.5 * (a.t + b.t));
    const bool far = squaredDistance(m.x, m.y, a, b) > kSag * kSag;
    if ((curved && depth < kMinDepth) || far) {
      if (depth >= kMaxDepth) return false;
      return refine(a, m, depth + 1, out) && refine(m, b, depth + 1, out);
    }
    out.push_back(b);
    return true;
  }
};

// The polyline of one pcurve on [first, last], split at its C2 intervals; empty if it cannot be sampled.
std::vector<Sample> polyline(const Handle(Geom2d_Curve) & pcurve, double first, double last, double scaleU,
                             double scaleV) {
  const Geom2dAdaptor_Curve curve(pcurve, first, last);
  const PcurveSampler sampler{curve, scaleU, scaleV, curve.GetType() != GeomAbs_Line};
  TColStd_Array1OfReal breaks(1, curve.NbIntervals(GeomAbs_C2) + 1);
  curve.Intervals(breaks, GeomAbs_C2);
  std::vector<Sample> line{sampler.at(first)};
  for (int i = breaks.Lower(); i < breaks.Upper(); ++i)
    if (!sampler.refine(line.back(), sampler.at(std::min(breaks(i + 1), last)), 0, line)) return {};
  return line;
}

// The pcurve on [first, last] in closed form if it is a line or a circle (Kind::Other otherwise).
UvBoundary::ExactPcurve exactPcurve(const Handle(Geom2d_Curve) & pcurve, double first, double last) {
  UvBoundary::ExactPcurve exact;
  if (pcurve.IsNull()) return exact;
  const Geom2dAdaptor_Curve curve(pcurve, first, last);
  if (curve.GetType() != GeomAbs_Line && curve.GetType() != GeomAbs_Circle) return exact;
  exact.kind =
      curve.GetType() == GeomAbs_Line ? UvBoundary::ExactPcurve::Kind::Line : UvBoundary::ExactPcurve::Kind::Circle;
  exact.a = curve.Value(first), exact.b = curve.Value(last);
  if (exact.kind == UvBoundary::ExactPcurve::Kind::Circle) exact.circle = curve.Circle();
  exact.first = first, exact.last = last;
  return exact;
}

// Two pcurves meet at a vertex, but each end is evaluated on its own curve, a few ulps from the
// other's: where the line through a point runs exactly through such a joint (a circle's seam on the
// line through its centre), crossings would be counted on neither side of it or on both. Ends closer
// than this (in margins, far below the undecided band of 1) are made one point, the first one seen.
constexpr double kJoint = 1e-6;

void joinEnds(std::vector<std::vector<Sample>>& lines) {
  std::vector<Sample> joints;
  for (auto& line : lines)
    for (Sample* end : {&line.front(), &line.back()}) {
      const auto same = std::find_if(joints.begin(), joints.end(), [&](const Sample& j) {
        return std::abs(j.x - end->x) < kJoint && std::abs(j.y - end->y) < kJoint;
      });
      if (same == joints.end())
        joints.push_back(*end);
      else
        end->x = same->x, end->y = same->y;
    }
}

}  // namespace

UvBoundary::UvBoundary(const TopoDS_Face& face, double marginU, double marginV)
    : scaleU_(1 / marginU), scaleV_(1 / marginV) {
  std::vector<std::vector<Sample>> lines;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More() && sampled_; e.Next()) {
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, first, last);
    lines.push_back(pcurve.IsNull() ? std::vector<Sample>{} : polyline(pcurve, first, last, scaleU_, scaleV_));
    pcurves_.push_back(exactPcurve(pcurve, first, last));
    sampled_ = !lines.back().empty();
  }
  if (!sampled_) return;
  joinEnds(lines);
  for (std::size_t i = 0; i < lines.size(); ++i) addPolyline(lines[i], static_cast<int>(i));
  binChunks();
}

void UvBoundary::binChunks() {
  if (chunks_.empty()) return;
  double low = chunks_[0].yMin, high = chunks_[0].yMax;
  for (const Chunk& c : chunks_) low = std::min(low, c.yMin), high = std::max(high, c.yMax);
  binLow_ = low - 1;
  const std::size_t count = std::clamp<std::size_t>(chunks_.size(), 1, 1024);
  binWidth_ = std::max((high + 1 - binLow_) / count, 1e-300);
  bins_.assign(count, {});
  for (std::size_t i = 0; i < chunks_.size(); ++i)
    for (std::size_t b = bin(chunks_[i].yMin - 1); b <= bin(chunks_[i].yMax + 1); ++b)
      bins_[b].push_back(static_cast<int>(i));
}

// The band of y, the first or the last beyond them (its chunks are a superset of those that count there).
std::size_t UvBoundary::bin(double y) const {
  const double at = (y - binLow_) / binWidth_;
  return at > 0 ? static_cast<std::size_t>(std::min(at, static_cast<double>(bins_.size() - 1))) : 0;
}

void UvBoundary::addPolyline(const std::vector<Sample>& line, int pcurve) {
  for (std::size_t start = 0; start + 1 < line.size(); start += kChunk) {
    Chunk c{{}, line[start].x, line[start].x, line[start].y, line[start].y, pcurve};
    for (std::size_t i = start; i < std::min(line.size(), start + kChunk + 1); ++i) {
      c.points.push_back(line[i]);
      c.xMin = std::min(c.xMin, line[i].x), c.xMax = std::max(c.xMax, line[i].x);
      c.yMin = std::min(c.yMin, line[i].y), c.yMax = std::max(c.yMax, line[i].y);
    }
    chunks_.push_back(std::move(c));
  }
}

std::pair<double, double> UvBoundary::gaps(const Chunk& c, double x, double y) {
  return {std::max({c.xMin - x, 0.0, x - c.xMax}), std::max({c.yMin - y, 0.0, y - c.yMax})};
}

// The distance to the nearest polyline segment (chunks whose box is farther than the nearest so far skipped), less
// the polylines' largest distance from their pcurves (kSag).
double UvBoundary::clearance(double u, double v) const {
  if (!sampled_) return 0;
  const double x = u * scaleU_, y = v * scaleV_;
  double nearest = std::numeric_limits<double>::infinity();  // squared
  for (const Chunk& c : chunks_) {
    const auto [dx, dy] = gaps(c, x, y);
    if (dx * dx + dy * dy >= nearest) continue;
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
      nearest = std::min(nearest, squaredDistance(x, y, c.points[i], c.points[i + 1]));
  }
  return std::max(0.0, std::sqrt(nearest) - kSag);
}

UvBoundary::Side UvBoundary::side(double u, double v) const {
  if (!sampled_) return Side::Undecided;
  const double x = u * scaleU_, y = v * scaleV_;
  int right = 0, left = 0;                  // crossings of the line through the point parallel to u, on either side
  if (bins_.empty()) return Side::Outside;  // no pcurve: nothing is crossed
  for (const int i : bins_[bin(y)]) {
    const Chunk& c = chunks_[i];
    const auto [dx, dy] = gaps(c, x, y);
    const bool near = dx * dx + dy * dy < 1;
    if (!near && dy > 0) continue;
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const Sample& a = c.points[i];
      const Sample& b = c.points[i + 1];
      if (near && squaredDistance(x, y, a, b) < 1) return Side::Undecided;
      if ((a.y > y) != (b.y > y)) ++(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y) > x ? right : left);
    }
  }
  if ((right + left) % 2 != 0) return Side::Undecided;  // the polylines do not close: a gap in a wire
  return right % 2 ? Side::Inside : Side::Outside;
}

// The distance from p to the segment a-b, or to the arc: to the circle where p's angle is within [first, last] (taken
// modulo the period from first), else to the nearer end.
double UvBoundary::ExactPcurve::distance(const gp_Pnt2d& p) const {
  if (kind == Kind::Line) {
    const Sample pa{0, a.X(), a.Y()}, pb{1, b.X(), b.Y()};
    return std::sqrt(squaredDistance(p.X(), p.Y(), pa, pb));
  }
  const double period = 2 * M_PI;
  double along = std::fmod(ElCLib::Parameter(circle, p) - first, period);  // from first, in [0, period)
  if (along < 0) along += period;
  if (first + along <= last) return std::abs(p.Distance(circle.Location()) - circle.Radius());
  return std::min(p.Distance(a), p.Distance(b));
}

bool UvBoundary::onLineOrCircle(double u, double v, double tolerance) const {
  if (!sampled_) return false;
  const double x = u * scaleU_, y = v * scaleV_;
  const double reachX = kSag + tolerance * scaleU_,
               reachY = kSag + tolerance * scaleV_;  // the pcurve's box, in margins
  auto near = [&](const Chunk& c) {
    const ExactPcurve& pcurve = pcurves_[c.pcurve];
    if (pcurve.kind == ExactPcurve::Kind::Other) return false;
    const auto [dx, dy] = gaps(c, x, y);
    return dx <= reachX && dy <= reachY && pcurve.distance(gp_Pnt2d(u, v)) <= tolerance;
  };
  if (bins_.empty()) return false;
  if (const std::vector<int>& band = bins_[bin(y)]; reachY <= 1)  // within the width the bins widen each chunk by
    return std::any_of(band.begin(), band.end(), [&](int i) { return near(chunks_[i]); });
  return std::any_of(chunks_.begin(), chunks_.end(), near);
}

double onEdgeBand(double tolerance) { return 0.5 * std::min(tolerance, Precision::Confusion()); }

std::unique_ptr<UvBoundary> faceUvBoundary(const TopoDS_Face& face, double diagonal, double leastMargin) {
  const double tolerance = largestTolerance(face), margin = std::max(1e-5 * diagonal, kToleranceMargin * tolerance);
  const BRepAdaptor_Surface surface(face, false);
  const double least = std::max(kToleranceMargin * tolerance, leastMargin);
  return std::make_unique<UvBoundary>(face, std::max(surface.UResolution(margin), least),
                                      std::max(surface.VResolution(margin), least));
}

}  // namespace hexlayer
