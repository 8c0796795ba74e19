#include "writers/writers.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>

#include "core/error.hpp"

namespace hexlayer {
namespace {

std::string lowerExtension(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void checkSurfaces(const HexMesh& mesh, const std::vector<SurfaceGroup>& surfaces) {
  for (const SurfaceGroup& g : surfaces) {
    for (int n : g.nodes)
      if (n < 0 || static_cast<std::size_t>(n) >= mesh.nodes.size())
        throw Error(ExitCode::Internal,
                    "surface group '" + g.name + "' has node " + std::to_string(n) + " out of range");
    for (const HexFace& f : g.hexFaces)
      if (f.hex < 0 || static_cast<std::size_t>(f.hex) >= mesh.hexes.size() || f.localFace < 0 || f.localFace > 5)
        throw Error(ExitCode::Internal,
                    "surface group '" + g.name + "' has a face of hex " + std::to_string(f.hex) + " out of range");
  }
}

void checkFits(const HexMesh& mesh, const MeshGroups& groups) {
  const std::vector<NodeSet>& nodeSets = groups.nodeSets;
  const std::vector<CellField>& cellFields = groups.cellFields;
  checkSurfaces(mesh, groups.surfaces);
  if (mesh.quadratic() && mesh.midEdges.size() != mesh.hexes.size())
    throw Error(ExitCode::Internal, "mid-edge nodes of " + std::to_string(mesh.midEdges.size()) + " hexes for " +
                                        std::to_string(mesh.hexes.size()) + " hexes");
  for (const CellField& f : cellFields)
    if (f.values.size() != mesh.hexes.size())
      throw Error(ExitCode::Internal, "cell field '" + f.name + "' has " + std::to_string(f.values.size()) +
                                          " values for " + std::to_string(mesh.hexes.size()) + " hexes");
  for (const NodeSet& s : nodeSets)
    for (int n : s.nodes)
      if (n < 0 || static_cast<std::size_t>(n) >= mesh.nodes.size())
        throw Error(ExitCode::Internal, "node set '" + s.name + "' has node " + std::to_string(n) + " out of range");
}

// Index into kHexEdges of the edge between local corners a and b.
int hexEdge(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if (std::minmax(a, b) == std::minmax(kHexEdges[e][0], kHexEdges[e][1])) return e;
  return -1;
}

// An element's corners, then its mid nodes (none if mids is null).
template <std::size_t C, std::size_t M>
ElementNodes cornersThenMids(const std::array<int, C>& corners, const std::array<int, M>* mids) {
  ElementNodes nodes;
  for (int n : corners) nodes.push_back(n);
  if (mids)
    for (int n : *mids) nodes.push_back(n);
  return nodes;
}

}  // namespace

ElementNodes boundaryFaceNodes(const HexMesh& mesh, const BoundaryFace& f) {
  ElementNodes nodes;
  for (int n : f.nodes) nodes.push_back(n);
  if (!mesh.quadratic()) return nodes;
  const std::array<int, 4>& local = kHexFaces[f.localFace];
  for (int i = 0; i < 4; ++i) nodes.push_back(mesh.midEdges[f.hex][hexEdge(local[i], local[(i + 1) % 4])]);
  return nodes;
}

ElementNodes elementNodes(const HexMesh& mesh, std::size_t h) {
  return cornersThenMids(mesh.hexes[h], mesh.quadratic() ? &mesh.midEdges[h] : nullptr);
}

ElementNodes shellElementNodes(const ShellMesh& shell, std::size_t e) {
  return cornersThenMids(shell.quads[e], shell.quadratic() ? &shell.midSides[e] : nullptr);
}

std::string formatDouble(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

namespace {

// The output stream of `path`, whose extension is .inp, .vtu or .msh (returned in ext).
std::ofstream openMeshFile(const std::string& path, std::string& ext) {
  ext = lowerExtension(path);
  if (ext != ".inp" && ext != ".vtu" && ext != ".msh")
    throw usageError("unknown output format '" + ext + "' of '" + path + "': use .inp, .vtu or .msh");
  std::ofstream out(path);
  if (!out) throw inputError("cannot open the output file '" + path + "' for writing");
  return out;
}

void closeMeshFile(std::ofstream& out, const std::string& path) {
  out.close();
  if (!out) throw inputError("failed writing the output file '" + path + "'");
}

// Opens `path` and writes it with the writer of its extension (each takes the stream), then closes it.
template <class Inp, class Vtu, class Msh>
void writeByExtension(const std::string& path, Inp&& inp, Vtu&& vtu, Msh&& msh) {
  std::string ext;
  std::ofstream out = openMeshFile(path, ext);
  ext == ".inp" ? inp(out) : ext == ".vtu" ? vtu(out) : msh(out);
  closeMeshFile(out, path);
}

}  // namespace

void writeMesh(const std::string& path, const HexMesh& mesh, const MeshGroups& groups) {
  checkFits(mesh, groups);
  writeByExtension(
      path, [&](std::ostream& o) { writeInp(o, mesh, groups); }, [&](std::ostream& o) { writeVtu(o, mesh, groups); },
      [&](std::ostream& o) { writeMsh(o, mesh, groups); });
}

void writeShellMesh(const std::string& path, const ShellMesh& shell) {
  if (shell.thickness.size() != shell.nodes.size() ||
      (shell.quadratic() && shell.midSides.size() != shell.quads.size()))
    throw Error(ExitCode::Internal, "the shell's thickness or mid-side nodes do not fit its nodes and elements");
  writeByExtension(
      path, [&](std::ostream& o) { writeShellInp(o, shell); }, [&](std::ostream& o) { writeShellVtu(o, shell); },
      [&](std::ostream& o) { writeShellMsh(o, shell); });
}

}  // namespace hexlayer
