// The whole meshing result for another process: the FreeCAD workbench runs the `hexlayer` executable out of
// FreeCAD's process and reads this back (Mod/HexLayer/hexlayer_fem/mesher.py), under the names of
// pyhexlayer.MeshResult's attributes.
#pragma once
#include <string>

#include "pipeline/pipeline.hpp"

namespace hexlayer {

// [in] path, r. Writes `path` (JSON: {"report": {...}, "binary": "<name of path>.bin", "arrays": {NAME: {"dtype":
// "<f8" or "<i8", "shape": [...], "offset": bytes}}}) and `path`.bin (the arrays' little-endian values, one after
// another). Arrays: nodes (N, 3), hexes (M, 8 or 20: corners, then the mid-edge nodes in kHexEdges order),
// scaled_jacobian (M), node_sets/TOP|BOTTOM|RIM, face_nodes/FaceK, face_elements/FaceK (rows of hex, local face),
// chordal_vertices, chordal_facets (F, 4; triangles padded with -1), quad_nodes, quads, node_layer; with a shell
// (MeshOptions::shell) shell_nodes, shell_elements (K, 4 or 8), shell_thickness, shell_node_sets/RIM,
// shell_face_nodes/FaceK; ids 0-based.
// Binary: 200 000 hexes are read back in a fraction of a second, where JSON text took longer than half the meshing.
// Throws inputError if a file cannot be written.
void writeResult(const std::string& path, const MeshResult& r);

}  // namespace hexlayer
