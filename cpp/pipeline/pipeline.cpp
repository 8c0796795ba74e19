#include "pipeline/pipeline.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <future>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "bubbles/bubble_packing.hpp"
#include "chordal/chordal_rim.hpp"
#include "chordal/chordal_surface.hpp"
#include "core/append.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "geometry/boundary_triangles.hpp"
#include "geometry/butt_joints.hpp"
#include "geometry/cad_faces.hpp"
#include "geometry/column_piece.hpp"
#include "geometry/foot_fillets.hpp"
#include "geometry/junction_cut.hpp"
#include "geometry/mixed_faces.hpp"
#include "geometry/sheet_junctions.hpp"
#include "geometry/wall_projector.hpp"
#include "geometry/wall_sides.hpp"
#include "pipeline/junction_mesh.hpp"
#include "pipeline/mesh_report.hpp"
#include "pipeline/shell_mesh.hpp"
#include "pipeline/surface_groups.hpp"
#include "quadmesh/column_foot.hpp"
#include "quadmesh/crease_chains.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "quadmesh/quad_stage.hpp"
#include "quadmesh/quad_strips.hpp"
#include "quality/quality.hpp"
#include "quality/validation.hpp"
#include "sweep/column_sweep.hpp"
#include "sweep/quadratic.hpp"
#include "sweep/rim_cap.hpp"
#include "sweep/rim_projection.hpp"
#include "sweep/sharp_edges.hpp"
#include "sweep/smoothing.hpp"
#include "sweep/sweep.hpp"
#include "sweep/sweep_to_walls.hpp"
#include "tets/tet_mesh.hpp"

namespace hexlayer {
namespace {

constexpr int kMaxLayers = 64;
constexpr double kDefaultSizeOverThickness = 1.0;
constexpr double kMaxAutoQuads = 250000;
// How far a rim node may move onto the rim faces, in walls: half of a rim cut obliquely 3.2 walls wide
// (wall_sides.hpp), with room.
constexpr double kRimReach = 1.6;
// A sweep column's end this far from the wall's foot node on it, in walls, is put on it before the smoothing
// (placeFootEnds): half the reach the join takes (meshPiece's wallShare, half a wall); a nearer one is left to the
// join.
constexpr double kFootEndNear = 0.25;
// Tears of the chordal surface (fillTears) are rim loops no longer than this many walls.
constexpr double kMaxTear = 5;

// Runs one stage, records its wall time and the process's peak memory at its end in stages[name], and reports
// its start and end as progress.
class StageClock {
 public:
  StageClock(std::map<std::string, StageTime>& stages, const MeshOptions& options)
      : stages_(stages), options_(options) {}
  template <class F>
  auto run(const std::string& name, F&& stage) {
    reportProgress(options_.progress, progressStart(name));
    const auto start = std::chrono::steady_clock::now();
    auto result = stage();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stages_[name] = {s, peakMemoryMiB()};
    reportProgress(options_.progress, progressFinish(name, s));
    return result;
  }

