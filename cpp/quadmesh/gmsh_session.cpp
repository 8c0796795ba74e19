#include "quadmesh/gmsh_session.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <type_traits>

// The C API function `fn` (its type from gmshc.h) called with these arguments and the error flag.
#define GMSH_CALL(fn, ...) call<decltype(fn)>(#fn, __VA_ARGS__)

namespace hexlayer {
namespace {

constexpr const char* kLibrary = "libgmsh.so.4.8";  // Debian 12's libgmsh4.8

}  // namespace

template <class F>
F* GmshSession::function(const char* name) const {
  void* f = dlsym(library_, name);
  if (!f) throw std::runtime_error(std::string("Gmsh's library has no ") + name);
  return reinterpret_cast<F*>(f);
}

template <class F, class... Args>
auto GmshSession::call(const char* name, Args... args) {
  int error = 0;
  auto check = [&] {
    if (error == 0) return;
    char* text = nullptr;
    int ignored = 0;
    function<decltype(gmshLoggerGetLastError)>("gmshLoggerGetLastError")(&text, &ignored);
    const std::string message = text && *text ? text : "Gmsh error " + std::to_string(error) + " in " + name;
    if (text) free_(text);
    throw std::runtime_error(message);
  };
  if constexpr (std::is_void_v<std::invoke_result_t<F*, Args..., int*>>) {
    function<F>(name)(args..., &error);
    check();
  } else {
    const auto result = function<F>(name)(args..., &error);
    check();
    return result;
  }
}

namespace {

// A C API array as a vector, the array freed with gmshFree.
template <class T>
std::vector<T> taken(T* data, std::size_t n, void (*free)(void*)) {
  std::vector<T> v(data, data + n);
  free(data);
  return v;
}

GmshDimTags pairs(const std::vector<int>& flat) {
  GmshDimTags p;
  for (std::size_t i = 0; i + 1 < flat.size(); i += 2) p.emplace_back(flat[i], flat[i + 1]);
  return p;
}

}  // namespace

GmshSession::GmshSession() {
  library_ = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (!library_) throw std::runtime_error(std::string("cannot load ") + kLibrary + ": " + dlerror());
  free_ = function<decltype(gmshFree)>("gmshFree");
  GMSH_CALL(gmshInitialize, 0, nullptr, 1);
  setNumber("General.Terminal", 0);
  setNumber("General.NumThreads", 1);  // deterministic output
}

GmshSession::~GmshSession() {
  int error = 0;
  function<decltype(gmshFinalize)>("gmshFinalize")(&error);
  dlclose(library_);
}

void GmshSession::setNumber(const std::string& option, double value) { GMSH_CALL(gmshOptionSetNumber, option.c_str(), value); }

void GmshSession::addModel(const std::string& name) { GMSH_CALL(gmshModelAdd, name.c_str()); }

int GmshSession::addDiscreteSurface() { return GMSH_CALL(gmshModelAddDiscreteEntity, 2, -1, nullptr, std::size_t{0}); }

void GmshSession::addNodes(int dim, int tag, std::vector<std::size_t> tags, std::vector<double> coords) {
  GMSH_CALL(gmshModelMeshAddNodes, dim, tag, tags.data(), tags.size(), coords.data(), coords.size(), nullptr, std::size_t{0});
}

void GmshSession::addElementsByType(int tag, int type, std::vector<std::size_t> nodeTags) {
  GMSH_CALL(gmshModelMeshAddElementsByType, tag, type, nullptr, std::size_t{0}, nodeTags.data(), nodeTags.size());
}

void GmshSession::classifySurfaces(double angle, bool boundary, bool forReparametrization, double curveAngle) {
  GMSH_CALL(gmshModelMeshClassifySurfaces, angle, int{boundary}, int{forReparametrization}, curveAngle, 1);
}

void GmshSession::createGeometry() { GMSH_CALL(gmshModelMeshCreateGeometry, nullptr, std::size_t{0}); }

void GmshSession::synchronizeGeo() { call<decltype(gmshModelGeoSynchronize)>("gmshModelGeoSynchronize"); }

void GmshSession::setSizeCallback(double (*callback)(int, int, double, double, double, void*), void* data) {
  GMSH_CALL(gmshModelMeshSetSizeCallback, callback, data);
}

GmshDimTags GmshSession::boundary(const GmshDimTags& dimTags, bool combined, bool oriented, bool recursive) {
  std::vector<int> flat;
  for (const auto& [dim, tag] : dimTags) flat.push_back(dim), flat.push_back(tag);
  int* out = nullptr;
  std::size_t n = 0;
  GMSH_CALL(gmshModelGetBoundary, flat.data(), flat.size(), &out, &n, int{combined}, int{oriented}, int{recursive});
  return pairs(taken(out, n, free_));
}

GmshDimTags GmshSession::entities(int dim) {
  int* out = nullptr;
  std::size_t n = 0;
  GMSH_CALL(gmshModelGetEntities, &out, &n, dim);
  return pairs(taken(out, n, free_));
}

void GmshSession::parametrizationBounds(int dim, int tag, std::vector<double>& lo, std::vector<double>& hi) {
  double *min = nullptr, *max = nullptr;
  std::size_t nMin = 0, nMax = 0;
  GMSH_CALL(gmshModelGetParametrizationBounds, dim, tag, &min, &nMin, &max, &nMax);
  lo = taken(min, nMin, free_);
  hi = taken(max, nMax, free_);
}

std::vector<double> GmshSession::value(int dim, int tag, std::vector<double> parameters) {
  double* coords = nullptr;
  std::size_t n = 0;
  GMSH_CALL(gmshModelGetValue, dim, tag, parameters.data(), parameters.size(), &coords, &n);
  return taken(coords, n, free_);
}

void GmshSession::setTransfiniteCurve(int tag, int nodes) { GMSH_CALL(gmshModelMeshSetTransfiniteCurve, tag, nodes, "Progression", 1.0); }

void GmshSession::setTransfiniteSurface(int tag) { GMSH_CALL(gmshModelMeshSetTransfiniteSurface, tag, "Left", nullptr, std::size_t{0}); }

void GmshSession::setRecombine(int dim, int tag) { GMSH_CALL(gmshModelMeshSetRecombine, dim, tag); }

void GmshSession::generate(int dim) { GMSH_CALL(gmshModelMeshGenerate, dim); }

void GmshSession::elementsByType(int type, std::vector<std::size_t>& tags, std::vector<std::size_t>& nodeTags) {
  std::size_t *elements = nullptr, *nodes = nullptr;
  std::size_t nElements = 0, nNodes = 0;
  GMSH_CALL(gmshModelMeshGetElementsByType, type, &elements, &nElements, &nodes, &nNodes, -1, std::size_t{0}, std::size_t{1});
  tags = taken(elements, nElements, free_);
  nodeTags = taken(nodes, nNodes, free_);
}

void GmshSession::nodes(std::vector<std::size_t>& tags, std::vector<double>& coords) {
  std::size_t* nodeTags = nullptr;
  double *xyz = nullptr, *parameters = nullptr;
  std::size_t nTags = 0, nXyz = 0, nParameters = 0;
  GMSH_CALL(gmshModelMeshGetNodes, &nodeTags, &nTags, &xyz, &nXyz, &parameters, &nParameters, -1, -1, 1, 0);
  tags = taken(nodeTags, nTags, free_);
  coords = taken(xyz, nXyz, free_);
  free_(parameters);
}

}  // namespace hexlayer
