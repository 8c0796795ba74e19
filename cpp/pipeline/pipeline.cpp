#include "pipeline/pipeline.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "bubbles/bubble_packing.hpp"
#include "chordal/chordal_rim.hpp"
#include "chordal/chordal_surface.hpp"
#include "core/append.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "geometry/cad_faces.hpp"
#include "geometry/mixed_faces.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"
#include "pipeline/report.hpp"
#include "pipeline/surface_groups.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "quadmesh/quad_stage.hpp"
#include "quality/quality.hpp"
#include "quality/validation.hpp"
#include "sweep/quadratic.hpp"
#include "sweep/rim_cap.hpp"
#include "sweep/rim_projection.hpp"
#include "sweep/smoothing.hpp"
#include "sweep/sweep.hpp"
#include "sweep/sweep_to_walls.hpp"
#include "tets/tet_mesh.hpp"

namespace hexlayer {
namespace {

constexpr int kMaxLayers = 64;
constexpr int kMaxSplitRounds = 3;  // rounds of splitting faces that are partly wall, partly rim
constexpr double kDefaultSizeOverThickness = 1.0;
constexpr double kMaxAutoQuads = 250000;
// How far a rim node may move onto the rim faces, in walls: half of a rim cut obliquely 3.2 walls wide
// (wall_sides.hpp), with room.
constexpr double kRimReach = 1.6;

// Runs one stage, records its wall time in report["timings_s"][name] and the process's peak memory
// at its end in report["peak_memory_mib"][name], and reports progress.
class StageClock {
 public:
  StageClock(nlohmann::json& report, const MeshOptions& options) : report_(report), options_(options) {}
  template <class F>
  auto run(const std::string& name, F&& stage) {
    const auto start = std::chrono::steady_clock::now();
    auto result = stage();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report_["timings_s"][name] = s;
    report_["peak_memory_mib"][name] = peakMemoryMiB();
    if (options_.progress) {
      std::ostringstream line;
      line << name << ": " << std::fixed << std::setprecision(2) << s << " s";
      options_.progress(line.str());
    }
    return result;
  }

