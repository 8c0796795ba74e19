#include "pipeline/report.hpp"

namespace hexlayer::report {
namespace {

nlohmann::json point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace

nlohmann::json faces(const WallSides& sides) {
  int top = 0, bottom = 0, lateral = 0;
  for (const FaceSide& f : sides.faces) (f.side == Side::Top ? top : f.side == Side::Bottom ? bottom : lateral)++;
  return {{"top", top}, {"bottom", bottom}, {"lateral", lateral}};
}

nlohmann::json memory(const MemoryEstimate& m) {
  return {{"quads", m.quads}, {"hexes", m.hexes}, {"bytes", m.bytes}, {"machine_bytes", m.machineBytes}};
}

nlohmann::json tets(const TetFilterCounts& dropped, std::size_t kept) {
  return {{"delaunay", dropped.delaunay},
          {"outside", dropped.outside},
          {"flat", dropped.flat},
          {"coplanar_kept", dropped.coplanar},
          {"kept", kept}};
}

nlohmann::json chordal(const ChordalSurface& cut) {
  return {{"triangles", cut.triangles},
          {"quads", cut.quads},
          {"vertices", cut.vertices.size()},
          {"pinched_facets_dropped", cut.pinchedFacetsDropped}};
}

nlohmann::json chordalRim(const RimSnapStats& s, double unit) {
  return {{"vertices", s.rimVertices},
          {"moved", s.moved},
          {"spikes_dropped", s.spikesDropped},
          {"largest_move", s.largestMove / unit}};
}

nlohmann::json smallFeatures(const SmallFeatures& s) {
  return {{"edges_shorter_than_size", s.shortEdges}, {"narrow_faces", s.narrowFaces}, {"first_at", point(s.firstAt)}};
}

nlohmann::json quadMesh(const QuadMesh& q) {
  return {{"quads", q.quads.size()},
          {"nodes", q.nodes.size()},
          {"triangles_paired", q.pairedTriangles},
          {"triangles_split", q.splitTriangles},
          {"unpaired_triangles", q.holes},
          {"doublets_removed", q.doubletsRemoved},
          {"structured_patches", q.structuredPatches},
          {"layout", layoutName(q.layout)}};
}

nlohmann::json sweep(const UntangleResult& u, const RimProjectionStats& rim) {
  return {{"untangled_regions", u.regions},
          {"untangling_rounds_kept", u.improved},
          {"worst_column_before_untangling", u.worstBefore},
          {"rim_nodes", rim.rimNodes},
          {"rim_nodes_on_lateral_faces", rim.onLateralFaces},
          {"rim_columns_left_unprojected", rim.columnsKept}};
}

nlohmann::json rimCap(const RimCapStats& s) {
  return {{"rim_edges", s.rimEdges}, {"capped_edges", s.cappedEdges}, {"columns", s.capColumns}, {"hexes", s.capHexes}};
}

nlohmann::json smoothing(const SmoothingStats& s) {
  return {{"poor_hexes", s.poorHexes},
          {"moves", s.nodesMoved},
          {"worst_before", s.worstBefore},
          {"worst_after", s.worstAfter}};
}

nlohmann::json quadratic(const QuadraticStats& s) {
  return {{"mid_edge_nodes", s.midNodes},
          {"wall_mid_edge_nodes", s.wallNodes},
          {"projected_onto_cad", s.projected},
          {"rim_mid_edge_nodes", s.rimNodes},
          {"rim_projected_onto_lateral_faces", s.rimProjected},
          {"max_projection_move", s.maxProjectionMove}};
}

nlohmann::json validation(const std::vector<ValidationFailure>& failures) {
  nlohmann::json v = {{"passed", failures.empty()}, {"failures", nlohmann::json::array()}};
  for (const ValidationFailure& f : failures) {
    nlohmann::json one = {{"check", f.check}, {"count", f.count}, {"message", f.message}};
    if (f.at) one["at"] = point(*f.at);
    v["failures"].push_back(one);
  }
  return v;
}

void writeMesh(const HexMesh& mesh, const QualityReport& q, const BoundaryCheck& b, double cadVolume,
               const std::vector<ValidationFailure>& failures, nlohmann::json& r) {
  r["order"] = mesh.quadratic() ? 2 : 1;
  r["hexes"] = mesh.hexes.size();
  r["nodes"] = mesh.nodes.size();
  r["layers"] = mesh.layers;
  r["inverted_hexes"] = q.inverted;
  r["worst_hex_at"] = point(q.worstAt);
  r["scaled_jacobian"] = {
      {"min", q.sjMin},
      {"avg", q.sjAvg},
      {"histogram", {{"lo", q.sjHistogram.lo}, {"hi", q.sjHistogram.hi}, {"counts", q.sjHistogram.counts}}}};
  r["aspect_ratio"] = {{"min", q.arMin}, {"avg", q.arAvg}, {"max", q.arMax}};
  r["volume"] = {{"cad", cadVolume}, {"mesh", q.volume}, {"relative_error", (q.volume - cadVolume) / cadVolume}};
  r["boundary"] = {{"faces", b.faces},
                   {"open_edges", b.openEdges},
                   {"non_manifold_edges", b.nonManifoldEdges},
                   {"watertight", b.watertight()},
                   {"euler_characteristic", b.eulerCharacteristic}};
  r["validation"] = validation(failures);
}

}  // namespace hexlayer::report
