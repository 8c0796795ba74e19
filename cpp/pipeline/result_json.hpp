// The whole meshing result for another process: the FreeCAD workbench runs the `hexlayer` executable out of
// FreeCAD's process and reads this back (Mod/HexLayer/hexlayer_fem/mesher.py), under the names of
// pyhexlayer.MeshResult's attributes.
#pragma once
#include <nlohmann/json.hpp>

#include "pipeline/pipeline.hpp"

namespace hexlayer {

// [in] r: a meshing result. Returns {"nodes": [[x, y, z], ...], "hexes": [[8 or 20 node ids], ...] (corners, then
// the mid-edge nodes in kHexEdges order), "scaled_jacobian": [...], "node_sets": {"TOP": [...], ...},
// "face_nodes": {"Face1": [...], ...}, "face_elements": {"Face1": [[hex, local face], ...], ...}, "report": {...},
// "chordal_vertices", "chordal_facets" (triangles padded with -1), "quad_nodes", "quads", "node_layer"}: ids 0-based.
nlohmann::json resultJson(const MeshResult& r);

}  // namespace hexlayer
