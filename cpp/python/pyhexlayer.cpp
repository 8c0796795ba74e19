// pyhexlayer: the Hex-Layer pipeline as a Python module (pybind11), for FreeCAD's workbench and macros.
// mesh_file(path, ...) and mesh_brep(text, ...) take the CLI's options as keywords and return a MeshResult
// of NumPy arrays and the report dict. hexlayer::Error becomes UsageError / InputError / GeometryError /
// ValidationError (subclasses of HexLayerError, with the CLI's exit code and message); no C++ exception reaches the
// interpreter.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Standard_Failure.hxx>

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/version.hpp"
#include "pipeline/pipeline.hpp"
#include "pipeline/report.hpp"

namespace py = pybind11;

namespace {

using hexlayer::ExitCode;

// The options of the CLI, checked by the core as the CLI checks them.
using Options = hexlayer::MeshOptions;

Options makeOptions(int layers, double size, const std::string& sizing, double aspect, int order, bool dropJunctions) {
  Options o;
  o.dropJunctions = dropJunctions;
  o.layers = layers;
  o.size = size;
  o.sizing = sizing;
  o.aspect = aspect;
  o.order = order;
  hexlayer::validateOptions(o);
  return o;
}

// The options of one run besides the meshing ones: force and shell.
Options forRun(Options o, bool force, bool shell) {
  o.force = force, o.shell = shell;
  return o;
}

// ---- results as Python objects -------------------------------------------------------------------

py::object toPython(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& item : j) list.append(toPython(item));
      return std::move(list);
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, value] : j.items()) dict[py::str(key)] = toPython(value);
      return std::move(dict);
    }
    default:
      return py::none();
  }
}

struct PyMeshResult {
  py::array_t<double> nodes;           // (N, 3)
  py::array_t<long long> hexes;        // (M, 8) or (M, 20), 0-based: 8 corners, then 12 mid-edge nodes (C3D20)
  py::array_t<double> scaledJacobian;  // (M,)
  py::dict nodeSets;                   // name -> node ids (0-based)
  py::dict faceNodes;                  // "FaceN" -> ids of the boundary nodes on CAD face N (0-based)
  py::dict faceElements;               // "FaceN" -> (K, 2): hex (0-based), local face 0..5 (CalculiX S1..S6)
  py::dict report;
  py::array_t<double> chordalVertices;   // (V, 3)
  py::array_t<long long> chordalFacets;  // (F, 4), triangles end with -1
  py::array_t<double> quadNodes;         // (Q, 3)
  py::array_t<long long> quads;          // (K, 4)
  py::array_t<long long> nodeLayer;      // (N,)
  // shell=True: the mid-surface shell (hexlayer::ShellMesh), else empty
  py::array_t<double> shellNodes;        // (S, 3)
  py::array_t<long long> shellElements;  // (E, 4) or (E, 8): corners, then the mid-side nodes (S8R)
  py::array_t<double> shellThickness;    // (S,)
  py::dict shellNodeSets;                // "RIM", "Face1".."FaceN" -> shell node ids (0-based)
};

py::array_t<double> nodeArray(const std::vector<hexlayer::Vec3>& nodes) {
  py::array_t<double> a({static_cast<py::ssize_t>(nodes.size()), py::ssize_t(3)});
  auto v = a.mutable_unchecked<2>();
  for (size_t i = 0; i < nodes.size(); ++i)
    for (int k = 0; k < 3; ++k) v(i, k) = nodes[i][k];
  return a;
}

// One row per hex: its 8 corners, then (quadratic mesh) its 12 mid-edge nodes in kHexEdges order, which
// is CalculiX's C3D20 order.
py::array_t<long long> hexArray(const hexlayer::HexMesh& mesh) {
  const int width = mesh.quadratic() ? 20 : 8;
  py::array_t<long long> a({static_cast<py::ssize_t>(mesh.hexes.size()), py::ssize_t(width)});
  auto v = a.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.hexes.size(); ++i) {
    for (int k = 0; k < 8; ++k) v(i, k) = mesh.hexes[i][k];
    for (int k = 8; k < width; ++k) v(i, k) = mesh.midEdges[i][k - 8];
  }
  return a;
}