 private:
  std::map<std::string, StageTime>& stages_;
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
// [out] source: how it was chosen.
double chooseSize(const MeshOptions& o, const WallSides& sides, double chordalArea, std::string& source) {
  const double planned = plannedSize(o, sides);
  if (o.size > 0 || o.aspect > 0) {
    source = o.size > 0 ? "given" : "aspect x wall thickness / layers";
    return planned;
  }
  source = "auto: wall thickness (at most " + std::to_string(int(kMaxAutoQuads)) + " quads)";
  return std::max(planned, std::sqrt(chordalArea / kMaxAutoQuads));
}

// Refuses, before meshing, a size that would need more memory than the machine has (estimateMemory: quads
// from the top wall's area); returns the estimate.
// unit: pipeline lengths per input length (CadSolid::unit), for the message.
MemoryEstimate requireMemory(const MeshOptions& o, const WallSides& sides, double unit) {
  double topArea = 0;
  for (const FaceSide& f : sides.faces) topArea += f.side == Side::Top ? f.area : 0;
  const double size = plannedSize(o, sides);
  const MemoryEstimate m = estimateMemory(topArea, size, o.layers, o.order, machineBytes());
  if (m.fits()) return m;
  std::ostringstream msg;
  msg << std::setprecision(3) << "quad size " << size / unit << " would need about " << m.quads << " quads, " << m.hexes
      << " hexes and " << m.bytes / 1e9 << " GB of memory (estimated), more than this machine's "
      << m.machineBytes / 1e9 << " GB: choose a larger --size (or --aspect) or fewer --layers";
  throw usageError(msg.str());
}

// The guard again once the quads are made, with adaptive sizing (its sizes run down to --min-size, where the planned
// size under-counts them), before the sweep makes the hexes; returns the estimate.
MemoryEstimate requireMemoryOfQuads(const MeshOptions& o, std::size_t quads) {
  const MemoryEstimate m = estimateMemoryOfQuads(static_cast<double>(quads), o.layers, o.order, machineBytes());
  if (m.fits()) return m;
  std::ostringstream msg;
  msg << std::setprecision(3) << "adaptive sizing made " << m.quads << " quads: " << m.hexes
      << " hexes would need about " << m.bytes / 1e9 << " GB of memory (estimated), more than this machine's "
      << m.machineBytes / 1e9 << " GB: choose a larger --min-size or --size, or fewer --layers";
  throw usageError(msg.str());
}

std::vector<std::string> faceNames(const CadSolid& cad, const Sheet& s) {
  std::vector<std::string> names;  // a split face's pieces once
  for (int f : s.faces)
    if (const std::string name = inputFaceName(cad, f); std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(name);
  return names;
}

// The sheet's place (in the input's units) and faces.
std::string describeSheet(const CadSolid& cad, const Sheet& s) {
  std::ostringstream out;
  out << sheetPlace(cad, s) << " [";
  const std::vector<std::string> names = faceNames(cad, s);
  for (std::size_t k = 0; k < names.size(); ++k) out << (k ? " " : "") << names[k];
  out << "]" << (s.column ? " (a column)" : "");
  return out.str();
}

// The refusal of sheets standing on the main sheet (sheets[1..]), naming them; `why` (may be empty): what junction
// meshing could not do with them.
Error junctionRefusal(const CadSolid& cad, const std::vector<Sheet>& sheets, const std::string& why) {
  std::ostringstream msg;
  const std::string prefix = "T-junction: ";
  const auto columns = std::count_if(sheets.begin() + 1, sheets.end(), [](const Sheet& s) { return s.column; });
  msg << prefix << sheets.size() - 1 << " sheet(s) (rib, boss or flange";
  if (columns > 0) msg << "; " << columns << " of them a column: a pin, post, block or pad";
  msg << ") stand on the main sheet, where the chordal surface would be non-manifold, which this method does not mesh";
  if (!why.empty())
    msg << " (junction meshing: " << (why.rfind(prefix, 0) == 0 ? why.substr(prefix.size()) : why) << ")";
  msg << ": " << describeSheet(cad, sheets[1]);
  for (std::size_t s = 2; s < std::min<std::size_t>(sheets.size(), 4); ++s)
    msg << ", " << describeSheet(cad, sheets[s]);
  if (sheets.size() > 4) msg << ", ...";
  msg << "; --drop-junctions meshes the main sheet without them";
  return geometryError(msg.str());
}

JunctionRecord junctionRecord(const CadSolid& cad, const Sheet& s) {
  JunctionRecord j;
  j.at = s.centre, j.faces = faceNames(cad, s), j.area = s.area, j.volume = s.volume;
  return j;
}

// The record of piece w: its sheet's, or where the cut parted the sheet (a boss through the plate), the piece's centre
// of mass and its share (by volume) of the sheet's area and volume. [in] cad, sheets, cut, w.
JunctionRecord pieceRecord(const CadSolid& cad, const std::vector<Sheet>& sheets, const JunctionCut& cut, int w) {
  JunctionRecord j = junctionRecord(cad, sheets[cut.sheetOf[w]]);
  if (std::count(cut.sheetOf.begin(), cut.sheetOf.end(), cut.sheetOf[w]) < 2) return j;  // the sheet is one piece
  double all = 0;
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
    if (cut.sheetOf[p] == cut.sheetOf[w]) all += volumeOf(cut.pieces[p]).first;
  const auto [volume, centre] = volumeOf(cut.pieces[w]);
  j.at = centre, j.area *= volume / all, j.volume *= volume / all;
  return j;
}

// Ribs, bosses and flanges standing on the sheet (T-junctions, where the chordal surface would be
// non-manifold), found two ways: sheets that meet only along concave edges, and walls whose rays cross to
// a wall on their own side. Refused, or left out with dropJunctions. [in,out] sides: the junctions' faces made
// lateral; [out] junctions: each listed. Returns the estimated volume left out.
double handleJunctions(const CadSolid& cad, WallSides& sides, bool drop, std::vector<JunctionRecord>& junctions) {
  double leftOut = 0;
  if (!sides.ownSideFaces.empty()) {
    if (!drop) throw ownSideError(cad, sides);
    const Sheet branch = sheetOf(cad, sides, sides.ownSideFaces);
    junctions.push_back(junctionRecord(cad, branch));
    leftOut += branch.volume;
    for (int f : sides.ownSideFaces) sides.faces[f].side = Side::Lateral;
  }
  const std::vector<Sheet> sheets = findSheets(cad, sides);
  for (std::size_t s = 1; s < sheets.size(); ++s) junctions.push_back(junctionRecord(cad, sheets[s]));
  if (sheets.size() < 2) return leftOut;
  if (drop) {
    keepFirstSheet(sheets, sides);
    for (std::size_t s = 1; s < sheets.size(); ++s) leftOut += sheets[s].volume;
    return leftOut;
  }
  throw junctionRefusal(cad, sheets, "");
}

// Order 2: 20-node hexes whose wall mid-edge nodes lie on the CAD walls (π_t, π_b of §3).
QuadraticStats makeQuadratic(HexMesh& mesh, const WallProjector& walls) {
  return addMidEdgeNodes(mesh, [&](Side side, const Vec3& p) { return walls.project(side, p); });
}

// The mesh's counts, quality (on the corners, also for 20-node hexes) and boundary, without the CAD's numbers
// and validation. [out] scaledJacobian: of every hex.
MeshMeasures measureMesh(const HexMesh& mesh, std::vector<double>& scaledJacobian) {
  MeshMeasures m;
  m.order = mesh.quadratic() ? 2 : 1;
  m.hexes = mesh.hexes.size(), m.nodes = mesh.nodes.size(), m.layers = mesh.layers;
  m.quality = measureQuality(mesh);
  m.boundary = checkBoundary(mesh);
  scaledJacobian = std::move(m.quality.scaledJacobian);
  m.quality.scaledJacobian.clear();
  return m;
}

// One solid's mesh measured and validated against the CAD's volume and Euler characteristic (its topology: not when
// junctions were left out, which may open or close holes). [out] scaledJacobian: of every hex.
MeshMeasures measureSolidMesh(const HexMesh& mesh, double cadVolume, long cadEuler, bool junctionsLeftOut,
                              std::vector<double>& scaledJacobian) {
  MeshMeasures m = measureMesh(mesh, scaledJacobian);
  m.cadVolume = cadVolume, m.cadEuler = cadEuler;
  m.failures = validateMesh(mesh, m.quality, m.boundary, cadVolume,
                            junctionsLeftOut ? std::nullopt : std::optional<long>(cadEuler));
  return m;
}

// A mesh that failed a validation check is not handed on, unless the caller forces it.
void enforceValidation(const MeshMeasures& m, const MeshOptions& o) {
  if (o.force || m.passed()) return;
  std::string message = "the mesh failed validation, nothing written (--force writes it anyway):";
  for (const ValidationFailure& f : m.failures) message += " " + f.message + ";";
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

// The group's nodes sorted, once each; its hex faces sorted by hex, then local face.
void sortGroup(SurfaceGroup& g) {
  std::sort(g.nodes.begin(), g.nodes.end());
  g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
  std::sort(g.hexFaces.begin(), g.hexFaces.end(), [](const HexFace& a, const HexFace& b) {
    return std::make_pair(a.hex, a.localFace) < std::make_pair(b.hex, b.localFace);
  });
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
  for (SurfaceGroup& g : merged) sortGroup(g);
  return merged;
}

// The mesh's boundary on the CAD faces (FreeCAD's FaceN). [in,out] mesh: every boundary node given a CAD face (of
// the input's faces); [in] group: whether to group the nodes and element faces by CAD face (not for a piece of a
// part, junction_mesh.hpp: the joined part is grouped); [out] r: the surface groups' statistics and the boundary
// deviation (if grouped).
std::vector<SurfaceGroup> groupByCadFace(HexMesh& mesh, const CadSolid& cad, const WallProjector& walls, MeshReport& r,
                                         bool group = true) {
  const std::vector<BoundaryFace> quads = boundaryFaces(mesh);  // sorted by hex, then local face
  const std::vector<int> boundary = boundaryNodes(mesh, quads);
  const std::size_t unplaced = faceUnplacedNodes(mesh, walls, boundary);
  SurfaceGroups s;
  if (group) {
    s = surfaceGroups(mesh, walls.faces(), quads, boundary);
    r.surfaceGroups = s.stats;
    r.boundaryDeviation = std::move(s.deviation);
  }
  r.surfaceGroups.nodesNotPutOnCad = unplaced;
  if (cad.inputFace.empty()) return std::move(s.groups);
  // Faces split into pieces (mixed_faces.hpp): the input's faces, as the user's part has them.
  for (int& f : mesh.nodeFace) f = inputFaceOf(cad, f);
  return group ? groupsOfInputFaces(std::move(s.groups), cad) : std::vector<SurfaceGroup>{};
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

// The options' lengths in the pipeline's units (CadSolid::unit per input length).
MeshOptions inPipelineUnits(MeshOptions o, double unit) {
  o.size *= unit, o.minSize *= unit, o.maxSize *= unit;
  return o;
}

// The mesh, the chordal surface, the quad mesh and the report's lengths so far back in the input's units.
void toInputUnits(MeshResult& result, double unit) {
  toInputUnits(result.report, unit);
  if (unit == 1) return;
  for (Vec3& p : result.mesh.nodes) p /= unit;
  for (Vec3& p : result.chordalSurface.vertices) p /= unit;
  for (double& radius : result.chordalSurface.radius) radius /= unit;
  for (Vec3& p : result.quadMesh.nodes) p /= unit;
  for (Vec3& p : result.shell.nodes) p /= unit;
  for (double& t : result.shell.thickness) t /= unit;
}

// The mean of the top and bottom walls' areas (a plate's, a cylinder segment's mid-surface area), in the pipeline's
// units.
double wallMeanArea(const WallSides& sides) {
  double area = 0;
  for (const FaceSide& f : sides.faces) area += f.side == Side::Lateral ? 0 : 0.5 * f.area;
  return area;
}

// The shells of several solids as one, each solid's node ids after those already there; the CAD faces numbered on.
void appendShell(ShellMesh& all, const ShellMesh& part) {
  const int offset = static_cast<int>(all.nodes.size());
  appendCells(all.quads, part.quads, offset);
  appendCells(all.midSides, part.midSides, offset);
  all.nodes.insert(all.nodes.end(), part.nodes.begin(), part.nodes.end());
  all.thickness.insert(all.thickness.end(), part.thickness.begin(), part.thickness.end());
  all.nodeSets.resize(part.nodeSets.size());
  for (std::size_t k = 0; k < part.nodeSets.size(); ++k) {
    all.nodeSets[k].name = part.nodeSets[k].name;
    for (int n : part.nodeSets[k].nodes) all.nodeSets[k].nodes.push_back(n + offset);
  }
  appendSurfaceGroups(all.faces, part.faces, offset, 0);
}

// The mesh, its stages and report brought to the input's units, measured and checked against the CAD (not yet
// enforced). [in,out] result; [in] cad, sides, o; [in] leftOut: the volume of junctions left out (pipeline units).
void measureSolid(MeshResult& result, const CadSolid& cad, const WallSides& sides, const MeshOptions& o, double leftOut,
                  StageClock& clock) {
  MeshReport& r = result.report;
  // From here on, the input's units.
  toInputUnits(result, cad.unit);
  const double unit3 = cad.unit * cad.unit * cad.unit;
  const long cadEuler = eulerCharacteristic(cad);
  r.mesh = clock.run("quality", [&] {
    return measureSolidMesh(result.mesh, (cad.volume - leftOut) / unit3, cadEuler, leftOut > 0, result.scaledJacobian);
  });
  r.junctionsLeftOut = leftOut / unit3;  // the mesh's CAD volume is the part's without them
  if (o.aspect > 0) r.aspectRatioHit = aspectHit(result.mesh, o.aspect);
  result.nodeSets = surfaceNodeSets(result.mesh);
  if (o.shell) r.shell = measureShell(result.shell, wallMeanArea(sides) / (cad.unit * cad.unit));
}

// The cut solid's face of every node put on a piece's face (-1: on a foot, or none). [in,out] mesh: a piece's
// hexes, nodeFace the piece's faces; [in] origin: JunctionCut::faceOrigin of the piece. Returns the nodes that were
// on a foot.
std::vector<int> toCutFaces(HexMesh& mesh, const std::vector<int>& origin) {
  std::vector<int> onFoot;
  for (std::size_t n = 0; n < mesh.nodeFace.size(); ++n) {
    int& f = mesh.nodeFace[n];
    if (f >= 0 && origin[f] < 0) onFoot.push_back(static_cast<int>(n));
    f = f >= 0 ? origin[f] : -1;
  }
  return onFoot;
}

// The solid as the stages see it (the geometry stage): every stage up to the surface groups works on the part scaled to
// one size (normalizingUnit). [in] solid; [in] cutFaces: per face, whether it is a cut through the part (a piece's
// foot; empty: none); [in,out] clock.
CadSolid stageSolid(const TopoDS_Solid& solid, const std::vector<char>& cutFaces, StageClock& clock) {
  CadSolid cad = clock.run("geometry", [&] { return prepareSolid(solid, normalizingUnit(solid)); });
  cad.cutInput = cutFaces;
  return cad;
}

// A column's hexes below this scaled Jacobian are refused (meshColumn).
constexpr double kWorstColumnHex = 0.1;

// A piece standing on a sheet that is no sheet but a column (column_piece.hpp: a pin, a post, a block): its foot's
// quads (column_foot.hpp) swept up its axis (column_sweep.hpp), about as many layers as its height holds quads; the
// boundary nodes given CAD faces, not grouped (the joined part is). [in] solid, given, cutFaces: as meshSolid's for a
// piece; [in] size: the quad size, in the solid's units; [in] across: the feet of columns meshed before on the sheets
// this one stands on, in the part's units: one on the sheet's other side under this one gives its quads
// (columnFootAcross); [in,out] boxes. Returns nullopt if the piece is no column.
std::optional<MeshResult> meshColumn(const TopoDS_Solid& solid, const MeshOptions& given,
                                     const std::vector<char>& cutFaces, double size,
                                     const std::vector<FootprintQuads>& across, FaceBoxes* boxes) {
  MeshResult result;
  MeshReport& r = result.report;
  StageClock clock(r.stages, given);
  const CadSolid cad = stageSolid(solid, cutFaces, clock);
  const MeshOptions o = inPipelineUnits(given, cad.unit);
  const std::optional<ColumnPiece> column = columnPiece(cad);
  if (!column) return std::nullopt;
  r.size = size * cad.unit, r.sizeSource = "the sheet's wall thickness";
  const ColumnFoot foot = clock.run("quad_mesh", [&] {
    for (FootprintQuads other : column->ledges.empty() ? across : std::vector<FootprintQuads>{}) {  // one across
      for (Vec3& p : other.nodes) p *= cad.unit;
      if (std::optional<ColumnFoot> taken = columnFootAcross(cad, *column, other, r.size)) return *taken;
    }
    return columnFootQuads(cad, *column, r.size, o.gmshRuns.get());
  });
  const WallSides sides = columnSides(cad, *column);
  r.thickness = sides.thickness;
  const WallProjector walls(cad, sides, boxes);
  const ColumnTiers tiers = columnTiers(*column, r.size);
  result.mesh = clock.run("sweep", [&] { return sweepColumn(cad, foot, *column, walls, tiers); });
  if (o.order == 2) r.quadratic = clock.run("quadratic", [&] { return makeQuadratic(result.mesh, walls); });
  groupByCadFace(result.mesh, cad, walls, r, /*group=*/false);
  result.quadMesh = foot.quads;
  r.quadMesh = countQuadMesh(foot.quads);
  measureSolid(result, cad, sides, o, 0, clock);
  // Caps at different heights over the foot (a boss's blind bore from its top, a ledge) give sweep columns of different
  // heights side by side, whose hexes shear across the step where the foot's quads do not follow its outline.
  const double worst = result.scaledJacobian.empty()
                           ? 1.0
                           : *std::min_element(result.scaledJacobian.begin(), result.scaledJacobian.end());
  if (worst < kWorstColumnHex) {
    std::ostringstream msg;
    msg << std::setprecision(2) << "column: its hexes shear across a step inside it (a blind bore from its top, a "
        << "ledge: scaled Jacobian " << worst << "), whose outline its foot's quads do not follow yet";
    throw geometryError(msg.str());
  }
  return result;
}

constexpr double kCreaseStep = 0.25;  // of a quad edge: a lap's crease sampled this often (followCreases)
constexpr double kOnFoot = 1e-3;      // of a layer: a node this near a foot's plane lies on it
// A wall's foot column this near (of a quad edge) to the projection of a column across the sheet is put across from it
// (snapFootColumnsAcross): alignFootAcross put its chordal node there.
constexpr double kAcrossReach = 0.25;

// A part cut at its junctions (issue 18; junction_mesh.hpp), meshed piece by piece: every sheet after the sheets
// standing on it (the cut's later, smaller sheets), its quads carrying their footprints, its hexes joined to theirs.
struct JunctionPieces {
  JunctionCut cut;
  std::vector<MeshReport> reports;  // per piece
  HexMesh joined;                   // every piece's hexes, the last piece's first, nodes on the cut's faces
  std::vector<int> onFeet;          // joined's nodes that were on a foot face
  // Per standing sheet, per sheet it stands on, its footprint there, its nodes joined's.
  std::vector<std::map<int, WallFoot>> feet;
  std::vector<char> crossed;  // per piece, whether walls stand on both its sides at one place (ribs crossing it)
  std::vector<char> columns;  // per piece, whether it is a column found on the part (Sheet::column)
  MeshResult stages;          // the pieces' chordal surfaces and quads, one after the other
};

// The seconds and peak memory of a piece's stages, as one stage.
StageTime pieceTime(const MeshReport& piece) {
  StageTime t;
  for (const auto& [name, stage] : piece.stages)
    t.seconds += stage.seconds, t.peakMemoryMiB = std::max(t.peakMemoryMiB, stage.peakMemoryMiB);
  return t;
}

// The footprints of the sheets standing on sheet s, one node per joined node (feet that meet share their nodes).
// [out] node: per footprint node, its joined node; [out] lap: per footprint node, whether it is a lap's (WallFoot).
FootprintQuads footprintsOn(const JunctionPieces& t, int s, std::vector<int>& node, std::vector<char>& lap) {
  FootprintQuads f;
  std::map<int, int> index;  // joined node -> footprint node
  for (const auto& on : t.feet) {
    const auto foot = on.find(s);
    if (foot == on.end()) continue;
    for (const auto& quad : foot->second.footprint.quads) {
      std::array<int, 4> q;
      for (int c = 0; c < 4; ++c) {
        const int n = foot->second.wallNode[quad[c]];
        const auto [it, added] = index.emplace(n, static_cast<int>(node.size()));
        if (added) node.push_back(n), f.nodes.push_back(t.joined.nodes[n]), lap.push_back(0);
        if (!foot->second.lap.empty() && foot->second.lap[quad[c]]) lap[it->second] = 1;
        q[c] = it->second;
      }
      f.quads.push_back(q);
    }
  }
  return f;
}

// The feet of the pieces meshed before piece s on the sheets it stands on, each once (a column's or a wall's across
// the sheet from s's may be one).
std::vector<const WallFoot*> feetMeshedBefore(const JunctionPieces& t, int s) {
  std::vector<const WallFoot*> feet;
  for (const Foot& own : t.cut.feet)
    if (own.sheet == s)
      for (std::size_t other = s + 1; other < t.feet.size(); ++other)
        if (const auto foot = t.feet[other].find(own.base);
            foot != t.feet[other].end() && std::find(feet.begin(), feet.end(), &foot->second) == feet.end())
          feet.push_back(&foot->second);
  return feet;
}

// A piece's hexes and whether they are a column's: a column found on the part (Sheet::column) is meshed as one (a low
// pad alone would mesh as a flat sheet lying on its foot), or by the sheet method where the cut left it no column (a
// block against a wall: cut off the floor and the wall, it has two feet); another piece by the sheet method, its quads
// edited by `carry` and its hexes by `swept`, or as a column where that method refuses a standing piece that carries no
// footprint (a pin: `not a thin section`). [in] solid, o, cutFaces, columnSize, across: as meshColumn's; [in]
// foundColumn, standing, carries: the piece's kind, whether it stands on another, whether others stand on it; [in,out]
// boxes. Throws the sheet method's error.
std::pair<MeshResult, bool> pieceHexes(const TopoDS_Solid& solid, bool foundColumn, bool standing, bool carries,
                                       const MeshOptions& o, const QuadEdit& carry, const HexEdit& swept,
                                       const std::vector<char>& cutFaces, double columnSize,
                                       const std::vector<FootprintQuads>& across, FaceBoxes& boxes) {
  if (foundColumn && carries) throw geometryError("column: walls stand on a post or block, which is not meshed yet");
  std::exception_ptr sheetError;
  auto bySheetMethod = [&]() -> std::optional<MeshResult> {
    try {
      return meshSolid(solid, o, carry, cutFaces, &boxes, swept);
    } catch (const Error& e) {
      if (e.code() != ExitCode::UnsupportedGeometry || !standing || carries) throw;
      sheetError = std::current_exception();
      return std::nullopt;
    }
  };
  if (!foundColumn)
    if (std::optional<MeshResult> sheet = bySheetMethod()) return {std::move(*sheet), false};
  if (std::optional<MeshResult> column = meshColumn(solid, o, cutFaces, columnSize, across, &boxes))
    return {std::move(*column), true};
  if (foundColumn && standing && std::count(cutFaces.begin(), cutFaces.end(), 1) > 1)  // two feet: no column
    if (std::optional<MeshResult> sheet = bySheetMethod()) return {std::move(*sheet), false};
  if (sheetError && !foundColumn) std::rethrow_exception(sheetError);
  throw geometryError(
      "column: a post or block stands on the sheet, but it is no column (its foot is not one face, or is tilted over "
      "45 degrees to its sides, or a face of it overhangs the foot), which is not meshed yet");
}

// Whether sheets of the cut stand on piece s. [in] cut, s.
bool carriesFeet(const JunctionCut& cut, int s) {
  return std::any_of(cut.feet.begin(), cut.feet.end(), [&](const Foot& f) { return f.base == s; });
}

// Meshes piece s with its quads carrying the footprints on it, joins its hexes to t.joined and keeps its own feet
// (in joined's nodes). [in] solid: the piece's (t.cut.pieces[s] or a copy); [in] o: in the pipeline's units;
// [in] tolerance: how near a node lies to its foot's plane; [in] wallShare: of the wall's thickness, how far a
// column's end may be from its foot node. [in,out] t; [in,out] boxes: the faces' exact boxes, shared with the part
// and the other pieces. [in] feetMeshed: empty if the pieces standing on s are meshed; else waits until they are
// (throwing their error), called where the piece's quads take their footprints (a sheet that stands on none).
void meshPiece(JunctionPieces& t, int s, const TopoDS_Solid& solid, const MeshOptions& o, double tolerance,
               double wallShare, double columnSize, FaceBoxes& boxes, const std::function<void()>& feetMeshed) {
  const int pieces = static_cast<int>(t.cut.pieces.size());
  reportProgress(o.progress, progressNote("", "piece " + std::to_string(pieces - s) + " of " + std::to_string(pieces)));
  std::vector<int> footNode;
  std::vector<char> footLap;
  FootprintQuads footprint;
  bool footprintTaken = false;
  const auto takeFootprint = [&] {  // once the pieces standing on s are meshed
    if (footprintTaken) return;
    if (feetMeshed) feetMeshed();
    footprint = footprintsOn(t, s, footNode, footLap), footprintTaken = true;
  };
  if (!feetMeshed) takeFootprint();
  const bool carries = feetMeshed ? carriesFeet(t.cut, s) : !footprint.quads.empty();
  std::vector<int> column;           // per footprint node, the sheet's quad node under it
  MergedFootprints merged;           // its shift in the part's units
  std::vector<FootSurface> ownFeet;  // the piece's feet on the sheets it stands on
  for (const Foot& f : t.cut.feet)
    if (f.sheet == s) ownFeet.emplace_back(f, tolerance);
  std::vector<char> cutFaces;  // the piece's feet, on the sheets it stands on or under those standing on it
  for (int origin : t.cut.faceOrigin[s]) cutFaces.push_back(origin < 0);
  // The feet meshed before: the columns' (meshColumn takes one across the sheet), and the walls' across the sheet from
  // the piece's (every sweep column's middle projected onto one of its feet lies on it: a boss's other half), whose
  // sweep columns the piece's foot is put across from; one ring across: the piece's ring grid as many quads round.
  std::vector<FootprintQuads> columnFeet;
  std::vector<const WallFoot*> wallsAcross;
  FootColumns across;
  for (const WallFoot* foot : feetMeshedBefore(t, s))
    if (foot->column)
      columnFeet.push_back(foot->footprint);
    else if (columnsAcross(ownFeet, foot->footColumns))
      wallsAcross.push_back(foot), across.insert(across.end(), foot->footColumns.begin(), foot->footColumns.end());
  MeshOptions own = o;
  if (wallsAcross.size() == 1 && wallsAcross[0]->ring) own.ringAround = static_cast<int>(across.size());
  double aligned = 0;  // the reach alignFootAcross had (0: it put no rim node across)
  // the sheet's quads made to carry the footprints of the walls standing on it
  const QuadEdit carryFootprints = [&](const CadSolid& c, QuadStage& stage) {
    takeFootprint();
    if (const double reach = meanEdge(stage.quads) / c.unit;
        alignFootAcross(stage.quads, ownFeet, across, c.unit, reach))
      aligned = reach;
    std::vector<char> blocked;  // the footprints' quads
    if (!footprint.quads.empty()) {
      const ChordalLocator locator(stage.chordal);
      FootprintQuads onWall = footprint;
      for (Vec3& p : onWall.nodes) p *= c.unit;
      // feet on both sides of the sheet (ribs crossing it) are one
      merged = mergeFeetOnBothSides(onChordalSurface(onWall, locator), locator);
      merged.shift /= c.unit;
      const FootprintInsertion in =
          insertFootprints(stage.quads, merged.footprint, locator, meanEdge(stage.quads), o.gmshRuns.get());
      for (int m : merged.node) column.push_back(in.node[m]);
      stage.feet.clear();
      for (std::size_t k = 0; k < column.size(); ++k)
        stage.feet.push_back({column[k], footprint.nodes[k] * c.unit, footLap[k] != 0});
      t.crossed[s] = merged.footprint.nodes.size() < merged.node.size();
      stage.quads = in.quads;
      std::vector<char> onFootprint(stage.quads.nodes.size(), 0);
      for (int n : in.node) onFootprint[n] = 1;
      blocked.resize(stage.quads.quads.size(), 0);
      for (std::size_t q = 0; q < stage.quads.quads.size(); ++q)
        blocked[q] = std::all_of(stage.quads.quads[q].begin(), stage.quads.quads[q].end(),
                                 [&](int n) { return onFootprint[n] != 0; });
    }
    // a rim loop all on a foot (a boss's) becomes a closed loop of fixed nodes in the sheet it stands on: even
    evenRimLoops(
        stage.quads,
        [&](const Vec3& p) {
          return std::any_of(ownFeet.begin(), ownFeet.end(), [&](FootSurface& f) { return f.holds(p / c.unit); });
        },
        blocked);
  };
  // its foot columns put across from those of a wall across the sheet (alignFootAcross put its rim nodes there)
  const HexEdit snapAcross = [&](const CadSolid& c, const QuadStage& stage, HexMesh& mesh) {
    if (aligned > 0) snapFootColumnsAcross(mesh, stage.quads, ownFeet, across, c.unit, kAcrossReach * aligned);
  };
  auto [piece, isColumn] = pieceHexes(solid, t.columns[s] != 0, s > 0, carries, own, carryFootprints, snapAcross,
                                      cutFaces, columnSize, columnFeet, boxes);
  takeFootprint();
  std::vector<int> shared(piece.mesh.nodes.size(), -1);
  if (!footprint.quads.empty()) {
    const double reach = wallShare * piece.report.thickness + merged.shift;
    shared = footNodesShared(piece.mesh, column, t.joined, footNode, reach);
    leanCrossedColumns(piece.mesh, piece.quadMesh, shared, t.joined);
    evenFootColumns(piece.mesh, static_cast<int>(piece.quadMesh.nodes.size()), shared, t.joined);
  }
  const std::vector<int> onFeet = toCutFaces(piece.mesh, t.cut.faceOrigin[s]);
  const std::vector<int> id = joinHexMesh(t.joined, piece.mesh, shared);
  for (int n : onFeet) t.onFeet.push_back(id[n]);
  std::set<int> bases;
  for (const Foot& f : t.cut.feet)
    if (f.sheet == s) bases.insert(f.base);
  for (int b : bases) {
    std::vector<FootSurface> surfaces = footSurfaces(t.cut, s, b, tolerance);
    WallFoot foot = isColumn ? columnFoot(piece.mesh, piece.quadMesh) : wallFoot(piece.mesh, piece.quadMesh, surfaces);
    for (int& n : foot.wallNode) n = id[n];
    t.feet[s][b] = std::move(foot);
  }
  appendStages(t.stages, piece);
  t.reports[s] = std::move(piece.report);
}

// One piece meshed by meshPiece: [in] s, solid, o, boxes, feetMeshed as meshPiece's.
using MeshOne = std::function<void(int s, const TopoDS_Solid& solid, const MeshOptions& o, FaceBoxes& boxes,
                                   const std::function<void()>& feetMeshed)>;

// Whether the base (piece 0) may be meshed beside the walls standing on it: it stands on no piece (only its quads'
// footprints wait for the others), and it is no column. [in] t: the cut.
bool baseBeside(const JunctionPieces& t) {
  return t.cut.pieces.size() > 1 && !t.columns[0] &&
         std::none_of(t.cut.feet.begin(), t.cut.feet.end(), [](const Foot& f) { return f.sheet == 0; });
}

// The boxes `from` keeps for the faces of `a`, kept in `to` for the faces of `b` (a copy of a: its faces in order).
void copyBoxes(const FaceBoxes& from, const TopoDS_Shape& a, FaceBoxes& to, const TopoDS_Shape& b) {
  TopExp_Explorer i(a, TopAbs_FACE), j(b, TopAbs_FACE);
  for (; i.More() && j.More(); i.Next(), j.Next())
    if (const Bnd_Box* box = from.find(TopoDS::Face(i.Current()))) to.keep(TopoDS::Face(j.Current()), *box);
}

// The walls (pieces 1 ..) meshed as meshJunctionPieces does, on a thread of their own, and the base beside them (on
// this thread; with one thread, after them) up to where its quads take their footprints, then to its end: its stages
// before do not depend on the walls. The base is meshed from a copy of its solid made before the walls (they share
// faces with it, whose triangles their stages make): the same result on any number of threads. Progress reaches
// o.progress on this thread, the walls' events first (as they come, at the base's events), the base's after them; the
// walls' error is thrown before the base's, as when meshed one after the other; a progress callback's exception (a
// cancel) stops the walls at their next event. The base's report counts its own work: its wait for the walls is not
// in its footprints' stage. [in,out] t; [in] mesh: meshes one piece; [in] o; [in,out] boxes: as meshPiece's.
void meshWallsAndBase(JunctionPieces& t, const MeshOne& mesh, const MeshOptions& o, FaceBoxes& boxes) {
  const TopoDS_Solid base = TopoDS::Solid(BRepBuilderAPI_Copy(t.cut.pieces[0], true, true).Shape());
  FaceBoxes baseBoxes;
  copyBoxes(boxes, t.cut.pieces[0], baseBoxes, base);
  const auto walls = [&](const MeshOptions& wo) {
    for (int s = static_cast<int>(t.cut.pieces.size()) - 1; s > 0; --s) mesh(s, t.cut.pieces[s], wo, boxes, {});
  };
  if (threadCount() < 2) {
    walls(o);
    mesh(0, base, o, baseBoxes, {});
  } else {
    ProgressRelay relay(o.progress);
    MeshOptions wallOptions = o;
    wallOptions.progress = relay.callback();
    const std::shared_future<void> wallsMeshed = std::async(std::launch::async, [&] {
                                                   struct Closing {
                                                     ProgressRelay& relay;
                                                     ~Closing() { relay.close(); }
                                                   } closing{relay};
                                                   walls(wallOptions);
                                                 }).share();
    bool handedOn = false, cancelled = false;  // the walls' events and result; a callback threw
    std::vector<Progress> held;                // the base's events until the walls' are handed on
    const auto guarded = [&](const auto& report) {
      try {
        report();
      } catch (...) {
        cancelled = true;
        throw;
      }
    };
    double waited = 0;               // seconds the base waited for the walls, in its footprints' stage
    const auto waitForWalls = [&] {  // their events handed on, then their error thrown, then the base's events
      if (handedOn) return;
      const auto from = std::chrono::steady_clock::now();
      guarded([&] { relay.forward(true); });
      waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
      handedOn = true;
      wallsMeshed.get();
      for (const Progress& event : held) guarded([&] { reportProgress(o.progress, event); });
    };
    MeshOptions own = o;
    own.progress = [&](const Progress& event) {
      if (!handedOn && wallsMeshed.wait_for(std::chrono::seconds(0)) == std::future_status::ready) waitForWalls();
      if (handedOn) return guarded([&] { reportProgress(o.progress, event); });
      guarded([&] { relay.forward(false); });
      held.push_back(event);
    };
    try {
      mesh(0, base, own, baseBoxes, waitForWalls);
    } catch (...) {
      if (cancelled) {
        relay.stop();
        throw;  // the walls waited for at wallsMeshed's end
      }
      const std::exception_ptr error = std::current_exception();
      relay.forward(true);
      wallsMeshed.get();  // the walls' error first
      std::rethrow_exception(error);
    }
    if (auto stage = t.reports[0].stages.find("footprints"); stage != t.reports[0].stages.end())
      stage->second.seconds = std::max(0.0, stage->second.seconds - waited);  // the base's own work, not its wait
  }
  copyBoxes(baseBoxes, base, boxes, t.cut.pieces[0]);
}

// [in] cad, sides, sheets (the sheet stood on, then the standing ones); [in] o: in the pipeline's units; [in,out]
// clock; [in,out] boxes: the faces' exact boxes (meshPiece). Throws the pieces' errors.
JunctionPieces meshJunctionPieces(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets,
                                  const MeshOptions& o, StageClock& clock, FaceBoxes& boxes) {
  JunctionPieces t;
  t.cut = clock.run("junction_cut", [&] { return cutAtJunctions(cad, sides, sheets); });  // sheets: crossings merged
  t.reports.resize(t.cut.pieces.size()), t.feet.resize(t.cut.pieces.size()), t.crossed.assign(t.cut.pieces.size(), 0);
  for (int s : t.cut.sheetOf) t.columns.push_back(sheets[s].column);
  // The sheet's node under a foot node is known by its column (the footprint's quad node); it is checked to be the
  // column's end nearer to the foot within half the wall's thickness (the sheet's rim and poor hexes are
  // smoothed after the sweep, and in a bend its chordal facets are coarser than the wall), then is the foot's node.
  MeshOptions piece = o;
  piece.force = true;
  const MeshOne mesh = [&](int s, const TopoDS_Solid& solid, const MeshOptions& po, FaceBoxes& b,
                           const std::function<void()>& feetMeshed) {
    try {
      meshPiece(t, s, solid, po, kOnFoot * sides.thickness / o.layers, 0.5, o.size > 0 ? o.size : sides.thickness, b,
                feetMeshed);
    } catch (const Error& e) {  // the part was read and checked: a piece that is no valid solid is the cut's doing
      if (e.code() == ExitCode::BadInput)
        throw geometryError("the cut at the junctions gave a piece that is no valid solid (" + std::string(e.what()) +
                            "), which is not meshed");
      if (e.code() != ExitCode::UnsupportedGeometry || s == 0) throw;
      // a standing piece's refusal names it (the base's names the walls' it waited for)
      const Vec3 at = pieceRecord(cad, sheets, t.cut, s).at / cad.unit;
      std::ostringstream msg;
      msg << e.what() << " (the piece at (" << at.x() << ", " << at.y() << ", " << at.z() << "))";
      throw geometryError(msg.str());
    }
  };
  if (baseBeside(t))
    meshWallsAndBase(t, mesh, piece, boxes);
  else
    for (int s = static_cast<int>(t.cut.pieces.size()) - 1; s >= 0; --s) mesh(s, t.cut.pieces[s], piece, boxes, {});
  return t;
}

// The foot's nodes (no CAD face: the foot is none) on the CAD face nearest to each (the first of the nearest), so
// that those on the boundary (the foot's edges) are grouped with the faces they lie on. A face whose box is farther
// than the face nearest to its box is not measured (it cannot be nearer). [in,out] mesh; [in] faces: the part's;
// [in] foot: nodes.
void placeFootNodes(HexMesh& mesh, const CadFaces& faces, const std::vector<int>& foot) {
  CadFaceProbe probe(faces);
  std::vector<double> boxDistance(faces.count());
  for (int n : foot) {
    const Vec3& p = mesh.nodes[n];
    Bnd_Box at;
    at.Add(gp_Pnt(p.x(), p.y(), p.z()));
    for (int f = 0; f < faces.count(); ++f) boxDistance[f] = faces.face(f).box.Distance(at);
    const int boxNearest =
        static_cast<int>(std::min_element(boxDistance.begin(), boxDistance.end()) - boxDistance.begin());
    const double bound = probe.distance(boxNearest, p);  // the nearest face is no farther
    double best = std::numeric_limits<double>::infinity();
    for (int f = 0; f < faces.count(); ++f)
      if (boxDistance[f] <= bound)
        if (const double d = f == boxNearest ? bound : probe.distance(f, p); d < best) best = d, mesh.nodeFace[n] = f;
  }
}

// The part's report from its pieces': the first sheet's stages' numbers stand for the part's (the mesh's are
// measured again), the counts are every piece's, the pieces' times two stages. [in,out] r: the stages so far; [in] t.
void reportPieces(MeshReport& r, JunctionPieces& t, const CadSolid& cad, const WallSides& sides) {
  std::map<std::string, StageTime> stages = std::move(r.stages);
  StageTime walls;
  for (std::size_t w = 1; w < t.reports.size(); ++w) {
    const StageTime one = pieceTime(t.reports[w]);
    walls.seconds += one.seconds, walls.peakMemoryMiB = std::max(walls.peakMemoryMiB, one.peakMemoryMiB);
  }
  stages["junction_walls"] = walls, stages["junction_sheet"] = pieceTime(t.reports[0]);
  const std::size_t facesSplit = r.facesSplit;
  r = std::move(t.reports[0]);
  for (std::size_t w = 1; w < t.reports.size(); ++w) {
    const MeshReport& p = t.reports[w];
    r.bubbles += p.bubbles, r.tetsKept += p.tetsKept;
    r.quadMesh.quads += p.quadMesh.quads, r.quadMesh.nodes += p.quadMesh.nodes;
    r.quadMesh.pinholesClosed += p.quadMesh.pinholesClosed;
    CreaseChainStats& c = r.creaseChains;  // the walls' laps
    c.chains += p.creaseChains.chains, c.dropped += p.creaseChains.dropped, c.nodesMoved += p.creaseChains.nodesMoved;
    c.farthest = std::max(c.farthest, p.creaseChains.farthest);
    c.worstQuad = std::min(c.worstQuad, p.creaseChains.worstQuad);
  }
  r.stages = std::move(stages), r.facesSplit = facesSplit, r.thickness = sides.thickness, r.faces = countFaces(sides);
  r.smallFeatures = findSmallFeatures(cad, sides, r.size);  // the part's faces, not the pieces' (a foot is none)
}

// Issue 18: walls standing on a sheet (junction_mesh.hpp) meshed all-hex and conformal: the walls' hexes and the
// sheet's joined on the walls' foot nodes, grouped by the part's faces. A junction the cut or the footprints cannot
// take, or a piece that does not mesh, is refused (geometryError naming it and why).
// [in] cad, sides, sheets: the part's (findSheets, two or more); [in] o: in the pipeline's units; [in,out] result:
// the stages so far (report), moved into the returned mesh; [in,out] clock: timing result's stages.
MeshResult meshJunctions(const CadSolid& cad, const WallSides& sides, const std::vector<Sheet>& sheets,
                         const MeshOptions& o, MeshResult& result, StageClock& clock) {
  if (o.shell) throw junctionRefusal(cad, sheets, "the shell is not made at junctions yet");
  JunctionPieces t;
  FaceBoxes boxes;  // most of the part's faces are its pieces' too: each face's exact box measured once
  try {
    t = meshJunctionPieces(cad, sides, sheets, o, clock, boxes);
  } catch (const Error& e) {
    if (e.code() == ExitCode::BadUsage) throw;
    throw junctionRefusal(cad, sheets, e.what());
  } catch (const Standard_Failure& e) {  // OpenCASCADE's exceptions are not std::exceptions
    throw junctionRefusal(cad, sheets, std::string("OpenCASCADE: ") + e.GetMessageString());
  }
  MeshReport& r = result.report;
  reportPieces(r, t, cad, sides);
  result.mesh = std::move(t.joined);
  const WallProjector walls(cad, sides, &boxes);
  placeFootNodes(result.mesh, walls.faces(), t.onFeet);
  result.surfaceGroups = clock.run("surface_groups", [&] { return groupByCadFace(result.mesh, cad, walls, r); });
  appendStages(result, t.stages);
  measureSolid(result, cad, sides, o, 0, clock);
  r.junctions.clear();
  for (std::size_t w = 1; w < t.feet.size(); ++w) {
    JunctionRecord j = pieceRecord(cad, sheets, t.cut, static_cast<int>(w));
    std::vector<int> foot;
    bool ring = true, column = true;
    for (const auto& [base, on] : t.feet[w])
      foot.insert(foot.end(), on.wallNode.begin(), on.wallNode.end()), ring = ring && on.ring,
                                                                       column = column && on.column;
    const JunctionHexes hexes = junctionHexes(result.mesh, result.scaledJacobian, foot);
    j.at /= cad.unit, j.area /= cad.unit * cad.unit, j.volume /= cad.unit * cad.unit * cad.unit;  // as toInputUnits
    j.kind = column ? "column" : ring ? "ring" : t.crossed[w] ? "X" : "T", j.meshed = true, j.hexes = hexes.hexes;
    j.minScaledJacobian = hexes.minScaledJacobian, j.meanScaledJacobian = hexes.meanScaledJacobian;
    r.junctions.push_back(j);
  }
  try {
    enforceValidation(r.mesh, o);
  } catch (const Error& e) {  // the joined mesh is not valid: the junctions are refused (--force writes it)
    throw junctionRefusal(cad, sheets, e.what());
  }
  return std::move(result);
}

// The boundary quads and nodes of the mesh nearer to one of `faces` (removed fillets, faces merged into a neighbour;
// within reach) than to the face they are grouped with (a quad by its centre; not compared if `overOwn`) move to its
// group. [in,out] groups: per input face; [in] mesh: in the input's units; [in] cad: the part, fillets and all;
// [in,out] probe: of cad's faces (made once for every pass); [in] faces: 0-based; [in] reach; [in] overOwn.
void groupByNearness(std::vector<SurfaceGroup>& groups, const HexMesh& mesh, const CadSolid& cad, CadFaceProbe& probe,
                     const std::vector<int>& faces, double reach, bool overOwn = false) {
  auto nearerOf = [&](const std::vector<int>& nodes, int group) {  // of their centre: the face's input face, or -1
    Vec3 p = Vec3::Zero();
    for (int n : nodes) p += cad.unit / nodes.size() * mesh.nodes[n];
    int best = -1;
    double nearest = reach;
    for (int f : faces)
      if (const double d = probe.distance(f, p); d < nearest) nearest = d, best = inputFaceOf(cad, f);
    for (int f = 0; !overOwn && best >= 0 && best != group && f < cad.faces.Extent(); ++f)
      if (inputFaceOf(cad, f) == group && probe.distance(f, p) <= nearest) best = -1;
    return best == group ? -1 : best;
  };
  std::vector<std::pair<int, HexFace>> quads;  // to the nearer face's group
  std::vector<std::pair<int, int>> nodes;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    std::vector<HexFace> keptQuads;
    for (const HexFace& q : groups[g].hexFaces) {
      std::vector<int> corners;
      for (int c : kHexFaces[q.localFace]) corners.push_back(mesh.hexes[q.hex][c]);
      if (const int to = nearerOf(corners, static_cast<int>(g)); to >= 0)
        quads.emplace_back(to, q);
      else
        keptQuads.push_back(q);
    }
    std::vector<int> keptNodes;
    for (int n : groups[g].nodes)
      if (const int to = nearerOf({n}, static_cast<int>(g)); to >= 0)
        nodes.emplace_back(to, n);
      else
        keptNodes.push_back(n);
    groups[g].hexFaces = std::move(keptQuads), groups[g].nodes = std::move(keptNodes);
  }
  for (const auto& [to, q] : quads) groups[to].hexFaces.push_back(q);
  for (const auto& [to, n] : nodes) groups[to].nodes.push_back(n);
  for (int f : faces) sortGroup(groups[inputFaceOf(cad, f)]);
}

// The smoothed part's groups as the part's: those of faces merged into a neighbour (FootFillets::merged) by nearness
// first (the piece of the surface each quad lies on), then those of the fillets (within twice the largest radius), and
// if a fillet is left without element faces (every quad beside it as near to a face beside it), each fillet takes those
// within its radius that are nearer to it than to the other fillets.
// [in,out] groups: per input face; [in] mesh: in the input's units; [in] cad: the part, fillets and all; [in] fillets.
void groupFootFillets(std::vector<SurfaceGroup>& groups, const HexMesh& mesh, const CadSolid& cad,
                      const FootFillets& fillets) {
  for (int f = 0; f < cad.faces.Extent(); ++f)
    if (const int input = inputFaceOf(cad, f); input >= static_cast<int>(groups.size())) groups.resize(input + 1);
  for (std::size_t g = 0; g < groups.size(); ++g) groups[g].name = "Face" + std::to_string(g + 1);
  const CadFaces faces(cad);
  CadFaceProbe probe(faces);
  if (!fillets.merged.empty()) groupByNearness(groups, mesh, cad, probe, fillets.merged, cad.diagonal);
  groupByNearness(groups, mesh, cad, probe, fillets.faces, 2 * fillets.largestRadius);
  if (std::any_of(fillets.faces.begin(), fillets.faces.end(),
                  [&](int f) { return groups[inputFaceOf(cad, f)].hexFaces.empty(); }))
    groupByNearness(groups, mesh, cad, probe, fillets.faces, fillets.largestRadius, true);
}

// Issue 18, fillets at the feet of standing walls (foot_fillets.hpp): the part meshed without them (meshJunctions on
// the smoothed part), its volume measured against the part's, its fillets grouped by nearness and reported.
// [in] cad: the part; [in,out] fillets: the smoothed part and its sides (its mixed faces split here); [in] o: in the
// pipeline's units; [in,out] result, clock.
MeshResult meshWithoutFootFillets(const CadSolid& cad, FootFillets& fillets, const MeshOptions& o, MeshResult& result,
                                  StageClock& clock) {
  CadSolid& smooth = fillets.smooth;
  WallSides& sides = fillets.sides;
  result.report.facesSplit += splitMixedFaces(smooth, sides);
  const std::vector<Sheet> sheets = findSheets(smooth, sides);
  if (!sides.ownSideFaces.empty() || sheets.size() < 2)
    throw junctionRefusal(smooth, sheets, "the part without the fillets at its walls' feet is not sheets on sheets");
  MeshResult out = meshJunctions(smooth, sides, mergeCrossingRibs(smooth, sides, sheets), o, result, clock);
  MeshReport& r = out.report;
  const double unit3 = cad.unit * cad.unit * cad.unit;
  r.mesh.cadVolume = cad.volume / unit3;  // the part's, fillets and all
  groupFootFillets(out.surfaceGroups, out.mesh, cad, fillets);
  std::set<int> inputs;  // a fillet split in pieces (mixed_faces.hpp) is one input face
  for (int f : fillets.faces) inputs.insert(inputFaceOf(cad, f));
  for (int f : inputs) r.smallFeatures.footFillets.push_back("Face" + std::to_string(f + 1));
  r.smallFeatures.footFilletRadius = fillets.largestRadius / cad.unit;
  return out;
}

// The part as walls standing on walls (issue 18: junction meshing, the fillets at the walls' feet smoothed over), or
// none if it is one sheet without such fillets. [in,out] cad, sides: as meshJunctions and meshWithoutFootFillets;
// [in] o; [in,out] result, clock. Throws their errors.
std::optional<MeshResult> meshAsSheets(CadSolid& cad, WallSides& sides, const MeshOptions& o, MeshResult& result,
                                       StageClock& clock) {
  if (const std::vector<Sheet> sheets = findSheets(cad, sides); sheets.size() > 1) {
    if (std::optional<FootFillets> smooth =
            clock.run("foot_fillets", [&] { return removeFootFillets(cad, sides, sheets); }))
      return meshWithoutFootFillets(cad, *smooth, o, result, clock);
    return meshJunctions(cad, sides, mergeCrossingRibs(cad, sides, sheets), o, result, clock);
  }
  if (std::optional<FootFillets> smooth = clock.run("foot_fillets", [&] { return removeRootFillets(cad, sides); }))
    return meshWithoutFootFillets(cad, *smooth, o, result, clock);
  return std::nullopt;
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
  if (!(o.quadStageBudget >= 0) || !(o.quadTryBudget >= 0) || !std::isfinite(o.quadStageBudget) ||
      !std::isfinite(o.quadTryBudget))
    throw usageError("--quad-budget and --quad-try-budget must be seconds (0 = from the part's size)");
  if (!(o.minSize >= 0) || !(o.maxSize >= 0) || !std::isfinite(o.minSize) || !std::isfinite(o.maxSize) ||
      (o.maxSize > 0 && o.minSize > o.maxSize))
    throw usageError("--min-size and --max-size must be lengths with --min-size <= --max-size");
}

MeshResult meshSolid(const TopoDS_Solid& solid, const MeshOptions& given) { return meshSolid(solid, given, {}); }

MeshResult meshSolid(const TopoDS_Solid& solid, const MeshOptions& given, const QuadEdit& edit,
                     const std::vector<char>& cutFaces, FaceBoxes* boxes, const HexEdit& hexEdit) {
  validateOptions(given);
  MeshResult result;
  MeshReport& r = result.report;
  StageClock clock(r.stages, given);
  CadSolid cad = stageSolid(solid, cutFaces, clock);
  const MeshOptions o = inPipelineUnits(given, cad.unit);
  // The boundary's triangles (a finer BRepMesh on freeform faces: seconds on a B-spline shell), made once for the wall
  // sides and the tet filter, again only if faces were split in between.
  std::optional<BoundaryTriangles> boundary;
  WallSides sides = clock.run("wall_sides", [&] { return classifyWallSides(cad, boundary.emplace(cad)); });
  r.facesSplit = clock.run("mixed_faces", [&] { return splitMixedFaces(cad, sides); });
  if (!o.dropJunctions && sides.ownSideFaces.empty()) {
    // a wall butting on walls of its sheet stands on them (with --drop-junctions it stays mitred: it is no sheet to
    // leave out under which the others' chordal surface runs on); where the part so cut is refused (a gusset's slope
    // in a box's corner makes the floor and the wall butt on each other), it is meshed as it was
    const CadSolid whole = cad;
    const WallSides wholeSides = sides;
    const MeshResult before = result;
    const std::size_t butts = clock.run("butt_joints", [&] { return splitButtJoints(cad, sides); });
    r.facesSplit += butts;
    std::optional<MeshResult> sheets;
    try {
      sheets = meshAsSheets(cad, sides, o, result, clock);
    } catch (const Error& e) {
      if (butts == 0 || e.code() != ExitCode::UnsupportedGeometry) throw;
      cad = whole, sides = wholeSides, result = before;
      sheets = meshAsSheets(cad, sides, o, result, clock);
    }
    if (sheets) return std::move(*sheets);
  }
  const double leftOut = handleJunctions(cad, sides, o.dropJunctions, r.junctions);
  r.thickness = sides.thickness;
  r.faces = countFaces(sides);
  r.memory = requireMemory(o, sides, cad.unit);
  const auto nodes = clock.run("bubbles", [&] { return packBubbles(cad, sides, BubbleOptions{}); });
  r.bubbles = nodes.size();
  TetMesh tets = clock.run("tets", [&] { return delaunayTets(nodes); });
  r.tetsDropped = clock.run("tet_filter", [&] {
    return keepSpanningTetsInside(tets, cad, r.facesSplit ? boundary.emplace(cad) : *boundary);
  });
  r.tetsKept = tets.tets.size();
  ChordalSurface cut = clock.run("chordal_surface", [&] {  // the tets' classes for the report beside it
    ChordalSurface built;
    sideBySide({[&] { built = buildChordalSurface(tets, cad.unit); }, [&] { r.tetClasses = classifyTets(tets); }});
    return built;
  });
  r.chordal = countChordal(cut);
  const WallProjector walls(cad, sides, boxes);
  r.chordal.rim = clock.run("chordal_rim", [&] {
    const std::vector<char> stepSides = thicknessStepSides(cad, sides);  // no rim: the chordal surface runs across
    const std::size_t tears = fillTears(
        cut, [&](const Vec3& p) { return walls.reaches(Side::Lateral, p, sides.thickness, stepSides); },
        [&](const Vec3& p) { return boundary->classify(p) == Containment::kInside; }, kMaxTear * sides.thickness);
    RimSnapStats snapped = snapRimBetweenWallEdges(
        cut, [&](const Vec3& p) { return walls.rimMiddle(p); }, sides.thickness);
    snapped.tearsFilled = tears;
    return snapped;
  });
  r.size = chooseSize(o, sides, chordalArea(cut), r.sizeSource);
  r.sizing = o.sizing;
  r.smallFeatures = findSmallFeatures(cad, sides, r.size);
  QuadStageOptions qo;
  qo.size = r.size, qo.adaptive = o.sizing == "adaptive", qo.sizing = {r.size, o.minSize, o.maxSize};
  qo.knifeEdges = !sides.knifeEdges.empty(), qo.progress = o.progress;
  qo.tryBudget = o.quadTryBudget, qo.stageBudget = o.quadStageBudget;
  qo.ringAround = o.ringAround;
  // a lap's creases (a piece's only: a part's own faces are no cut), followed by the quads' edges: the layouts whose
  // edges can follow them rank first
  qo.creases = lapCreases(cad, sides, kCreaseStep * r.size);
  QuadStage stage = clock.run("quad_mesh", [&] { return meshFairedChordalSurface(cut, tets, qo); });
  if (!qo.creases.empty())  // sampled at the quads' own edge
    r.creaseChains = clock.run("crease_chains", [&] {
      return followCreases(stage.quads, ChordalLocator(stage.chordal),
                           lapCreases(cad, sides, kCreaseStep * meanEdge(stage.quads)));
    });
  if (edit) clock.run("footprints", [&] { return edit(cad, stage), 0; });  // the walls' feet carried into the quads
  const QuadMesh& quads = stage.quads;
  if (qo.adaptive) r.memory = requireMemoryOfQuads(o, quads.quads.size());
  r.chordal.fairingIterations = stage.fairingIterations;
  r.chordal.knifeFacetsDropped = stage.knifeFacets;
  r.chordal.sliverEdges = stage.sliverEdges;
  r.quadMesh = countQuadMesh(quads);
  r.quadMesh.budgetSeconds = stage.budgetSeconds;
  r.quadMesh.pinholesClosed = holesClosed(quads, stage.chordal);
  const ChordalLocator locator(stage.chordal);
  SweepResult swept = clock.run("sweep", [&] { return sweepToWalls(quads, locator, cad, sides, o.layers); });
  result.mesh = std::move(swept.mesh);
  const std::vector<char> onFeet =  // the walls' foot nodes
      placeFootEnds(result.mesh, quads, stage.feet, kFootEndNear * sides.thickness);
  r.untangled = swept.untangled;
  r.rimProjection =
      clock.run("rim", [&] { return projectRim(result.mesh, cad, sides, walls, kRimReach * sides.thickness); });
  r.rimCap = clock.run("rim_cap", [&] { return capRims(result.mesh, cad, sides, walls); });
  r.smoothing = clock.run("smoothing", [&] { return smoothPoorHexes(result.mesh, walls, sides, onFeet); });
  r.sharpEdges = clock.run("sharp_edges", [&] { return captureSharpEdges(result.mesh, cad, sides); });
  if (hexEdit) hexEdit(cad, stage, result.mesh);
  if (o.order == 2) r.quadratic = clock.run("quadratic", [&] { return makeQuadratic(result.mesh, walls); });
  result.surfaceGroups =
      clock.run("surface_groups", [&] { return groupByCadFace(result.mesh, cad, walls, r, /*group=*/!edit); });
  if (o.shell)
    result.shell = clock.run("shell", [&] { return midSurfaceShell(result.mesh, quads, result.surfaceGroups); });
  result.chordalSurface = std::move(stage.chordal);
  result.quadMesh = std::move(stage.quads);
  measureSolid(result, cad, sides, o, leftOut, clock);
  enforceValidation(r.mesh, o);
  return result;
}

MeshResult meshFile(const std::string& path, const MeshOptions& given) {
  validateOptions(given);
  MeshOptions o = given;  // the Gmsh runs forked from a process as small as this one is before it reads the part
  if (!o.gmshRuns) o.gmshRuns = std::make_shared<ForkServer>(&openGmshSession);
  const std::vector<TopoDS_Solid> solids = readSolids(path);
  if (solids.size() == 1) return meshSolid(solids[0], o);
  MeshResult all;  // several solids: mesh each, one report per solid plus the totals
  std::vector<MeshReport> reports;
  double cadMidArea = 0;
  for (size_t i = 0; i < solids.size(); ++i) {
    const std::string which = "solid " + std::to_string(i + 1) + " of " + std::to_string(solids.size());
    reportProgress(o.progress, progressNote("", which));
    MeshResult one;
    try {
      one = meshSolid(solids[i], o);
    } catch (const Error& e) {
      throw Error(e.code(), which + ": " + e.what());
    }
    cadMidArea += one.report.shell ? one.report.shell->cadMidSurfaceArea : 0;
    reports.push_back(std::move(one.report));
    appendShell(all.shell, one.shell);
    appendSurfaceGroups(all.surfaceGroups, one.surfaceGroups, static_cast<int>(all.mesh.nodes.size()),
                        static_cast<int>(all.mesh.hexes.size()));
    appendHexMesh(all.mesh, one.mesh);
    appendStages(all, one);
  }
  // Separate bodies (nodes where two touch are not shared): validated each on its own, not together.
  all.report = mergeSolids(std::move(reports), measureMesh(all.mesh, all.scaledJacobian));
  all.nodeSets = surfaceNodeSets(all.mesh);
  if (o.shell) all.report.shell = measureShell(all.shell, cadMidArea);
  return all;
}

}  // namespace hexlayer
