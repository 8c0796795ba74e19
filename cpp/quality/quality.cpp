#include "quality/quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

#include "core/groups.hpp"

namespace hexlayer {

const std::array<std::array<int, 4>, 6> kHexFaces = {
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

namespace {

// For corner k, the far ends of its three edges (e1, e2, e3), right-handed for a positive hex.
constexpr int kCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

constexpr int kHistogramBins = 10;

// Sign of corner i's natural coordinates (xi, eta, zeta) in [-1, 1]^3.
Eigen::Vector3d cornerSign(int i) {
  const double xi = (i == 1 || i == 2 || i == 5 || i == 6) ? 1 : -1;
  const double eta = (i % 4 >= 2) ? 1 : -1;
  const double zeta = i >= 4 ? 1 : -1;
  return {xi, eta, zeta};
}

// Jacobian dx/d(xi, eta, zeta) of the trilinear map at natural point s.
Eigen::Matrix3d trilinearJacobian(const std::array<Vec3, 8>& x, const Eigen::Vector3d& s) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d c = cornerSign(i);
    const Eigen::Vector3d f = (Eigen::Vector3d::Ones() + c.cwiseProduct(s));  // (1 + c_d s_d) per direction
    const Eigen::Vector3d grad(c.x() * f.y() * f.z(), c.y() * f.x() * f.z(), c.z() * f.x() * f.y());
    J += x[i] * grad.transpose() / 8.0;
  }
  return J;
}

double meanLength(const std::array<Vec3, 8>& x, const int (*edges)[2], int n) {
  double sum = 0;
  for (int e = 0; e < n; ++e) sum += (x[edges[e][1]] - x[edges[e][0]]).norm();
  return sum / n;
}

int histogramBin(double v) {
  if (!(v > 0)) return 0;  // also NaN
  return std::min(kHistogramBins - 1, static_cast<int>(v * kHistogramBins));
}

struct PerHex {
  std::vector<double> sj, ar, volume;
};

PerHex measureEachHex(const HexMesh& mesh) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(mesh.hexes.size());
  PerHex m{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t h = 0; h < n; ++h) {
    const std::array<Vec3, 8> x = hexCorners(mesh, static_cast<std::size_t>(h));
    m.sj[h] = hexScaledJacobian(x);
    m.ar[h] = hexAspectRatio(x);
    m.volume[h] = hexVolume(x);
  }
  return m;
}

struct DirectedEdge {
  int lo, hi;
  int dir;  // +1 if the face runs lo -> hi, -1 otherwise
  bool operator<(const DirectedEdge& o) const { return std::tie(lo, hi, dir) < std::tie(o.lo, o.hi, o.dir); }
};

// Adds one boundary edge group [b, e) (same lo, hi) to the counts.
void classifyEdgeGroup(const DirectedEdge* b, const DirectedEdge* e, BoundaryCheck& c) {
  const std::ptrdiff_t uses = e - b;
  const bool open = uses == 1, nonManifold = uses > 2, flipped = uses == 2 && b[0].dir == b[1].dir;
  c.openEdges += open;
  c.nonManifoldEdges += nonManifold;
  c.inconsistentlyOrientedEdges += flipped;
  if ((open || nonManifold || flipped) && c.firstBadEdge[0] < 0) c.firstBadEdge = {b->lo, b->hi};
}

}  // namespace

std::array<Vec3, 8> hexCorners(const HexMesh& mesh, std::size_t h) {
  std::array<Vec3, 8> x;
  for (int i = 0; i < 8; ++i) x[i] = mesh.nodes[mesh.hexes[h][i]];
  return x;
}

// Verdict scaled Jacobian: min_k det(e1,e2,e3)/(|e1||e2||e3|) over the corners k, -1 if an edge is degenerate.
double hexScaledJacobian(const std::array<Vec3, 8>& x) {
  double sj = 1;
  for (int k = 0; k < 8; ++k) {
    const Vec3 e1 = x[kCornerEdges[k][0]] - x[k], e2 = x[kCornerEdges[k][1]] - x[k], e3 = x[kCornerEdges[k][2]] - x[k];
    const double lengths = e1.norm() * e2.norm() * e3.norm();
    if (!(lengths > 0)) return -1;
    sj = std::min(sj, e1.dot(e2.cross(e3)) / lengths);
  }
  return sj;
}