// One row per cell (facet, quad) of its node ids.
template <std::size_t W>
py::array_t<long long> cellArray(const std::vector<std::array<int, W>>& cells) {
  py::array_t<long long> a({static_cast<py::ssize_t>(cells.size()), static_cast<py::ssize_t>(W)});
  auto v = a.mutable_unchecked<2>();
  for (size_t i = 0; i < cells.size(); ++i)
    for (std::size_t k = 0; k < W; ++k) v(i, k) = cells[i][k];
  return a;
}

template <class T>
py::array_t<T> vectorArray(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

// 0-based node ids as int64.
py::array_t<long long> idArray(const std::vector<int>& ids) {
  return vectorArray(std::vector<long long>(ids.begin(), ids.end()));
}

// The shell's elements, one row each: 4 corners, then (S8R) the mid-side nodes of edges 0-1, 1-2, 2-3, 3-0.
void addShell(PyMeshResult& p, const hexlayer::ShellMesh& s) {
  p.shellNodes = nodeArray(s.nodes);
  const int width = s.quadratic() ? 8 : 4;
  p.shellElements = py::array_t<long long>({static_cast<py::ssize_t>(s.quads.size()), py::ssize_t(width)});
  auto v = p.shellElements.mutable_unchecked<2>();
  for (std::size_t e = 0; e < s.quads.size(); ++e)
    for (int k = 0; k < width; ++k) v(e, k) = k < 4 ? s.quads[e][k] : s.midSides[e][k - 4];
  p.shellThickness = vectorArray(s.thickness);
  for (const hexlayer::NodeSet& set : s.nodeSets) p.shellNodeSets[py::str(set.name)] = idArray(set.nodes);
  for (const hexlayer::SurfaceGroup& g : s.faces) p.shellNodeSets[py::str(g.name)] = idArray(g.nodes);
}

PyMeshResult toPython(const hexlayer::MeshResult& r) {
  PyMeshResult p;
  p.nodes = nodeArray(r.mesh.nodes);
  p.hexes = hexArray(r.mesh);
  p.scaledJacobian = vectorArray(r.scaledJacobian);
  for (const hexlayer::NodeSet& set : r.nodeSets) p.nodeSets[py::str(set.name)] = idArray(set.nodes);
  for (const hexlayer::SurfaceGroup& g : r.surfaceGroups) {
    p.faceNodes[py::str(g.name)] = idArray(g.nodes);
    py::array_t<long long> faces({static_cast<py::ssize_t>(g.hexFaces.size()), py::ssize_t(2)});
    auto v = faces.mutable_unchecked<2>();
    for (std::size_t i = 0; i < g.hexFaces.size(); ++i) v(i, 0) = g.hexFaces[i].hex, v(i, 1) = g.hexFaces[i].localFace;
    p.faceElements[py::str(g.name)] = faces;
  }
  p.report = toPython(hexlayer::toJson(r.report));
  p.chordalVertices = nodeArray(r.chordalSurface.vertices);
  p.chordalFacets = cellArray(r.chordalSurface.facets);
  p.quadNodes = nodeArray(r.quadMesh.nodes);
  p.quads = cellArray(r.quadMesh.quads);
  p.nodeLayer = vectorArray(std::vector<long long>(r.mesh.nodeLayer.begin(), r.mesh.nodeLayer.end()));
  addShell(p, r.shell);
  return p;
}

// ---- running the pipeline without the GIL -----------------------------------------------------------

// The pipeline runs with the GIL released; each progress event takes it back to let Ctrl-C stop the run (between
// stages and between a stage's steps), and each line (a finished stage, a note: Progress::isLine) to call
// `progress` (if not None). An exception of the callback ends the run and reaches the caller.
// The callback is held by pointer: copies of the std::function (made without the GIL) never touch its refcount.
hexlayer::MeshResult runReleased(const std::function<hexlayer::MeshResult(const hexlayer::MeshOptions&)>& run,
                                 Options o, const py::object& progress) {
  const py::object* callback = &progress;
  o.progress = [callback](const hexlayer::Progress& event) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (event.isLine() && !callback->is_none()) (*callback)(event.line());
  };
  py::gil_scoped_release release;
  return run(o);
}

