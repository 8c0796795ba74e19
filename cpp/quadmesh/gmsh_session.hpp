// Gmsh's C API (gmshc.h) from libgmsh loaded when a session opens (dlopen), not linked: binding the
// symbols of libgmsh and of the libraries it pulls in (FLTK, X11, OpenGL, OpenCASCADE's viewer)
// cost every run about 35 ms at start-up, though a part meshed by a block grid never calls Gmsh.
// A session is opened in the child process that runs Gmsh (quad_mesh.cpp) and closed with it.
#pragma once
#include <gmshc.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hexlayer {

using GmshDimTags = std::vector<std::pair<int, int>>;

// One Gmsh session: initialized on construction (terminal output off, one thread for deterministic
// output), finalized on destruction. Every call throws std::runtime_error with Gmsh's last logged
// error if Gmsh reports one; the constructor throws if libgmsh cannot be loaded.
class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  void setNumber(const std::string& option, double value);
  void addModel(const std::string& name);
  int addDiscreteSurface();
  void addNodes(int dim, int tag, std::vector<std::size_t> tags, std::vector<double> coords);
  void addElementsByType(int tag, int type, std::vector<std::size_t> nodeTags);
  void classifySurfaces(double angle, bool boundary, bool forReparametrization, double curveAngle);
  void createGeometry();
  void synchronizeGeo();
  // callback(dim, tag, x, y, z, data): the mesh size at (x, y, z).
  void setSizeCallback(double (*callback)(int, int, double, double, double, void*), void* data);
  GmshDimTags boundary(const GmshDimTags& dimTags, bool combined, bool oriented, bool recursive);
  GmshDimTags entities(int dim);
  void parametrizationBounds(int dim, int tag, std::vector<double>& lo, std::vector<double>& hi);
  std::vector<double> value(int dim, int tag, std::vector<double> parameters);
  void setTransfiniteCurve(int tag, int nodes);
  void setTransfiniteSurface(int tag);
  void setRecombine(int dim, int tag);
  void generate(int dim);
  void elementsByType(int type, std::vector<std::size_t>& tags, std::vector<std::size_t>& nodeTags);
  void nodes(std::vector<std::size_t>& tags, std::vector<double>& coords);  // all nodes, with those on boundaries

 private:
  template <class F>
  F* function(const char* name) const;
  // Calls the C API function `name` with the arguments and Gmsh's error flag; throws on an error.
  template <class F, class... Args>
  auto call(const char* name, Args... args);

  void* library_ = nullptr;
  void (*free_)(void*) = nullptr;  // gmshFree, for the arrays the API returns
};

}  // namespace hexlayer