 private:
  nlohmann::json& report_;
  const MeshOptions& options_;
};

// The quad size as far as it is known before the chordal surface: the given one, A layer thicknesses
// (thickness / layers) with --aspect A, else the wall thickness (bending-accurate C3D8I with 2 layers).
double plannedSize(const MeshOptions& o, const WallSides& sides) {
  return o.size > 0     ? o.size
         : o.aspect > 0 ? o.aspect * sides.thickness / o.layers
                        : kDefaultSizeOverThickness * sides.thickness;
}

// The quad size used: the planned one, made coarser by default if the part would need too many quads.
double chooseSize(const MeshOptions& o, const WallSides& sides, double chordalArea, nlohmann::json& report) {
  const double planned = plannedSize(o, sides);
  if (o.size > 0 || o.aspect > 0) {
    report["size_source"] = o.size > 0 ? "given" : "aspect x wall thickness / layers";
    return planned;
  }
  report["size_source"] = "auto: wall thickness (at most " + std::to_string(int(kMaxAutoQuads)) + " quads)";
  return std::max(planned, std::sqrt(chordalArea / kMaxAutoQuads));
}

// Refuses, before meshing, a size that would need more memory than the machine has (estimateMemory: quads
// from the top wall's area).
// unit: pipeline lengths per input length (CadSolid::unit), for the message.
void requireMemory(const MeshOptions& o, const WallSides& sides, double unit, nlohmann::json& r) {
  double topArea = 0;
  for (const FaceSide& f : sides.faces) topArea += f.side == Side::Top ? f.area : 0;
  const double size = plannedSize(o, sides);
  const MemoryEstimate m = estimateMemory(topArea, size, o.layers, o.order, machineBytes());
  r["memory_estimate"] = report::memory(m);
  if (m.fits()) return;
  std::ostringstream msg;
  msg << std::setprecision(3) << "quad size " << size / unit << " would need about " << m.quads << " quads, " << m.hexes
      << " hexes and " << m.bytes / 1e9 << " GB of memory (estimated), more than this machine's "
      << m.machineBytes / 1e9 << " GB: choose a larger --size (or --aspect) or fewer --layers";
  throw usageError(msg.str());
}

// Faces that are partly wall and partly rim split into pieces that are one or the other (mixed_faces.hpp), the
// sides measured again; returns how many were split.
std::size_t splitMixedFaces(CadSolid& cad, WallSides& sides) {
  std::size_t split = 0;
  for (int round = 0; round < kMaxSplitRounds; ++round) {  // a skin over a wall, its rim and the other wall: twice
    const std::vector<FaceSplit> splits = findMixedFaces(cad, sides);
    if (splits.empty()) break;
    CadSolid pieces = splitFaces(cad, splits);
    if (pieces.faces.Extent() == 0) break;
    cad = std::move(pieces);
    sides = classifyWallSides(cad);
    split += splits.size();
  }
  return split;
}

std::vector<std::string> faceNames(const CadSolid& cad, const Sheet& s) {
  std::vector<std::string> names;  // a split face's pieces once
  for (int f : s.faces)
    if (const std::string name = inputFaceName(cad, f); std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(name);
  return names;
}

// unit: pipeline lengths per input length (CadSolid::unit); the centre is given in the input's units.
std::string describeSheet(const CadSolid& cad, const Sheet& s) {
  const double unit = cad.unit;
  std::ostringstream out;
  const Vec3 c = s.centre / unit;
  out << "(" << c.x() << ", " << c.y() << ", " << c.z() << ") [";
  const std::vector<std::string> names = faceNames(cad, s);
  for (std::size_t k = 0; k < names.size(); ++k) out << (k ? " " : "") << names[k];
  out << "]";
  return out.str();
}

nlohmann::json junctionReport(const CadSolid& cad, const Sheet& s) {
  return {{"at", {s.centre.x(), s.centre.y(), s.centre.z()}},
          {"faces", faceNames(cad, s)},
          {"area", s.area},
          {"volume", s.volume}};
}

// Ribs, bosses and flanges standing on the sheet (T-junctions, where the chordal surface would be
// non-manifold), found two ways: sheets that meet only along concave edges, and walls whose rays cross to
// a wall on their own side. Refused, or left out with dropJunctions; they are listed in the report.
// Returns the estimated volume left out.
double handleJunctions(const CadSolid& cad, WallSides& sides, bool drop, nlohmann::json& report) {
  report["junctions"] = nlohmann::json::array();
  double leftOut = 0;
  if (!sides.ownSideFaces.empty()) {
    if (!drop) throw ownSideError(cad, sides);
    const Sheet branch = sheetOf(cad, sides, sides.ownSideFaces);
    report["junctions"].push_back(junctionReport(cad, branch));
    leftOut += branch.volume;
    for (int f : sides.ownSideFaces) sides.faces[f].side = Side::Lateral;
  }
  const std::vector<Sheet> sheets = findSheets(cad, sides);
  for (std::size_t s = 1; s < sheets.size(); ++s) report["junctions"].push_back(junctionReport(cad, sheets[s]));
  if (sheets.size() < 2) return leftOut;
  if (drop) {
    keepFirstSheet(sheets, sides);
    for (std::size_t s = 1; s < sheets.size(); ++s) leftOut += sheets[s].volume;
    return leftOut;
  }
  std::ostringstream msg;
  msg << "T-junction: " << sheets.size() - 1 << " sheet(s) (rib, boss or flange) stand on the main sheet, where the "
      << "chordal surface would be non-manifold, which this method does not mesh: " << describeSheet(cad, sheets[1]);
  for (std::size_t s = 2; s < std::min<std::size_t>(sheets.size(), 4); ++s)
    msg << ", " << describeSheet(cad, sheets[s]);
  if (sheets.size() > 4) msg << ", ...";
  msg << "; --drop-junctions meshes the main sheet without them";
  throw geometryError(msg.str());
}

// Order 2: 20-node hexes whose wall mid-edge nodes lie on the CAD walls (π_t, π_b of §3).
nlohmann::json makeQuadratic(HexMesh& mesh, const WallProjector& walls) {
  return report::quadratic(addMidEdgeNodes(mesh, [&](Side side, const Vec3& p) { return walls.project(side, p); }));
}

// Writes the quality numbers into the report and returns the scaled Jacobian of every hex.
std::vector<double> reportQuality(const HexMesh& mesh, double cadVolume, nlohmann::json& r) {
  QualityReport q = measureQuality(mesh);  // on the corners, also for 20-node hexes
  const BoundaryCheck b = checkBoundary(mesh);
  report::writeMesh(mesh, q, b, cadVolume, validateMesh(mesh, q, b, cadVolume), r);
  return std::move(q.scaledJacobian);
}

// A mesh that failed a validation check is not handed on, unless the caller forces it.
void enforceValidation(const nlohmann::json& r, const MeshOptions& o) {
  if (o.force || r["validation"]["passed"].get<bool>()) return;
  std::string message = "the mesh failed validation, nothing written (--force writes it anyway):";
  for (const auto& f : r["validation"]["failures"]) message += " " + f["message"].get<std::string>() + ";";
  message.back() = '.';
  throw validationError(message);
}

// Share of the hexes whose aspect ratio is within 10 % of the requested one (Figure 11).
double aspectHit(const HexMesh& mesh, double aspect) {
  std::size_t hit = 0;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    hit += std::abs(hexAspectRatio(hexCorners(mesh, h)) - aspect) <= 0.1 * aspect;
  return mesh.hexes.empty() ? 0 : static_cast<double>(hit) / mesh.hexes.size();
}

// A mesh with a hole the part does not have (or without one it has) differs from the CAD in the
// Euler characteristic of its boundary.
void compareTopology(nlohmann::json& r, long cadEuler) {
  r["boundary"]["cad_euler_characteristic"] = cadEuler;
  r["boundary"]["same_topology_as_cad"] = r["boundary"]["euler_characteristic"].get<long>() == cadEuler;
}

std::vector<NodeSet> surfaceNodeSets(const HexMesh& mesh) {
  std::vector<NodeSet> sets{{"TOP", {}}, {"BOTTOM", {}}, {"RIM", {}}};
  for (size_t i = 0; i < mesh.nodes.size(); ++i) {
    const bool wall = mesh.nodeOnRim[i] != kRimCap;  // a cap's nodes lie on the rim in every layer
    if (wall && mesh.nodeLayer[i] == mesh.layers) sets[0].nodes.push_back(static_cast<int>(i));
    if (wall && mesh.nodeLayer[i] == 0) sets[1].nodes.push_back(static_cast<int>(i));
    if (mesh.nodeOnRim[i]) sets[2].nodes.push_back(static_cast<int>(i));
  }
  return sets;
}

// The groups of the pieces of a split face merged into the input face's, one group per input face in order.
std::vector<SurfaceGroup> groupsOfInputFaces(std::vector<SurfaceGroup> pieces, const CadSolid& cad) {
  std::vector<SurfaceGroup> merged(*std::max_element(cad.inputFace.begin(), cad.inputFace.end()) + 1);
  for (std::size_t f = 0; f < merged.size(); ++f) merged[f].name = "Face" + std::to_string(f + 1);
  for (std::size_t f = 0; f < pieces.size(); ++f) {
    SurfaceGroup& to = merged[cad.inputFace[f]];
    to.nodes.insert(to.nodes.end(), pieces[f].nodes.begin(), pieces[f].nodes.end());
    to.hexFaces.insert(to.hexFaces.end(), pieces[f].hexFaces.begin(), pieces[f].hexFaces.end());
  }
  for (SurfaceGroup& g : merged) {
    std::sort(g.nodes.begin(), g.nodes.end());
    g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
    std::sort(g.hexFaces.begin(), g.hexFaces.end(), [](const HexFace& a, const HexFace& b) {
      return std::make_pair(a.hex, a.localFace) < std::make_pair(b.hex, b.localFace);
    });
  }
  return merged;
}

// The mesh's boundary on the CAD faces (FreeCAD's FaceN): surface groups and boundary deviation in the report.
std::vector<SurfaceGroup> groupByCadFace(HexMesh& mesh, const CadSolid& cad, const WallProjector& walls,
                                         nlohmann::json& r) {
  const std::vector<BoundaryFace> quads = boundaryFaces(mesh);  // sorted by hex, then local face
  const std::vector<int> boundary = boundaryNodes(mesh, quads);
  const std::size_t unplaced = faceUnplacedNodes(mesh, walls, boundary);
  SurfaceGroups s = surfaceGroups(mesh, CadFaces(cad), quads, boundary);
  r["surface_groups"] = std::move(s.surfaceReport);
  r["surface_groups"]["nodes_not_put_on_cad"] = unplaced;
  r["boundary_deviation"] = std::move(s.deviationReport);
  if (cad.inputFace.empty()) return std::move(s.groups);
  // Faces split into pieces (mixed_faces.hpp): the input's faces, as the user's part has them.
  for (int& f : mesh.nodeFace) f = inputFaceOf(cad, f);
  return groupsOfInputFaces(std::move(s.groups), cad);
}

// The chordal surface and quad mesh of one more solid, their ids after those already there (-1 stays).
void appendStages(MeshResult& all, const MeshResult& part) {
  ChordalSurface& c = all.chordalSurface;
  appendCells(c.facets, part.chordalSurface.facets, static_cast<int>(c.vertices.size()));
  c.vertices.insert(c.vertices.end(), part.chordalSurface.vertices.begin(), part.chordalSurface.vertices.end());
  QuadMesh& q = all.quadMesh;
  appendCells(q.quads, part.quadMesh.quads, static_cast<int>(q.nodes.size()));
  q.nodes.insert(q.nodes.end(), part.quadMesh.nodes.begin(), part.quadMesh.nodes.end());
}

// Several solids are separate bodies (nodes where two touch are not shared): their validations,
// each failure prefixed with its solid.
nlohmann::json validationOfSolids(const nlohmann::json& solids) {
  nlohmann::json v = {{"passed", true}, {"failures", nlohmann::json::array()}};
  for (std::size_t i = 0; i < solids.size(); ++i)
    for (nlohmann::json f : solids[i]["validation"]["failures"]) {
      f["message"] = "solid " + std::to_string(i + 1) + ": " + f["message"].get<std::string>();
      v["passed"] = false;
      v["failures"].push_back(f);
    }
  return v;
}

// The options' lengths in the pipeline's units (CadSolid::unit per input length).
MeshOptions inPipelineUnits(MeshOptions o, double unit) {
  o.size *= unit, o.minSize *= unit, o.maxSize *= unit;
  return o;
}

// The mesh, the chordal surface, the quad mesh and the report's lengths so far back in the input's units.
void toInputUnits(MeshResult& result, nlohmann::json& r, double unit) {
  if (unit == 1) return;
  for (Vec3& p : result.mesh.nodes) p /= unit;
  for (Vec3& p : result.chordalSurface.vertices) p /= unit;
  for (double& radius : result.chordalSurface.radius) radius /= unit;
  for (Vec3& p : result.quadMesh.nodes) p /= unit;
  auto length = [&](nlohmann::json& j, double power) {
    if (j.is_number())
      j = j.get<double>() / std::pow(unit, power);
    else if (j.is_array())
      for (auto& x : j) x = x.get<double>() / unit;  // a point
  };
  length(r["thickness"], 1);
  length(r["size"], 1);
  length(r["small_features"]["first_at"], 1);
  for (auto& j : r["junctions"]) length(j["at"], 1), length(j["area"], 2), length(j["volume"], 3);
  nlohmann::json& deviation = r["boundary_deviation"];
  for (const char* key : {"max", "mean", "worst_at"})
    if (deviation.contains(key)) length(deviation[key], 1);
  if (r.contains("quadratic")) length(r["quadratic"]["max_projection_move"], 1);
}

}  // namespace

void validateOptions(const MeshOptions& o) {
  if (o.layers < 1 || o.layers > kMaxLayers)
    throw usageError("--layers must be between 1 and " + std::to_string(kMaxLayers) + ", got " +
                     std::to_string(o.layers));
  if (!(o.size >= 0) || !std::isfinite(o.size)) throw usageError("--size must be a positive length");
  if (o.order != 1 && o.order != 2) throw usageError("--order must be 1 or 2, got " + std::to_string(o.order));
  if (o.sizing != "uniform" && o.sizing != "adaptive")
    throw usageError("--sizing must be 'uniform' or 'adaptive', got '" + o.sizing + "'");
  if (!(o.aspect >= 0) || !std::isfinite(o.aspect)) throw usageError("--aspect must be a positive ratio (0 = off)");
  if (o.size > 0 && o.aspect > 0) throw usageError("give --size or --aspect, not both");
  if (!(o.minSize >= 0) || !(o.maxSize >= 0) || !std::isfinite(o.minSize) || !std::isfinite(o.maxSize) ||
      (o.maxSize > 0 && o.minSize > o.maxSize))
    throw usageError("--min-size and --max-size must be lengths with --min-size <= --max-size");
}

MeshResult meshSolid(const TopoDS_Solid& solid, const MeshOptions& given) {
  validateOptions(given);
  MeshResult result;
  nlohmann::json& r = result.report;
  StageClock clock(r, given);
  // Every stage up to the surface groups works on the part scaled to one size (normalizingUnit).
  CadSolid cad = clock.run("geometry", [&] { return prepareSolid(solid, normalizingUnit(solid)); });
  const MeshOptions o = inPipelineUnits(given, cad.unit);
  WallSides sides = clock.run("wall_sides", [&] { return classifyWallSides(cad); });
  r["faces_split"] = clock.run("mixed_faces", [&] { return splitMixedFaces(cad, sides); });
  const double leftOut = handleJunctions(cad, sides, o.dropJunctions, r);
  r["thickness"] = sides.thickness;
  r["faces"] = report::faces(sides);
  requireMemory(o, sides, cad.unit, r);
  const auto nodes = clock.run("bubbles", [&] { return packBubbles(cad, sides, BubbleOptions{}); });
  r["bubbles"] = nodes.size();
  TetMesh tets = clock.run("tets", [&] { return delaunayTets(nodes); });
  const TetFilterCounts dropped = clock.run("tet_filter", [&] { return keepSpanningTetsInside(tets, cad); });
  r["tets"] = report::tets(dropped, tets.tets.size());
  ChordalSurface cut = clock.run("chordal_surface", [&] { return buildChordalSurface(tets, cad.unit); });
  r["tet_classes"] = classifyTets(tets);
  r["chordal_surface"] = report::chordal(cut);
  const WallProjector walls(cad, sides);
  const RimSnapStats snap = clock.run("chordal_rim", [&] {
    return snapRimBetweenWallEdges(
        cut, [&](const Vec3& p) { return walls.rimMiddle(p); }, sides.thickness);
  });
  r["chordal_surface"]["rim"] = report::chordalRim(snap, cad.unit);
  const double size = chooseSize(o, sides, chordalArea(cut), r);
  r["size"] = size;
  r["sizing"] = o.sizing;
  const SmallFeatures small = findSmallFeatures(cad, sides, size);
  r["small_features"] = report::smallFeatures(small);
  QuadStageOptions qo;
  qo.size = size, qo.adaptive = o.sizing == "adaptive", qo.sizing = {size, o.minSize, o.maxSize};
  qo.knifeEdges = !sides.knifeEdges.empty(), qo.progress = o.progress;
  QuadStage stage = clock.run("quad_mesh", [&] { return meshFairedChordalSurface(cut, tets, qo); });
  const QuadMesh& quads = stage.quads;
  r["chordal_surface"]["fairing_iterations"] = stage.fairingIterations;
  r["chordal_surface"]["knife_edge_facets_dropped"] = stage.knifeFacets;
  r["quad_mesh"] = report::quadMesh(quads);
  const ChordalLocator locator(stage.chordal);
  SweepResult swept = clock.run("sweep", [&] { return sweepToWalls(quads, locator, cad, sides, o.layers); });
  result.mesh = std::move(swept.mesh);
  const RimProjectionStats rim =
      clock.run("rim", [&] { return projectRim(result.mesh, cad, sides, walls, kRimReach * sides.thickness); });
  r["sweep"] = report::sweep(swept.untangled, rim);
  const RimCapStats cap = clock.run("rim_cap", [&] { return capRims(result.mesh, cad, sides, walls); });
  r["rim_cap"] = report::rimCap(cap);
  const SmoothingStats smooth = clock.run("smoothing", [&] { return smoothPoorHexes(result.mesh, walls, sides); });
  r["smoothing"] = report::smoothing(smooth);
  if (o.order == 2) r["quadratic"] = clock.run("quadratic", [&] { return makeQuadratic(result.mesh, walls); });
  result.surfaceGroups = clock.run("surface_groups", [&] { return groupByCadFace(result.mesh, cad, walls, r); });
  result.chordalSurface = std::move(stage.chordal);
  result.quadMesh = std::move(stage.quads);
  // From here on, the input's units.
  toInputUnits(result, r, cad.unit);
  const double unit3 = cad.unit * cad.unit * cad.unit;
  result.scaledJacobian =
      clock.run("quality", [&] { return reportQuality(result.mesh, (cad.volume - leftOut) / unit3, r); });
  r["volume"]["junctions_left_out"] = leftOut / unit3;  // "cad" is the part's volume without them
  compareTopology(r, eulerCharacteristic(cad));
  if (o.aspect > 0) r["aspect_ratio_hit"] = aspectHit(result.mesh, o.aspect);
  result.nodeSets = surfaceNodeSets(result.mesh);
  enforceValidation(r, o);
  return result;
}

MeshResult meshFile(const std::string& path, const MeshOptions& o) {
  validateOptions(o);
  const std::vector<TopoDS_Solid> solids = readSolids(path);
  if (solids.size() == 1) return meshSolid(solids[0], o);
  MeshResult all;  // several solids: mesh each, one report per solid plus the totals
  double cad = 0;
  for (size_t i = 0; i < solids.size(); ++i) {
    const std::string which = "solid " + std::to_string(i + 1) + " of " + std::to_string(solids.size());
    if (o.progress) o.progress(which);
    MeshResult one;
    try {
      one = meshSolid(solids[i], o);
    } catch (const Error& e) {
      throw Error(e.code(), which + ": " + e.what());
    }
    cad += one.report["volume"]["cad"].get<double>();
    all.report["solids"].push_back(one.report);
    appendSurfaceGroups(all.surfaceGroups, one.surfaceGroups, static_cast<int>(all.mesh.nodes.size()),
                        static_cast<int>(all.mesh.hexes.size()));
    appendHexMesh(all.mesh, one.mesh);
    appendStages(all, one);
  }
  all.scaledJacobian = reportQuality(all.mesh, cad, all.report);
  long cadEuler = 0;
  for (const auto& one : all.report["solids"]) cadEuler += one["boundary"]["cad_euler_characteristic"].get<long>();
  compareTopology(all.report, cadEuler);
  all.report["validation"] = validationOfSolids(all.report["solids"]);
  all.nodeSets = surfaceNodeSets(all.mesh);
  return all;
}

}  // namespace hexlayer
