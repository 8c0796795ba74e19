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

void checkFits(const HexMesh& mesh, const std::vector<NodeSet>& nodeSets, const std::vector<CellField>& cellFields) {
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

}  // namespace

std::vector<int> elementNodes(const HexMesh& mesh, std::size_t h) {
  std::vector<int> ids(mesh.hexes[h].begin(), mesh.hexes[h].end());
  if (mesh.quadratic()) ids.insert(ids.end(), mesh.midEdges[h].begin(), mesh.midEdges[h].end());
  return ids;
}

std::string formatDouble(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

void writeMesh(const std::string& path, const HexMesh& mesh, const std::vector<NodeSet>& nodeSets,
               const std::vector<CellField>& cellFields) {
  const std::string ext = lowerExtension(path);
  if (ext != ".inp" && ext != ".vtu" && ext != ".msh")
    throw usageError("unknown output format '" + ext + "' of '" + path + "': use .inp, .vtu or .msh");
  checkFits(mesh, nodeSets, cellFields);
  std::ofstream out(path);
  if (!out) throw inputError("cannot open the output file '" + path + "' for writing");
  if (ext == ".inp") writeInp(out, mesh, nodeSets);
  if (ext == ".vtu") writeVtu(out, mesh, nodeSets, cellFields);
  if (ext == ".msh") writeMsh(out, mesh, cellFields);
  out.close();
  if (!out) throw inputError("failed writing the output file '" + path + "'");
}

}  // namespace hexlayer
