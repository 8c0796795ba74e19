#include "pipeline/report.hpp"

namespace hexlayer {
namespace {

nlohmann::json point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

nlohmann::json faces(const FaceCounts& f) { return {{"top", f.top}, {"bottom", f.bottom}, {"lateral", f.lateral}}; }

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

nlohmann::json chordalRim(const RimSnapStats& s) {
  return {{"vertices", s.rimVertices},
          {"moved", s.moved},
          {"spikes_dropped", s.spikesDropped},
          {"largest_move", s.largestMove},
          {"tears_filled", s.tearsFilled}};
}

nlohmann::json chordal(const ChordalRecord& c) {
  return {{"triangles", c.triangles},
          {"quads", c.quads},
          {"vertices", c.vertices},
          {"pinched_facets_dropped", c.pinchedFacetsDropped},
          {"island_facets_dropped", c.islandFacetsDropped},
          {"rim", chordalRim(c.rim)},
          {"fairing_iterations", c.fairingIterations},
          {"knife_edge_facets_dropped", c.knifeFacetsDropped},
          {"sliver_edges", c.sliverEdges}};
}

nlohmann::json smallFeatures(const SmallFeatures& s) {
  return {{"edges_shorter_than_size", s.shortEdges},
          {"narrow_faces", s.narrowFaces},
          {"first_at", point(s.firstAt)},
          {"foot_fillets_smoothed", {{"faces", s.footFillets}, {"largest_radius", s.footFilletRadius}}}};
}

nlohmann::json quadMesh(const QuadMeshCounts& q) {
  return {{"quads", q.quads},
          {"nodes", q.nodes},
          {"triangles_paired", q.pairedTriangles},
          {"triangles_split", q.splitTriangles},
          {"unpaired_triangles", q.holes},
          {"doublets_removed", q.doubletsRemoved},
          {"structured_patches", q.structuredPatches},
          {"pinholes_closed", q.pinholesClosed},
          {"layout", q.layout},
          {"gmsh_tries",
           {{"run", q.tries.run},
            {"failed", q.tries.failed},
            {"timed_out", q.tries.timedOut},
            {"not_started", q.tries.skipped},
            {"same_patches_not_run", q.tries.samePatches},
            {"given_up_on_faired_surfaces", q.tries.givenUp}}},
          {"time_budget_s", q.budgetSeconds}};
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
          {"search_moves", s.searchMoves},
          {"worst_before", s.worstBefore},
          {"worst_after", s.worstAfter}};
}

nlohmann::json sharpEdges(const SharpEdgeStats& s) {
  return {{"edges", s.edges}, {"nodes_moved", s.nodesMoved}, {"nodes_kept", s.nodesKept}};
}

nlohmann::json creaseChains(const CreaseChainStats& s) {
  return {{"chains", s.chains},
          {"dropped", s.dropped},
          {"nodes_moved", s.nodesMoved},
          {"farthest", s.farthest},
          {"worst_quad", s.worstQuad}};
}

nlohmann::json quadratic(const QuadraticStats& s) {
  return {{"mid_edge_nodes", s.midNodes},
          {"wall_mid_edge_nodes", s.wallNodes},
          {"projected_onto_cad", s.projected},
          {"rim_mid_edge_nodes", s.rimNodes},
          {"rim_projected_onto_lateral_faces", s.rimProjected},
          {"max_projection_move", s.maxProjectionMove}};
}

nlohmann::json surfaceGroups(const SurfaceGroupStats& s) {
  return {{"cad_faces", s.cadFaces},
          {"meshed_cad_faces", s.meshedCadFaces},
          {"boundary_nodes", s.boundaryNodes},
          {"nodes_on_several_faces", s.nodesOnSeveralFaces},
          {"element_faces", s.elementFaces},
          {"element_faces_across_cad_edges", s.elementFacesAcrossCadEdges},
          {"nodes_not_put_on_cad", s.nodesNotPutOnCad}};
}

nlohmann::json deviation(const BoundaryDeviation& d) {
  const OffFaceCounts& off = d.offFaceTolerance;
  nlohmann::json r = {{"nodes", d.nodes},
                      {"max", d.max},
                      {"mean", d.mean},
                      {"max_relative", d.maxRelative},
                      {"mean_relative", d.meanRelative},
                      {"off_face_tolerance",
                       {{"wall_corners", off.wallCorners},
                        {"rim_corners", off.rimCorners},
                        {"wall_mid_edge", off.wallMidEdge},
                        {"rim_mid_edge", off.rimMidEdge}}}};
  if (d.worstAt) r["worst_at"] = point(*d.worstAt), r["worst_face"] = d.worstFace;
  return r;
}

nlohmann::json shell(const ShellRecord& s) {
  return {{"element_type", s.order == 2 ? "S8R" : "S4"},
          {"elements", s.elements},
          {"nodes", s.nodes},
          {"thickness", {{"min", s.thicknessMin}, {"median", s.thicknessMedian}, {"max", s.thicknessMax}}},
          {"area",
           {{"shell", s.area}, {"cad_mid_surface", s.cadMidSurfaceArea}, {"relative_error", s.relativeAreaError()}}}};
}

nlohmann::json junctions(const std::vector<JunctionRecord>& list) {
  nlohmann::json all = nlohmann::json::array();
  for (const JunctionRecord& j : list) {
    all.push_back(
        {{"at", point(j.at)}, {"faces", j.faces}, {"area", j.area}, {"volume", j.volume}, {"meshed", j.meshed}});
    if (!j.meshed) continue;
    all.back()["kind"] = j.kind, all.back()["hexes"] = j.hexes;
    all.back()["scaled_jacobian"] = {{"min", j.minScaledJacobian}, {"avg", j.meanScaledJacobian}};
  }
  return all;
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

nlohmann::json boundary(const MeshMeasures& m) {
  const BoundaryCheck& b = m.boundary;
  return {{"faces", b.faces},
          {"open_edges", b.openEdges},
          {"non_manifold_edges", b.nonManifoldEdges},
          {"watertight", b.watertight()},
          {"euler_characteristic", b.eulerCharacteristic},
          {"cad_euler_characteristic", m.cadEuler},
          {"same_topology_as_cad", m.sameTopologyAsCad()}};
}

// The mesh's own numbers, the keys of a report of one solid and of several.
nlohmann::json measures(const MeshMeasures& m) {
  const QualityReport& q = m.quality;
  const Histogram& h = q.sjHistogram;
  return {{"order", m.order},
          {"hexes", m.hexes},
          {"nodes", m.nodes},
          {"layers", m.layers},
          {"inverted_hexes", q.inverted},
          {"worst_hex_at", point(q.worstAt)},
          {"scaled_jacobian",
           {{"min", q.sjMin}, {"avg", q.sjAvg}, {"histogram", {{"lo", h.lo}, {"hi", h.hi}, {"counts", h.counts}}}}},
          {"aspect_ratio", {{"min", q.arMin}, {"avg", q.arAvg}, {"max", q.arMax}}},
          {"volume", {{"cad", m.cadVolume}, {"mesh", q.volume}, {"relative_error", m.relativeVolumeError()}}},
          {"boundary", boundary(m)},
          {"validation", validation(m.failures)}};
}

// Every stage's time and peak memory.
void stageTimes(const std::map<std::string, StageTime>& stages, nlohmann::json& r) {
  r["timings_s"] = nlohmann::json::object();
  r["peak_memory_mib"] = nlohmann::json::object();
  for (const auto& [name, t] : stages) r["timings_s"][name] = t.seconds, r["peak_memory_mib"][name] = t.peakMemoryMiB;
}

// The keys of one solid's stages.
void stages(const MeshReport& s, nlohmann::json& r) {
  stageTimes(s.stages, r);
  r["faces_split"] = s.facesSplit;
  r["junctions"] = junctions(s.junctions);
  r["thickness"] = s.thickness;
  r["faces"] = faces(s.faces);
  r["memory_estimate"] = memory(s.memory);
  r["bubbles"] = s.bubbles;
  r["tets"] = tets(s.tetsDropped, s.tetsKept);
  r["tet_classes"] = s.tetClasses;
  r["chordal_surface"] = chordal(s.chordal);
  r["size"] = s.size;
  r["size_source"] = s.sizeSource;
  r["sizing"] = s.sizing;
  r["small_features"] = smallFeatures(s.smallFeatures);
  r["quad_mesh"] = quadMesh(s.quadMesh);
  r["sweep"] = sweep(s.untangled, s.rimProjection);
  r["rim_cap"] = rimCap(s.rimCap);
  r["smoothing"] = smoothing(s.smoothing);
  r["sharp_edges"] = sharpEdges(s.sharpEdges);
  if (s.creaseChains.chains + s.creaseChains.dropped > 0) r["crease_chains"] = creaseChains(s.creaseChains);
  if (s.quadratic) r["quadratic"] = quadratic(*s.quadratic);
  r["surface_groups"] = surfaceGroups(s.surfaceGroups);
  r["boundary_deviation"] = deviation(s.boundaryDeviation);
  r["volume"]["junctions_left_out"] = s.junctionsLeftOut;  // "cad" is the part's volume without them
  if (s.aspectRatioHit) r["aspect_ratio_hit"] = *s.aspectRatioHit;
}

}  // namespace

nlohmann::json toJson(const MeshReport& report) {
  nlohmann::json r = measures(report.mesh);
  if (report.shell) r["shell"] = shell(*report.shell);
  if (report.solids.empty()) {
    stages(report, r);
    return r;
  }
  r["solids"] = nlohmann::json::array();
  for (const MeshReport& one : report.solids) r["solids"].push_back(toJson(one));
  return r;
}

}  // namespace hexlayer
