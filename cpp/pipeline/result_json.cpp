#include "pipeline/result_json.hpp"

namespace hexlayer {
namespace {

nlohmann::json points(const std::vector<Vec3>& x) {
  nlohmann::json a = nlohmann::json::array();
  for (const Vec3& p : x) a.push_back({p.x(), p.y(), p.z()});
  return a;
}

template <class Cells>
nlohmann::json rows(const Cells& cells) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& cell : cells) a.push_back(nlohmann::json(std::vector<int>(cell.begin(), cell.end())));
  return a;
}

nlohmann::json hexRows(const HexMesh& mesh) {
  nlohmann::json a = nlohmann::json::array();
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    std::vector<int> row(mesh.hexes[h].begin(), mesh.hexes[h].end());
    if (mesh.quadratic()) row.insert(row.end(), mesh.midEdges[h].begin(), mesh.midEdges[h].end());
    a.push_back(std::move(row));
  }
  return a;
}

}  // namespace

nlohmann::json resultJson(const MeshResult& r) {
  nlohmann::json j;
  j["nodes"] = points(r.mesh.nodes);
  j["hexes"] = hexRows(r.mesh);
  j["scaled_jacobian"] = r.scaledJacobian;
  j["node_sets"] = nlohmann::json::object();
  for (const NodeSet& s : r.nodeSets) j["node_sets"][s.name] = s.nodes;
  j["face_nodes"] = nlohmann::json::object();
  j["face_elements"] = nlohmann::json::object();
  for (const SurfaceGroup& g : r.surfaceGroups) {
    j["face_nodes"][g.name] = g.nodes;
    nlohmann::json faces = nlohmann::json::array();
    for (const HexFace& f : g.hexFaces) faces.push_back({f.hex, f.localFace});
    j["face_elements"][g.name] = std::move(faces);
  }
  j["report"] = r.report;
  j["chordal_vertices"] = points(r.chordalSurface.vertices);
  j["chordal_facets"] = rows(r.chordalSurface.facets);
  j["quad_nodes"] = points(r.quadMesh.nodes);
  j["quads"] = rows(r.quadMesh.quads);
  j["node_layer"] = r.mesh.nodeLayer;
  return j;
}

}  // namespace hexlayer