// Volume: integral of det J over [-1,1]^3 by 2x2x2 Gauss, exact since det J has degree <= 2 per coordinate.
double hexVolume(const std::array<Vec3, 8>& x) {
  const double g = 1.0 / std::sqrt(3.0);
  double v = 0;
  for (int i = 0; i < 8; ++i) v += trilinearJacobian(x, g * cornerSign(i)).determinant();
  return v;
}

// Aspect ratio: mean |quad edge| (8 edges of faces 0-3, 4-7) / mean |sweep edge| (i -> i+4).
double hexAspectRatio(const std::array<Vec3, 8>& x) {
  static constexpr int quadEdges[8][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  static constexpr int sweepEdges[4][2] = {{0, 4}, {1, 5}, {2, 6}, {3, 7}};
  const double thickness = meanLength(x, sweepEdges, 4);
  if (!(thickness > 0)) return std::numeric_limits<double>::infinity();
  return meanLength(x, quadEdges, 8) / thickness;
}

QualityReport measureQuality(const HexMesh& mesh) {
  QualityReport q;
  q.sjHistogram.counts.assign(kHistogramBins, 0);
  if (mesh.hexes.empty()) return q;
  PerHex m = measureEachHex(mesh);
  const double n = static_cast<double>(mesh.hexes.size());
  const auto worst = std::min_element(m.sj.begin(), m.sj.end());
  q.sjMin = *worst;
  for (const Vec3& p : hexCorners(mesh, static_cast<std::size_t>(worst - m.sj.begin()))) q.worstAt += p / 8;
  q.arMin = *std::min_element(m.ar.begin(), m.ar.end());
  q.arMax = *std::max_element(m.ar.begin(), m.ar.end());
  double sjSum = 0, arSum = 0;
  for (std::size_t h = 0; h < m.sj.size(); ++h) {  // serial sums: the same result for any thread count
    sjSum += m.sj[h];
    arSum += m.ar[h];
    q.volume += m.volume[h];
    ++q.sjHistogram.counts[histogramBin(m.sj[h])];
    q.inverted += m.sj[h] <= 0;
  }
  q.sjAvg = sjSum / n;
  q.arAvg = arSum / n;
  q.scaledJacobian = std::move(m.sj);
  return q;
}

std::vector<BoundaryFace> boundaryFaces(const HexMesh& mesh) {
  const std::size_t count = 6 * mesh.hexes.size();  // face f is local face f % 6 of hex f / 6
  auto corners = [&](std::size_t f) {
    std::array<int, 4> k;
    for (int i = 0; i < 4; ++i) k[i] = mesh.hexes[f / 6][kHexFaces[f % 6][i]];
    return k;
  };
  auto key = [&](std::size_t f) {  // its corners sorted: the same for every hex the face is on
    std::array<int, 4> k = corners(f);
    std::sort(k.begin(), k.end());
    return k;
  };
  // The faces by their lowest node (a counting sort): two hexes share a face only within one bucket,
  // and a bucket holds the few faces round one node. A face whose key is found twice is interior.
  // (Node ids outside the mesh, which validation reports, wrap round into some bucket.)
  const long buckets = std::max<long>(1, static_cast<long>(mesh.nodes.size()));
  const Groups<std::size_t> byNode = groupByKey<std::size_t>(buckets, [&](auto emit) {
    for (std::size_t f = 0; f < count; ++f) emit(static_cast<unsigned>(key(f)[0]) % buckets, f);
  });
  std::vector<char> shared(count, 0);  // each face is written by the one bucket it is in
#pragma omp parallel for schedule(dynamic, 4096)
  for (long v = 0; v < buckets; ++v)
    for (std::size_t a = byNode.start[v]; a < byNode.start[v + 1]; ++a)
      for (std::size_t b = a + 1; b < byNode.start[v + 1]; ++b)
        if (key(byNode.items[a]) == key(byNode.items[b])) shared[byNode.items[a]] = shared[byNode.items[b]] = 1;
  std::vector<BoundaryFace> faces;  // by hex, then local face
  for (std::size_t f = 0; f < count; ++f)
    if (!shared[f]) faces.push_back({corners(f), static_cast<int>(f / 6), static_cast<int>(f % 6)});
  return faces;
}

BoundaryCheck checkBoundary(const HexMesh& mesh) {
  const std::vector<BoundaryFace> faces = boundaryFaces(mesh);
  BoundaryCheck c;
  c.faces = faces.size();
  std::vector<DirectedEdge> edges;
  edges.reserve(4 * faces.size());
  for (const BoundaryFace& f : faces)
    for (int i = 0; i < 4; ++i) {
      const int a = f.nodes[i], b = f.nodes[(i + 1) % 4];
      edges.push_back({std::min(a, b), std::max(a, b), a < b ? 1 : -1});
    }
  std::sort(edges.begin(), edges.end());
  long distinctEdges = 0;
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j, ++distinctEdges) {
    for (j = i + 1; j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi;) ++j;
    classifyEdgeGroup(edges.data() + i, edges.data() + j, c);
  }
  std::vector<int> vertices;
  for (const BoundaryFace& f : faces) vertices.insert(vertices.end(), f.nodes.begin(), f.nodes.end());
  std::sort(vertices.begin(), vertices.end());
  const long distinctVertices = std::unique(vertices.begin(), vertices.end()) - vertices.begin();
  c.eulerCharacteristic = distinctVertices - distinctEdges + static_cast<long>(faces.size());
  return c;
}

