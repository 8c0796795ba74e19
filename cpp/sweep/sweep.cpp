#include "sweep/sweep.hpp"

#include "core/error.hpp"

namespace hexlayer {

SweepDirection interpolateSweep(const ChordalSurface& chordal, const ChordalPoint& at) {
  const auto& f = chordal.facets[at.facet];
  SweepDirection d{Vec3::Zero(), 0};
  for (int k = 0; k < (f[3] < 0 ? 3 : 4); ++k) {
    d.normal += at.weights[k] * chordal.normals[f[k]];  // Eq. 7 (Eq. 4 on an edge)
    d.radius += at.weights[k] * chordal.radius[f[k]];   // Eq. 6 (Eq. 5 on an edge)
  }
  d.normal.normalize();  // the weighted sum of unit normals is shorter than 1: sweep along a unit vector
  return d;
}

std::vector<double> layerOffsets(int m) {
  std::vector<double> offsets(m + 1);
  const double s = 2.0 / m;  // s = 2r / m, in units of r
  for (int k = 0; k <= m; ++k) offsets[k] = s * (k - 0.5 * m);
  return offsets;
}


HexMesh sweepQuads(const QuadMesh& q, const ChordalLocator& chordal, int m) {
  if (m < 1) throw usageError("the number of layers must be at least 1");
  const std::vector<double> offsets = layerOffsets(m);
  const std::vector<std::vector<int>> rim = rimEdgeNeighbours(q);  // the chordal surface's rim
  std::vector<SweepDirection> dir(q.nodes.size());
  #pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(q.nodes.size()); ++i) dir[i] = interpolateSweep(chordal.surface(), chordal.locate(q.nodes[i]));

  HexMesh mesh;
  mesh.layers = m;
  const int stride = m + 1;  // hex node of quad node i in layer k: i * (m + 1) + k
  mesh.nodes.resize(q.nodes.size() * stride);
  mesh.nodeLayer.resize(mesh.nodes.size());
  mesh.nodeOnRim.resize(mesh.nodes.size());
  for (size_t i = 0; i < q.nodes.size(); ++i)
    for (int k = 0; k <= m; ++k) {
      mesh.nodes[i * stride + k] = q.nodes[i] + dir[i].normal * (dir[i].radius * offsets[k]);  // §7.2
      mesh.nodeLayer[i * stride + k] = k;
      mesh.nodeOnRim[i * stride + k] = !rim[i].empty();
    }
  mesh.hexes.reserve(q.quads.size() * m);
  for (std::array<int, 4> quad : q.quads) {
    const Vec3 n = (q.nodes[quad[2]] - q.nodes[quad[0]]).cross(q.nodes[quad[3]] - q.nodes[quad[1]]);
    const Vec3 sweepDir = dir[quad[0]].normal + dir[quad[1]].normal + dir[quad[2]].normal + dir[quad[3]].normal;
    if (n.dot(sweepDir) < 0) std::swap(quad[1], quad[3]);  // counter-clockwise seen from the top
    for (int k = 0; k < m; ++k) {  // §7.3: the quad's nodes in layers k and k + 1
      std::array<int, 8> hex;
      for (int c = 0; c < 4; ++c) hex[c] = quad[c] * stride + k, hex[c + 4] = quad[c] * stride + k + 1;
      mesh.hexes.push_back(hex);
    }
  }
  return mesh;
}

}  // namespace hexlayer