// A temporary .brep file holding `text`, removed when this goes out of scope.
class TemporaryBrep {
 public:
  explicit TemporaryBrep(const std::string& text) {
    std::string pattern = (std::filesystem::temp_directory_path() / "pyhexlayer-XXXXXX.brep").string();
    const int fd = mkstemps(pattern.data(), 5);
    if (fd < 0) throw hexlayer::inputError("cannot create a temporary file for the BREP string");
    close(fd);
    path_ = pattern;
    std::ofstream(path_, std::ios::binary) << text;
  }
  ~TemporaryBrep() { std::remove(path_.c_str()); }
  TemporaryBrep(const TemporaryBrep&) = delete;
  TemporaryBrep& operator=(const TemporaryBrep&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The core names its input file in its messages: say "the BREP string" instead of the temporary file.
std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

PyMeshResult meshFile(const std::string& path, const Options& o, const py::object& progress) {
  return toPython(
      runReleased([&](const hexlayer::MeshOptions& core) { return hexlayer::meshFile(path, core); }, o, progress));
}

// The BREP string is meshed through a temporary file, so it takes the file's path in the core: the same
// reading, solid extraction (solids, or the solids closed shells bound) and validation as a .brep file.
PyMeshResult meshBrep(const std::string& text, const Options& o, const py::object& progress) {
  const TemporaryBrep file(text);
  try {
    return meshFile(file.path(), o, progress);
  } catch (const hexlayer::Error& e) {
    throw hexlayer::Error(e.code(), replaceAll(e.what(), "'" + file.path() + "'", "the BREP string"));
  }
}

// ---- exceptions ---------------------------------------------------------------------------------------

struct ExceptionTypes {
  py::object base, usage, input, geometry, validation;
  const py::object& of(ExitCode code) const {
    switch (code) {
      case ExitCode::BadUsage:
        return usage;
      case ExitCode::BadInput:
        return input;
      case ExitCode::UnsupportedGeometry:
        return geometry;
      case ExitCode::InvalidMesh:
        return validation;
      default:
        return base;
    }
  }
};

py::object defineException(py::module_& m, const char* name, PyObject* base, int exitCode, const char* doc) {
  py::object type = py::reinterpret_steal<py::object>(
      PyErr_NewExceptionWithDoc((std::string("pyhexlayer.") + name).c_str(), doc, base, nullptr));
  if (!type) throw py::error_already_set();
  type.attr("exit_code") = exitCode;
  m.attr(name) = type;
  return type;
}

ExceptionTypes defineExceptions(py::module_& m) {
  ExceptionTypes t;
  t.base = defineException(m, "HexLayerError", PyExc_Exception, int(ExitCode::Internal),
                           "A meshing run failed; exit_code is the CLI's exit code, str() its message.");
  t.usage =
      defineException(m, "UsageError", t.base.ptr(), int(ExitCode::BadUsage), "A bad option value (exit code 2).");
  t.input = defineException(m, "InputError", t.base.ptr(), int(ExitCode::BadInput),
                            "A missing, unreadable or invalid input file or shape (exit code 3).");
  t.geometry = defineException(m, "GeometryError", t.base.ptr(), int(ExitCode::UnsupportedGeometry),
                               "A valid solid the method does not handle, e.g. not thin (exit code 4).");
  t.validation = defineException(m, "ValidationError", t.base.ptr(), int(ExitCode::InvalidMesh),
                                 "The mesh failed a validation check, e.g. an inverted hex (exit code 6); force=True "
                                 "returns it with the failures in report['validation'].");
  return t;
}

void raise(const py::object& type, const std::string& message, int exitCode) {
  py::object error = type(message);
  error.attr("exit_code") = exitCode;
  PyErr_SetObject(type.ptr(), error.ptr());
}

void registerTranslator(const ExceptionTypes& types) {
  static const ExceptionTypes* translated = new ExceptionTypes(types);  // lives as long as the interpreter
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const hexlayer::Error& e) {
      raise(translated->of(e.code()), e.what(), int(e.code()));
    } catch (const Standard_Failure& e) {  // OpenCASCADE's exceptions are not std::exceptions
      PyErr_SetString(PyExc_RuntimeError, (std::string("OpenCASCADE: ") + e.GetMessageString()).c_str());
    }
  });
}

