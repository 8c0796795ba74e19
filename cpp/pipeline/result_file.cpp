#include "pipeline/result_file.hpp"

#include <cstdint>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "pipeline/report.hpp"

namespace hexlayer {
namespace {

// The arrays, their values appended to one binary stream as they are added.
class Arrays {
 public:
  explicit Arrays(std::ofstream& out) : out_(out) {}
  template <class T>
  void add(const std::string& name, const std::vector<T>& values, std::vector<std::size_t> shape) {
    static_assert(sizeof(double) == 8, "8-byte doubles");
    index_[name] = {{"dtype", std::is_floating_point_v<T> ? "<f8" : "<i8"}, {"shape", shape}, {"offset", offset_}};
    for (const T& v : values) {
      if constexpr (std::is_floating_point_v<T>)
        write(static_cast<double>(v));
      else
        write(static_cast<std::int64_t>(v));
    }
  }
  nlohmann::json index() const { return index_; }

 private:
  template <class V>
  void write(V v) {  // little-endian on the machines FreeCAD runs on (x86-64, arm64)
    out_.write(reinterpret_cast<const char*>(&v), sizeof v);
    offset_ += sizeof v;
  }
  std::ofstream& out_;
  nlohmann::json index_ = nlohmann::json::object();
  std::size_t offset_ = 0;
};

std::vector<double> flat(const std::vector<Vec3>& x) {
  std::vector<double> v;
  v.reserve(3 * x.size());
  for (const Vec3& p : x) v.insert(v.end(), {p.x(), p.y(), p.z()});
  return v;
}

template <class Cells>
std::vector<int> flatCells(const Cells& cells) {
  std::vector<int> v;
  for (const auto& c : cells) v.insert(v.end(), c.begin(), c.end());
  return v;
}

std::vector<int> hexRows(const HexMesh& mesh) {
  std::vector<int> v;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    v.insert(v.end(), mesh.hexes[h].begin(), mesh.hexes[h].end());
    if (mesh.quadratic()) v.insert(v.end(), mesh.midEdges[h].begin(), mesh.midEdges[h].end());
  }
  return v;
}

// The mid-surface shell: shell_nodes, shell_elements (K, 4 or 8), shell_thickness, shell_node_sets/RIM,
// shell_face_nodes/FaceK.
void addShell(Arrays& a, const ShellMesh& s) {
  a.add("shell_nodes", flat(s.nodes), {s.nodes.size(), 3});
  std::vector<int> elements;
  for (std::size_t e = 0; e < s.quads.size(); ++e) {
    elements.insert(elements.end(), s.quads[e].begin(), s.quads[e].end());
    if (s.quadratic()) elements.insert(elements.end(), s.midSides[e].begin(), s.midSides[e].end());
  }
  a.add("shell_elements", elements, {s.quads.size(), s.quadratic() ? 8u : 4u});
  a.add("shell_thickness", s.thickness, {s.thickness.size()});
  for (const NodeSet& n : s.nodeSets) a.add("shell_node_sets/" + n.name, n.nodes, {n.nodes.size()});
  for (const SurfaceGroup& g : s.faces) a.add("shell_face_nodes/" + g.name, g.nodes, {g.nodes.size()});
}

}  // namespace

void writeResult(const std::string& path, const MeshResult& r) {
  const std::string binary = path + ".bin";
  std::ofstream out(binary, std::ios::binary);
  if (!out) throw inputError("cannot write the result '" + binary + "'");
  Arrays a(out);
  a.add("nodes", flat(r.mesh.nodes), {r.mesh.nodes.size(), 3});
  a.add("hexes", hexRows(r.mesh), {r.mesh.hexes.size(), r.mesh.quadratic() ? 20u : 8u});
  a.add("scaled_jacobian", r.scaledJacobian, {r.scaledJacobian.size()});
  for (const NodeSet& s : r.nodeSets) a.add("node_sets/" + s.name, s.nodes, {s.nodes.size()});
  for (const SurfaceGroup& g : r.surfaceGroups) {
    a.add("face_nodes/" + g.name, g.nodes, {g.nodes.size()});
    std::vector<int> faces;
    for (const HexFace& f : g.hexFaces) faces.insert(faces.end(), {f.hex, f.localFace});
    a.add("face_elements/" + g.name, faces, {g.hexFaces.size(), 2});
  }
  a.add("chordal_vertices", flat(r.chordalSurface.vertices), {r.chordalSurface.vertices.size(), 3});
  a.add("chordal_facets", flatCells(r.chordalSurface.facets), {r.chordalSurface.facets.size(), 4});
  a.add("quad_nodes", flat(r.quadMesh.nodes), {r.quadMesh.nodes.size(), 3});
  a.add("quads", flatCells(r.quadMesh.quads), {r.quadMesh.quads.size(), 4});
  a.add("node_layer", r.mesh.nodeLayer, {r.mesh.nodeLayer.size()});
  if (!r.shell.quads.empty()) addShell(a, r.shell);
  if (!out.flush()) throw inputError("cannot write the result '" + binary + "'");
  std::ofstream header(path);
  if (!header) throw inputError("cannot write the result '" + path + "'");
  const std::string name = binary.substr(binary.find_last_of('/') + 1);
  header << nlohmann::json{{"report", toJson(r.report)}, {"binary", name}, {"arrays", a.index()}} << "\n";
}

}  // namespace hexlayer
