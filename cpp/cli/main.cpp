// hexlayer: the command-line tool. `hexlayer mesh INPUT -o OUT [--layers N] [--size H | --aspect A] [--sizing
// uniform|adaptive]
// [--min-size H] [--max-size H] [--order 1|2] [--shell] [--report R] [--force] [--quiet]`, `hexlayer --version`
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <Standard_Failure.hxx>
#include <csignal>
#include <cstring>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "core/error.hpp"
#include "core/progress_printer.hpp"
#include "core/version.hpp"
#include "pipeline/pipeline.hpp"
#include "pipeline/report.hpp"
#include "pipeline/result_file.hpp"
#include "writers/writers.hpp"

namespace {

using hexlayer::ExitCode;

// A crash in a library (OpenCASCADE's healing has been seen to dereference null on some faces) ends the run with a
// line that says so and the internal-error exit code, not a bare signal: only async-signal-safe calls here.
void crashed(int signal) {
  const char* name = signal == SIGSEGV  ? "segmentation fault"
                     : signal == SIGBUS ? "bus error"
                     : signal == SIGFPE ? "arithmetic exception"
                                        : "illegal instruction";
  const char head[] = "hexlayer: internal error: crashed (", tail[] = "); please report it with the input file\n";
  [[maybe_unused]] ssize_t w = write(STDERR_FILENO, head, sizeof head - 1);
  w = write(STDERR_FILENO, name, std::strlen(name));
  w = write(STDERR_FILENO, tail, sizeof tail - 1);
  _exit(static_cast<int>(ExitCode::Internal));
}

// The running stage is drawn at most this often (seconds): a few times a second.
constexpr double kProgressInterval = 0.25;

struct MeshCommand {
  std::string input, output, report, result;
  bool quiet = false;
  bool machine = false;  // progress as "@progress"/"@running" lines on stderr, for a program that runs this one
  hexlayer::MeshOptions options;
};

// The quad size and the small features of one solid's report.
void describeSizing(const hexlayer::MeshReport& r, std::ostream& s) {
  s << " Quad size " << r.size << " (" << r.sizeSource << ").";
  const hexlayer::SmallFeatures& f = r.smallFeatures;
  if (f.shortEdges + f.narrowFaces > 0)
    s << " " << f.shortEdges << " CAD edges shorter than the quad size and " << f.narrowFaces
      << " faces narrower (the first at (" << f.firstAt.x() << ", " << f.firstAt.y() << ", " << f.firstAt.z()
      << ")): features that small may be smoothed over.";
  if (!f.footFillets.empty())
    s << " " << f.footFillets.size() << " fillets or chamfers at walls' feet (radius or width up to "
      << f.footFilletRadius << ") smoothed over: meshed as sharp corners, grouped by nearness.";
}

std::string summary(const hexlayer::MeshReport& r, const std::string& output) {
  std::ostringstream s;
  const hexlayer::MeshMeasures& m = r.mesh;
  s << std::setprecision(4) << "Wrote " << output << ": " << m.hexes << " hexes, " << m.nodes << " nodes, " << m.layers
    << " layers. Scaled Jacobian min " << m.quality.sjMin << ", avg " << m.quality.sjAvg << ". Volume "
    << m.quality.volume << " vs CAD " << m.cadVolume << " (" << std::showpos << 100 * m.relativeVolumeError()
    << std::noshowpos << " %).";
  if (!r.solids.empty()) {
    s << " " << r.solids.size() << " solids, each meshed on its own.";
    return s.str();
  }
  describeSizing(r, s);
  if (!r.stages.empty()) {
    s << " Time:";
    for (const auto& [stage, t] : r.stages)
      s << " " << stage << " " << std::fixed << std::setprecision(2) << t.seconds << " s" << std::defaultfloat;
    s << ".";
  }
  return s.str();
}

// With --shell: what was written instead of the hexes.
std::string shellSummary(const hexlayer::ShellRecord& s, const std::string& output) {
  std::ostringstream out;
  out << std::setprecision(4) << "Wrote " << output << ": mid-surface shell, " << s.elements << " "
      << (s.order == 2 ? "S8R" : "S4") << " elements, " << s.nodes << " nodes. Thickness min " << s.thicknessMin
      << ", median " << s.thicknessMedian << ", max " << s.thicknessMax << ". Area " << s.area;
  if (s.cadMidSurfaceArea > 0)
    out << " vs the walls' mean " << s.cadMidSurfaceArea << " (" << std::showpos << 100 * s.relativeAreaError()
        << std::noshowpos << " %)";
  out << ".";
  return out.str();
}

void writeReport(const std::string& path, const nlohmann::json& report) {
  std::ofstream out(path);
  if (!out) throw hexlayer::inputError("cannot write the report '" + path + "'");
  out << std::setw(2) << report << "\n";
}

// The meshing options, the same for `mesh` and `check`.
void addMeshOptions(CLI::App* command, MeshCommand& c) {
  command->add_option("--layers", c.options.layers, "Hex layers through the thickness (default 2)");
  command->add_option("--size", c.options.size,
                      "Quad edge length on the chordal surface (default: the wall thickness)");
  command->add_option("--sizing", c.options.sizing,
                      "Quad sizing: uniform or adaptive (radius function and curvature, §6.1) (default adaptive)");
  command->add_flag(
      "--drop-junctions", c.options.dropJunctions,
      "Mesh the largest sheet and leave out ribs, bosses and flanges standing on it (default: refuse, exit 4)");
  command->add_option("--aspect", c.options.aspect,
                      "In-plane quad size / layer thickness, instead of --size (default off)");
  command->add_option("--min-size", c.options.minSize, "Smallest adaptive quad size (default: a quarter of the size)");
  command->add_option("--max-size", c.options.maxSize, "Largest adaptive quad size (default: 4 x the size)");
  command->add_option("--order", c.options.order,
                      "Element order: 1 = 8-node hexes (C3D8I), 2 = 20-node hexes (C3D20R) (default 1)");
  command->add_flag("--shell", c.options.shell,
                    "Write the mid-surface shell instead of the hexes: S4 (S8R with --order 2) with the nodal "
                    "thickness, node sets per CAD face");
  command->add_option("--quad-budget", c.options.quadStageBudget,
                      "Seconds the quad stage may spend on Gmsh tries before it keeps the best so far (default 0: "
                      "300 s + 1 s per 100 quads)");
  command->add_option("--quad-try-budget", c.options.quadTryBudget,
                      "Seconds one Gmsh try may take before it is killed as failed (default 0: 60 s + 1 s per 200 "
                      "quads)");
  command->add_flag("--force", c.options.force,
                    "Write the mesh even if it fails validation (with a warning per failed check)");
}

// Meshes with the progress on stderr (progress_printer.hpp: a status line on a terminal, plain lines elsewhere,
// "@progress"/"@running" lines with --machine; none with --quiet). The printer is gone (its status line cleared)
// when meshing ends. [in,out] c: the command, its options' progress set while meshing. Returns the result.
hexlayer::MeshResult meshWithProgress(MeshCommand& c) {
  std::optional<hexlayer::ProgressPrinter> printer;
  if (c.machine || !c.quiet) {
    printer.emplace(std::cerr, hexlayer::progressStyleFor(c.machine, STDERR_FILENO), kProgressInterval, true);
    c.options.progress = [&printer](const hexlayer::Progress& event) { printer->show(event); };
  }
  hexlayer::MeshResult result = hexlayer::meshFile(c.input, c.options);
  c.options.progress = nullptr;
  return result;
}

// Why the mesh's boundary has another Euler characteristic than the part's: each hole of a sheet filled raises it by
// 2 (one narrower than about a quad or the wall: a bend relief; the quads' share: QuadMeshCounts::pinholesClosed),
// each hole more lowers it by 2. [in] m: the mesh's measures; [in] quads: the quad stage's counts.
std::string topologyMessage(const hexlayer::MeshMeasures& m, const hexlayer::QuadMeshCounts& quads) {
  const long apart = m.boundary.eulerCharacteristic - m.cadEuler;
  std::ostringstream msg;
  msg << "the mesh boundary has Euler characteristic " << m.boundary.eulerCharacteristic << " but the part "
      << m.cadEuler << ": ";
  if (apart > 0 && apart % 2 == 0)
    msg << "the mesh fills " << apart / 2 << " hole(s) of the part (narrower than about a quad or the wall: a bend "
        << "relief where walls meet at a corner; the quads closed " << quads.pinholesClosed << " of them)";
  else if (apart < 0 && apart % 2 == 0)
    msg << "the mesh has " << -apart / 2 << " hole(s) the part does not have";
  else
    msg << "the mesh has a hole the part does not have, or fills one it has";
  return msg.str();
}

int runMesh(MeshCommand& c) {
  hexlayer::MeshResult result = meshWithProgress(c);
  if (!c.result.empty()) hexlayer::writeResult(c.result, result);
  std::vector<hexlayer::CellField> fields;
  if (!result.mesh.hexes.empty()) fields.push_back({"scaled_jacobian", result.scaledJacobian});
  if (c.options.shell)
    hexlayer::writeShellMesh(c.output, result.shell);
  else
    hexlayer::writeMesh(c.output, result.mesh, {result.nodeSets, result.surfaceGroups, fields});
  if (!c.report.empty()) writeReport(c.report, hexlayer::toJson(result.report));
  if (!c.quiet && !c.machine)
    std::cout << (c.options.shell ? shellSummary(*result.report.shell, c.output) : summary(result.report, c.output))
              << std::endl;
  const hexlayer::MeshMeasures& m = result.report.mesh;
  for (const hexlayer::ValidationFailure& f : m.failures)  // only with --force: else meshFile threw
    std::cerr << "hexlayer: warning: validation failed (written because of --force): " << f.message << std::endl;
  const bool topologyFailed = std::any_of(m.failures.begin(), m.failures.end(),
                                          [](const hexlayer::ValidationFailure& f) { return f.check == "topology"; });
  if (!m.sameTopologyAsCad() && !topologyFailed)  // a failed one is said above: a hole the part does not have
    std::cerr << "hexlayer: warning: " << topologyMessage(m, result.report.quadMesh) << std::endl;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(signal, crashed);
  CLI::App app{"HexLayer: layered all-hex meshes of thin-section CAD solids (Hex-Layer method)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("hexlayer ") + hexlayer::kVersion);
  MeshCommand c;
  CLI::App* mesh = app.add_subcommand("mesh", "Mesh a thin solid into layered hexahedra");
  mesh->add_option("input", c.input, "CAD file: .step/.stp, .iges/.igs or .brep")->required();
  mesh->add_option("-o,--output", c.output, "Output mesh: .inp (CalculiX), .vtu (VTK) or .msh (Gmsh 4.1)")->required();
  addMeshOptions(mesh, c);
  mesh->add_option("--report", c.report, "Write a JSON report of every stage");
  mesh->add_option(
      "--result", c.result,
      "Write the whole result (mesh, node sets, face groups, report, chordal surface and quad mesh) as a JSON "
      "index and its arrays in FILE.bin: what the FreeCAD workbench reads");
  mesh->add_flag("--machine", c.machine,
                 "Progress on stderr for a program that runs this one: '@progress <line>' per finished stage, "
                 "'@running <stage> [<done> <total>]' for the running one; no summary");
  mesh->add_flag("--quiet", c.quiet, "No progress and no summary");
  CLI::App* check = app.add_subcommand("check", "Check mesh options without meshing: exit 0, or 2 with the reason");
  addMeshOptions(check, c);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "hexlayer: error: " << e.what() << " (hexlayer mesh --help lists the options)" << std::endl;
    return static_cast<int>(ExitCode::BadUsage);
  }
  try {
    CLI::App* used = mesh->parsed() ? mesh : check;
    if (used->count("--size") > 0 && !(c.options.size > 0))  // 0 is the default's "from the part", not a size
      throw hexlayer::usageError("--size must be a positive length");
    if (check->parsed()) {
      hexlayer::validateOptions(c.options);
      return 0;
    }
    return runMesh(c);
  } catch (const hexlayer::Error& e) {
    std::cerr << "hexlayer: error: " << e.what() << std::endl;
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::cerr << "hexlayer: internal error: " << e.what() << std::endl;
    return static_cast<int>(ExitCode::Internal);
  } catch (const Standard_Failure& e) {  // OpenCASCADE's exceptions are not std::exceptions
    std::cerr << "hexlayer: internal error: OpenCASCADE: " << e.GetMessageString() << std::endl;
    return static_cast<int>(ExitCode::Internal);
  }
}