// The keyword arguments shared by mesh_file, mesh_brep and check_options.
#define HEXLAYER_OPTION_ARGS                                                                   \
  py::kw_only(), py::arg("layers") = 2, py::arg("size") = 0.0, py::arg("sizing") = "adaptive", \
                 py::arg("aspect") = 0.0, py::arg("order") = 1, py::arg("drop_junctions") = false

constexpr const char* kOptionsDoc =
    "layers: hex layers through the thickness (1-64); size: quad edge length, 0 = the wall thickness; "
    "sizing: 'uniform' or 'adaptive' (radius function and curvature); aspect: in-plane size / layer thickness instead "
    "of size, 0 = off; "
    "order: 1 = linear hexes (M, 8), 2 = quadratic hexes (M, 20), wall mid-edge nodes on the CAD walls; "
    "drop_junctions: mesh the largest sheet and leave out ribs, bosses and flanges standing on it (else a straight "
    "rib on a flat rectangular plate is meshed with it, the others raise GeometryError); "
    "progress: callable taking one line per finished stage, or None "
    "(an exception it raises ends the run); force: return a mesh that failed validation instead of raising "
    "ValidationError; shell: also the mid-surface shell (shell_nodes, shell_elements, shell_thickness, "
    "shell_node_sets, report['shell']).";

}  // namespace