CoincidentNodes findCoincidentNodes(const HexMesh& mesh, double tol) {
  CoincidentNodes found;
  if (!(tol > 0) || mesh.nodes.empty()) return found;
  Vec3 lo = mesh.nodes[0], hi = mesh.nodes[0];
  for (const Vec3& p : mesh.nodes) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  // Cells at least tol wide, no finer than 1e-6 of the extent: at most 2^20 a side, so a cell's
  // three indices pack into one sorted key with z last (cells z-1 .. z+1 are one key range).
  const double cell = std::max(tol, 1e-6 * (hi - lo).maxCoeff());
  auto index = [&](const Vec3& p) { return ((p - lo) / cell).array().floor().cast<std::int64_t>().eval(); };
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return static_cast<std::uint64_t>((x << 42) | (y << 21) | z);
  };
  std::vector<std::pair<std::uint64_t, int>> byCell(mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const auto c = index(mesh.nodes[i]);
    byCell[i] = {key(c.x(), c.y(), c.z()), static_cast<int>(i)};
  }
  std::sort(byCell.begin(), byCell.end());
  const long n = static_cast<long>(mesh.nodes.size());
  std::size_t pairs = 0;
  long first = n;
#pragma omp parallel for schedule(static) reduction(+ : pairs) reduction(min : first)
  for (long i = 0; i < n; ++i) {  // each pair counted at its higher-numbered node
    const Vec3& p = mesh.nodes[i];
    const auto c = index(p);
    for (std::int64_t x = std::max<std::int64_t>(c.x() - 1, 0); x <= c.x() + 1; ++x)
      for (std::int64_t y = std::max<std::int64_t>(c.y() - 1, 0); y <= c.y() + 1; ++y) {
        auto at = std::lower_bound(byCell.begin(), byCell.end(),
                                   std::make_pair(key(x, y, std::max<std::int64_t>(c.z() - 1, 0)), 0));
        for (const std::uint64_t last = key(x, y, c.z() + 1); at != byCell.end() && at->first <= last; ++at)
          if (at->second < i && (mesh.nodes[at->second] - p).squaredNorm() < tol * tol)
            ++pairs, first = std::min(first, i);
      }
  }
  found.pairs = pairs;
  if (first < n) found.firstNode = static_cast<int>(first);
  return found;
}

std::size_t countCoincidentNodes(const HexMesh& mesh, double tol) { return findCoincidentNodes(mesh, tol).pairs; }

}  // namespace hexlayer
