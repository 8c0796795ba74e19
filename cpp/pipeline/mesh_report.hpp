// MeshReport: the numbers of one meshing run, every stage's typed result or statistics record gathered as the
// pipeline runs them (pipeline.cpp); report.hpp writes it as JSON, once (every key in docs/report.schema.json).
// Lengths are in the input's units once the pipeline is done (toInputUnits), areas in those squared, volumes cubed.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "chordal/chordal_rim.hpp"
#include "chordal/chordal_surface.hpp"
#include "core/memory.hpp"
#include "core/types.hpp"
#include "geometry/wall_sides.hpp"
#include "pipeline/shell_mesh.hpp"
#include "pipeline/surface_groups.hpp"
#include "quadmesh/crease_chains.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "quality/quality.hpp"
#include "quality/validation.hpp"
#include "sweep/quadratic.hpp"
#include "sweep/rim_cap.hpp"
#include "sweep/rim_projection.hpp"
#include "sweep/sharp_edges.hpp"
#include "sweep/smoothing.hpp"
#include "sweep/untangle.hpp"
#include "tets/tet_mesh.hpp"

namespace hexlayer {

// One stage's wall time and the process's peak memory at its end ("timings_s", "peak_memory_mib").
struct StageTime {
  double seconds = 0;
  double peakMemoryMiB = 0;
};

// A rib, boss or flange standing on the meshed sheet (a T-junction), listed in "junctions": left out
// (--drop-junctions), or meshed with the sheet (issue 18).
struct JunctionRecord {
  Vec3 at = Vec3::Zero();          // the centre of its faces
  std::vector<std::string> faces;  // its input faces (FaceN), a split face's pieces once
  double area = 0, volume = 0;     // of its faces; its estimated volume
  bool meshed = false;             // meshed: the fields below are set
  std::string kind;  // "T": a rib standing on a sheet; "X": one other ribs cross (standing on both its sides at one
                     // place, each a T on it); "ring": a boss (its foot closed on itself)
  std::size_t hexes = 0;                                 // the junction hexes: those with a corner on the rib's foot
  double minScaledJacobian = 0, meanScaledJacobian = 0;  // of the junction hexes
};

// How many faces of the part are top wall, bottom wall and lateral (rim) faces ("faces").
struct FaceCounts {
  int top = 0, bottom = 0, lateral = 0;
};

// The chordal surface as cut from the tets and as the quads were made on it ("chordal_surface").
struct ChordalRecord {
  std::size_t triangles = 0, quads = 0, vertices = 0;
  std::size_t pinchedFacetsDropped = 0;  // ChordalSurface::pinchedFacetsDropped
  std::size_t islandFacetsDropped = 0;   // ChordalSurface::islandFacetsDropped
  RimSnapStats rim;                      // its rim placed between the walls' rim edges
  int fairingIterations = 0;             // QuadStage::fairingIterations
  std::size_t knifeFacetsDropped = 0;    // QuadStage::knifeFacets
  std::size_t sliverEdges = 0;           // QuadStage::sliverEdges
};

// The quad mesh's counts and layout ("quad_mesh"): QuadMesh without its nodes and quads.
struct QuadMeshCounts {
  std::size_t quads = 0, nodes = 0;
  std::size_t pairedTriangles = 0, splitTriangles = 0, holes = 0;
  int doubletsRemoved = 0;
  std::size_t structuredPatches = 0;
  long pinholesClosed = 0;   // the chordal surface's rim loops the quads close (holesClosed)
  std::string layout;        // layoutName
  QuadTries tries;           // the Gmsh tries of every fairing level ("gmsh_tries")
  double budgetSeconds = 0;  // the quad stage's time budget ("time_budget_s", QuadStage::budgetSeconds)
};

// The mesh's own numbers, measured on the finished mesh: "order", "hexes", "nodes", "layers", "inverted_hexes",
// "worst_hex_at", "scaled_jacobian", "aspect_ratio", "volume", "boundary" and "validation".
struct MeshMeasures {
  int order = 1;  // 2 for 20-node hexes
  std::size_t hexes = 0, nodes = 0;
  int layers = 0;
  QualityReport quality;  // without the per-hex scaled Jacobian (MeshResult::scaledJacobian holds it)
  BoundaryCheck boundary;
  double cadVolume = 0;                     // the part's volume, without the junctions left out
  long cadEuler = 0;                        // the CAD boundary's Euler characteristic
  std::vector<ValidationFailure> failures;  // the validation checks failed (validateMesh)

  bool passed() const { return failures.empty(); }
  double relativeVolumeError() const { return (quality.volume - cadVolume) / cadVolume; }
  bool sameTopologyAsCad() const { return boundary.eulerCharacteristic == cadEuler; }
};

struct MeshReport {
  std::map<std::string, StageTime> stages;  // by stage name, each stage that ran
  std::size_t facesSplit = 0;               // faces partly wall, partly rim, split (mixed_faces.hpp)
  std::vector<JunctionRecord> junctions;    // meshed, or left out with --drop-junctions
  double junctionsLeftOut = 0;              // their estimated volume
  double thickness = 0;                     // the wall thickness
  FaceCounts faces;
  MemoryEstimate memory;  // of the planned size, before meshing
  std::size_t bubbles = 0;
  TetFilterCounts tetsDropped;
  std::size_t tetsKept = 0;
  std::map<std::string, std::size_t> tetClasses;  // classifyTets
  ChordalRecord chordal;
  double size = 0;         // the quad size used
  std::string sizeSource;  // how it was chosen
  std::string sizing;      // "adaptive" or "uniform"
  SmallFeatures smallFeatures;
  QuadMeshCounts quadMesh;
  UntangleResult untangled;  // the sweep's untangling
  RimProjectionStats rimProjection;
  RimCapStats rimCap;
  SmoothingStats smoothing;
  SharpEdgeStats sharpEdges;
  CreaseChainStats creaseChains;            // a lap's creases followed by the quads (crease_chains.hpp)
  std::optional<QuadraticStats> quadratic;  // order 2 only
  SurfaceGroupStats surfaceGroups;
  BoundaryDeviation boundaryDeviation;
  std::optional<double> aspectRatioHit;  // with --aspect: share of the hexes within 10 % of it
  std::optional<ShellRecord> shell;      // with MeshOptions::shell (of all the solids together, also in each solid's)
  MeshMeasures mesh;
  // Several solids, each meshed on its own: their reports; the fields above are then unused but `mesh` (of them
  // all together).
  std::vector<MeshReport> solids;
};

// The counts of a wall classification, a chordal surface and a quad mesh as the report keeps them.
FaceCounts countFaces(const WallSides& sides);
ChordalRecord countChordal(const ChordalSurface& cut);  // without the rim and fairing numbers
QuadMeshCounts countQuadMesh(const QuadMesh& quads);

// [in,out] report: the stages' lengths (wall thickness, size, the small features' and junctions' places, the
// chordal rim's largest move, the boundary deviation, the quadratic nodes' largest move) divided by `unit`
// (pipeline lengths per input length, CadSolid::unit), the junctions' areas by unit^2 and volumes by unit^3.
// `mesh` and junctionsLeftOut are not touched: they are measured on the mesh in the input's units.
void toInputUnits(MeshReport& report, double unit);

// The report of a mesh of several solids each meshed on its own. [in] solids: their reports, in order; [in] whole:
// the measures of their meshes together, whose CAD volume and Euler characteristic become the solids' sums and
// whose validation failures the solids' failures, each prefixed with its solid ("solid 2: ...").
MeshReport mergeSolids(std::vector<MeshReport> solids, MeshMeasures whole);

}  // namespace hexlayer