PYBIND11_MODULE(pyhexlayer, m) {
  m.doc() =
      "Hex-Layer: layered all-hex FEM meshes of thin CAD solids.\n\n"
      "MeshResult.hexes holds 0-based node ids, one row per hex. Order 1: (M, 8), the corners; 0-3 the bottom "
      "quad (counter-clockwise seen from the top side), 4-7 the quad above them. Order 2: (M, 20), the same 8 "
      "corners, then the 12 mid-edge nodes in CalculiX's C3D20 order: edges 0-1, 1-2, 2-3, 3-0, 4-5, 5-6, 6-7, "
      "7-4, 0-4, 1-5, 2-6, 3-7. A mid-edge node is shared by all hexes around its edge.";
  m.attr("__version__") = hexlayer::kVersion;
  registerTranslator(defineExceptions(m));

  py::class_<PyMeshResult>(m, "MeshResult", "Nodes, hexes, per-hex quality, node sets and the report of one run.")
      .def_readonly("nodes", &PyMeshResult::nodes, "float64 (N, 3) node coordinates")
      .def_readonly(
          "hexes", &PyMeshResult::hexes,
          "int64 (M, 8) or, order 2, (M, 20) 0-based node ids: corners 0-3 the bottom quad, 4-7 the quad above "
          "them, then the 12 mid-edge nodes in C3D20 order (see the module doc)")
      .def_readonly("scaled_jacobian", &PyMeshResult::scaledJacobian, "float64 (M,) Verdict scaled Jacobian per hex")
      .def_readonly("node_sets", &PyMeshResult::nodeSets, "dict: 'TOP', 'BOTTOM', 'RIM' -> int64 node ids (0-based)")
      .def_readonly("face_nodes", &PyMeshResult::faceNodes,
                    "dict: 'Face1'..'FaceN' (FreeCAD's numbering of the CAD faces) -> int64 ids (0-based) of the "
                    "boundary nodes on that face; a node on a CAD edge is on every face there")
      .def_readonly("face_elements", &PyMeshResult::faceElements,
                    "dict: 'Face1'..'FaceN' -> int64 (K, 2): hex row (0-based) and its local face 0..5 on that CAD "
                    "face (0 bottom 0-3-2-1, 1 top 4-5-6-7, 2..5 sides 0-1-5-4 .. 3-0-4-7: CalculiX S1..S6)")
      .def_readonly("report", &PyMeshResult::report, "dict: the CLI's JSON report")
      .def_readonly("chordal_vertices", &PyMeshResult::chordalVertices,
                    "float64 (V, 3): vertices of the chordal surface (§5) the quad mesh was made on (after fairing)")
      .def_readonly("chordal_facets", &PyMeshResult::chordalFacets,
                    "int64 (F, 4) 0-based rows of chordal_vertices: quads, and triangles padded with -1")
      .def_readonly("quad_nodes", &PyMeshResult::quadNodes,
                    "float64 (Q, 3): nodes of the quad mesh on the chordal surface")
      .def_readonly("quads", &PyMeshResult::quads,
                    "int64 (K, 4) 0-based rows of quad_nodes: the quads the sweep made the hexes of")
      .def_readonly("node_layer", &PyMeshResult::nodeLayer,
                    "int64 (N,): layer of each node, 0 = bottom surface .. layers = top surface; -1 = a mid-edge node "
                    "between two layers (order 2), or a rim cap's node inside the part. A hex's layer is the lowest "
                    "of its corners' that are in one")
      .def_readonly("shell_nodes", &PyMeshResult::shellNodes,
                    "float64 (S, 3), shell=True: the mid-surface shell's nodes: the quad mesh's (on the chordal "
                    "surface), then order 2's mid-side nodes (midway between the walls); else (0, 3)")
      .def_readonly("shell_elements", &PyMeshResult::shellElements,
                    "int64 (E, 4) or, order 2, (E, 8) 0-based rows of shell_nodes: corners counter-clockwise seen "
                    "from the top wall, then the mid-side nodes of edges 0-1, 1-2, 2-3, 3-0 (S4 / S8R)")
      .def_readonly("shell_thickness", &PyMeshResult::shellThickness,
                    "float64 (S,): the wall thickness at each shell node (its sweep line's wall ends along the normal)")
      .def_readonly("shell_node_sets", &PyMeshResult::shellNodeSets,
                    "dict: 'RIM' (the shell's boundary) and 'Face1'..'FaceN' (the shell nodes whose sweep line ends on "
                    "the wall FaceN, or whose column lies on the rim face FaceN) -> int64 ids (0-based)")
      .def("__repr__", [](const PyMeshResult& r) {
        return "<pyhexlayer.MeshResult " + std::to_string(r.hexes.shape(0)) + " hexes, " +
               std::to_string(r.nodes.shape(0)) + " nodes>";
      });

  m.def(
      "mesh_file",
      [](const std::string& path, int layers, double size, const std::string& sizing, double aspect, int order,
         bool dropJunctions, const py::object& progress, bool force, bool shell) {
        return meshFile(path, forRun(makeOptions(layers, size, sizing, aspect, order, dropJunctions), force, shell),
                        progress);
      },
      py::arg("path"), HEXLAYER_OPTION_ARGS, py::arg("progress") = py::none(), py::arg("force") = false,
      py::arg("shell") = false,
      (std::string("Meshes every solid of a STEP, IGES or BREP file. ") + kOptionsDoc).c_str());
  m.def(
      "mesh_brep",
      [](const std::string& text, int layers, double size, const std::string& sizing, double aspect, int order,
         bool dropJunctions, const py::object& progress, bool force, bool shell) {
        return meshBrep(text, forRun(makeOptions(layers, size, sizing, aspect, order, dropJunctions), force, shell),
                        progress);
      },
      py::arg("brep"), HEXLAYER_OPTION_ARGS, py::arg("progress") = py::none(), py::arg("force") = false,
      py::arg("shell") = false,
      (std::string("Meshes every solid of a shape in OpenCASCADE's BREP text (FreeCAD: Shape.exportBrepToString()). ") +
       kOptionsDoc)
          .c_str());
  m.def(
      "check_options",
      [](int layers, double size, const std::string& sizing, double aspect, int order, bool dropJunctions) {
        makeOptions(layers, size, sizing, aspect, order, dropJunctions);
      },
      HEXLAYER_OPTION_ARGS, "Raises UsageError, with the CLI's message, if an option value is not supported.");
}
