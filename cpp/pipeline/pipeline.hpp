// The Hex-Layer method end to end (paper §4, Figure 2): CAD solid -> bubbles -> tets -> chordal
// surface -> quad mesh -> sweep -> quality. Each stage is a call into its own folder.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "chordal/chordal_surface.hpp"
#include "core/child_process.hpp"
#include "core/progress.hpp"
#include "core/types.hpp"
#include "geometry/cad_solid.hpp"
#include "pipeline/mesh_report.hpp"
#include "quadmesh/quad_mesh.hpp"
#include "quadmesh/quad_stage.hpp"

namespace hexlayer {

class FaceBoxes;

struct MeshOptions {
  int layers = 2;                   // hex layers through the thickness (§7.2)
  double size = 0;                  // quad edge length on the chordal surface; 0 = chosen from the part
  int order = 1;                    // 1: 8-node hexes, 2: 20-node hexes with the wall mid-edge nodes on the CAD
  std::string sizing = "adaptive";  // "adaptive" or "uniform" (§6.1: radius function and curvature)
  double aspect = 0;                // in-plane quad size / layer thickness; 0 = off (size from --size or the wall)
  double minSize = 0, maxSize = 0;  // bounds of the adaptive size; 0 = a quarter and 4 x the size
  bool dropJunctions = false;       // leave out ribs/bosses on the largest sheet (else a T is meshed, others refused)
  bool force = false;               // hand on a mesh that failed validation (report "validation") instead of throwing
  bool shell = false;               // also the mid-surface shell (MeshResult::shell, report "shell")
  // Each stage's start and end, how far a long stage is (the quad stage: its tries) and notes (may be empty).
  // Called on the calling thread, between and inside the stages.
  ProgressCallback progress;
  // The quad stage's time budgets (quad_stage.hpp: --quad-budget, --quad-try-budget), in seconds; 0 = from the
  // part's size. A Gmsh try that runs out of its budget is a failed try; after the stage's no try starts.
  double quadTryBudget = 0, quadStageBudget = 0;
  // Forks the Gmsh runs of the gaps round walls' feet (child_process.hpp): meshFile starts one, Gmsh open in it,
  // before it reads the part; null: each run is forked from this process.
  std::shared_ptr<ForkServer> gmshRuns;
  // A junction piece's ring grid (a boss's half across the plate from the other's ring of this many foot columns):
  // its quads round; 0 = from the size.
  int ringAround = 0;
};

struct MeshResult {
  HexMesh mesh;                             // all solids of the input, one conformal mesh per solid
  std::vector<NodeSet> nodeSets;            // TOP, BOTTOM, RIM
  std::vector<SurfaceGroup> surfaceGroups;  // one per CAD face, Face1..FaceN as FreeCAD numbers them
  MeshReport report;                        // numbers of every stage; toJson (report.hpp) writes them
  std::vector<double> scaledJacobian;       // per hex, as measured for the report
  // The stages as used (§5-6), for looking at them: the (faired) chordal surface the quad mesh was made on,
  // and that quad mesh, which the sweep turned into the hexes (mesh.nodeLayer: each node's layer).
  ChordalSurface chordalSurface;
  QuadMesh quadMesh;
  ShellMesh shell;  // with MeshOptions::shell: the quad mesh as shell elements (shell_mesh.hpp), else empty
};

// Checks the options; throws usageError naming the bad one.
void validateOptions(const MeshOptions& options);

// Meshes every solid of a CAD file (STEP, IGES, BREP). The mesh is validated (report "validation");
// unless options.force, a failed check throws validationError naming the check and the place.
MeshResult meshFile(const std::string& path, const MeshOptions& options);

// Meshes one solid; validated like meshFile. A part where one rib stands on a flat plate (a T junction, issue 18)
// is cut at the rib's foot and its pieces meshed and joined (junction_mesh.hpp); other junctions are refused
// (geometryError) unless options.dropJunctions.
MeshResult meshSolid(const TopoDS_Solid& solid, const MeshOptions& options);

// Replaces the quads the quad stage made, before the sweep (a plate's quads carrying a rib's footprint, issue 18).
// [in] cad: the solid as the stages see it (scaled by cad.unit); [in,out] stage: its quads replaced.
using QuadEdit = std::function<void(const CadSolid& cad, QuadStage& stage)>;

// Edits the swept hexes before they are made order 2 (a piece's foot columns put across from another piece's foot).
// [in] cad: as QuadEdit's; [in] stage: the quads swept; [in,out] mesh: the hexes, in cad's units.
using HexEdit = std::function<void(const CadSolid& cad, const QuadStage& stage, HexMesh& mesh)>;

// meshSolid for a piece of a part (junction_mesh.hpp): the quad stage's quads replaced by `edit` (none: as made, and
// the boundary grouped as meshSolid's); with an edit, the boundary nodes are given CAD faces but not grouped (the
// joined part is: MeshResult::surfaceGroups empty). [in] solid, options, edit; [in] cutFaces: per face of the solid
// (TopExp::MapShapes' order), whether it is a cut through the part (a foot: CadSolid::cutInput); empty: none;
// [in,out] boxes: the exact boxes of faces the piece shares with the part and the other pieces (CadFaces); null:
// none; [in] hexEdit: run on the hexes after the sweep's stages, before order 2 (none: nothing).
MeshResult meshSolid(const TopoDS_Solid& solid, const MeshOptions& options, const QuadEdit& edit,
                     const std::vector<char>& cutFaces = {}, FaceBoxes* boxes = nullptr, const HexEdit& hexEdit = {});

}  // namespace hexlayer
