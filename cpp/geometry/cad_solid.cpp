#include "geometry/cad_solid.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_TVertex.hxx>
#include <BRep_Tool.hxx>
#include <BinTools.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_Surface.hxx>
#include <IGESControl_Reader.hxx>
#include <IMeshTools_Parameters.hxx>
#include <NCollection_DataMap.hxx>
#include <Precision.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Solid.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <XSControl_Reader.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/child_process.hpp"
#include "core/error.hpp"

namespace hexlayer {

namespace {

// normalizingUnit: parts whose diagonal is outside [kSmallestDiagonal, kLargestDiagonal) (in metres or microns, if
// drawn in millimetres) are scaled by the power of kUnitStep (a unit's step: mm, m, km) that brings them inside, so
// that a part in metres is met at the size of the same part in millimetres. Parts within are left as they are:
// Gmsh took 3x longer on the scaled copy of a B-spline part (the AnalysisSitus ski part) whatever the size.
constexpr double kSmallestDiagonal = 10, kLargestDiagonal = 10000, kUnitStep = 1000;

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// A reader gets this long, plus kReadSecondsPerMB per MB of file, before it is taken for hung.
constexpr double kReadSeconds = 10, kReadSecondsPerMB = 20;
// The CAD volume (the mesh's reference) to this relative error.
constexpr double kVolumeTolerance = 1e-7;

enum class Format { Step, Iges, Brep };

Format formatOf(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".step" || ext == ".stp") return Format::Step;
  if (ext == ".iges" || ext == ".igs") return Format::Iges;
  if (ext == ".brep" || ext == ".brp") return Format::Brep;
  throw inputError("unknown input format '" + ext + "' of '" + path + "': use .step, .stp, .iges, .igs or .brep");
}

const char* formatName(Format f) { return f == Format::Step ? "STEP" : f == Format::Iges ? "IGES" : "BREP"; }

TopoDS_Shape readWithTranslator(XSControl_Reader& reader, const std::string& path) {
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw inputError("not a valid " + std::string(formatName(formatOf(path))) + " file");
  reader.TransferRoots();
  return reader.OneShape();
}

}  // namespace

TopoDS_Shape readShapeInProcess(const std::string& path) {
  try {
    switch (formatOf(path)) {
      case Format::Step: {
        STEPControl_Reader reader;
        return readWithTranslator(reader, path);
      }
      case Format::Iges: {
        IGESControl_Reader reader;
        return readWithTranslator(reader, path);
      }
      case Format::Brep: {
        TopoDS_Shape shape;
        if (!BRepTools::Read(shape, path.c_str(), BRep_Builder())) throw inputError("not a valid BREP file");
        return shape;
      }
    }
  } catch (const Standard_Failure& e) {  // OpenCASCADE's exceptions are not std::exceptions
    throw inputError(std::string("not a valid ") + formatName(formatOf(path)) + " file (" + e.GetMessageString() + ")");
  }
  return {};
}

namespace {

// The shape in OpenCASCADE's binary format (BinTools), and back: its reals as stored, but the axes of a circle or a
// cylinder are made orthonormal again on reading (gp_Ax2), a change in the last bit on some parts (two of 66 meshed
// differently, by as little), the same on every run.
std::string binaryShape(const TopoDS_Shape& shape) {
  std::ostringstream out(std::ios::binary);
  BinTools::Write(shape, out);
  return out.str();
}

TopoDS_Shape shapeOfBinary(const std::string& bytes) {
  std::istringstream in(bytes, std::ios::binary);
  TopoDS_Shape shape;
  try {
    BinTools::Read(shape, in);
  } catch (const Standard_Failure& e) {
    throw internalError(std::string("the shape read in the child process could not be read back: ") +
                        e.GetMessageString());
  }
  return shape;
}

// OpenCASCADE's readers can loop forever (BRepTools::Read on a truncated .brep) or crash on a damaged
// file, so the file is read in a child process, which hands the shape back in the binary format (reading a
// STEP file again here took a second on a part of 850 faces; BREP text would round every real to 15 digits).
TopoDS_Shape readShape(const std::string& path) {
  const Format format = formatOf(path);
  std::error_code ec;
  const double seconds = kReadSeconds + kReadSecondsPerMB * std::filesystem::file_size(path, ec) / 1e6;
  const ChildResult child = runInChildProcess([&] { return binaryShape(readShapeInProcess(path)); }, seconds);
  if (child.ok) return shapeOfBinary(child.output);
  if (child.threw) throw inputError("cannot read '" + path + "': " + child.failure);
  throw inputError("cannot read '" + path + "': the " + formatName(format) + " reader " + child.failure +
                   " (a truncated or damaged file?)");
}

// The solid a closed shell bounds, its faces turned outward.
TopoDS_Solid solidOfClosedShell(const TopoDS_Shell& shell) {
  BRepBuilderAPI_MakeSolid make(shell);
  ShapeFix_Solid fix(make.Solid());
  fix.Perform();
  const TopoDS_Shape fixed = fix.Solid();
  return fixed.ShapeType() == TopAbs_SOLID ? TopoDS::Solid(fixed) : make.Solid();
}

// What a shape without a solid holds, e.g. "1 open shell of 5 faces".
std::string contents(const TopoDS_Shape& shape) {
  if (shape.IsNull()) return "nothing that could be transferred";
  auto count = [&](TopAbs_ShapeEnum type) {
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, type, map);
    return map.Extent();
  };
  const int shells = count(TopAbs_SHELL), faces = count(TopAbs_FACE), edges = count(TopAbs_EDGE);
  std::ostringstream s;
  if (shells > 0)
    s << shells << " open shell(s) of " << faces << " face(s) in all, not closed";
  else if (faces > 0)
    s << faces << " loose face(s)";
  else if (edges > 0)
    s << edges << " edge(s) (wires or curves), no face";
  else
    s << "no face and no edge";
  s << "; Hex-Layer needs a closed solid";
  return s.str();
}

// The edges of planar faces given their curves in the plane, which STEP files often leave out: OpenCASCADE
// would project them again at every point classified on the face (every ray hit, every distance to it).
void storePlanarCurves(const TopTools_IndexedMapOfShape& faces) {
  for (int f = 1; f <= faces.Extent(); ++f) {
    const TopoDS_Face& face = TopoDS::Face(faces(f));
    if (!BRep_Tool::Surface(face)->IsKind(STANDARD_TYPE(Geom_Plane))) continue;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
      BRepLib::BuildPCurveForEdgeOnPlane(TopoDS::Edge(e.Current()), face);
  }
}

}  // namespace

std::vector<TopoDS_Solid> readSolids(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw inputError("input file '" + path + "' does not exist");
  if (!std::filesystem::is_regular_file(path, ec))
    throw inputError("input '" + path + "' is not a regular file (a folder?)");
  if (std::filesystem::file_size(path, ec) == 0) throw inputError("input file '" + path + "' is empty");
  formatOf(path);  // an unknown extension is refused before reading
  if (!std::ifstream(path).good()) throw inputError("input file '" + path + "' cannot be opened");
  const TopoDS_Shape shape = readShape(path);
  std::vector<TopoDS_Solid> solids;
  if (!shape.IsNull())
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) solids.push_back(TopoDS::Solid(it.Current()));
  if (solids.empty() && !shape.IsNull())  // a closed shell bounds a solid: sheet-metal files often hold only that
    for (TopExp_Explorer it(shape, TopAbs_SHELL); it.More(); it.Next())
      if (BRep_Tool::IsClosed(it.Current())) solids.push_back(solidOfClosedShell(TopoDS::Shell(it.Current())));
  if (solids.empty()) throw inputError("'" + path + "' contains no solid: " + contents(shape));
  return solids;
}

double normalizingUnit(const TopoDS_Solid& solid) {
  Bnd_Box box;
  BRepBndLib::Add(solid, box, false);
  const double diagonal = box.IsVoid() ? 0 : std::sqrt(box.SquareExtent());
  if (!(diagonal > 0) || !std::isfinite(diagonal)) return 1;
  double unit = 1;
  while (diagonal * unit < kSmallestDiagonal) unit *= kUnitStep;
  while (diagonal * unit >= kLargestDiagonal) unit /= kUnitStep;
  return unit;
}

CadSolid prepareSolid(const TopoDS_Solid& input, double unit) {
  CadSolid cad;
  cad.solid = input;
  cad.unit = unit;
  if (unit != 1) {
    gp_Trsf scale;
    scale.SetScale(gp_Pnt(0, 0, 0), unit);
    const TopoDS_Shape scaled = BRepBuilderAPI_Transform(input, scale, true).Shape();
    if (scaled.ShapeType() != TopAbs_SOLID) throw inputError("the solid could not be scaled to the pipeline's size");
    cad.solid = TopoDS::Solid(scaled);
  }
  BRepCheck_Analyzer check(cad.solid, true, true);  // its sub-shapes checked in parallel: the same verdict
  if (!check.IsValid()) {
    ShapeFix_Solid fix(cad.solid);  // heal small tolerance defects before giving up
    fix.Perform();
    if (fix.Solid().ShapeType() == TopAbs_SOLID) cad.solid = TopoDS::Solid(fix.Solid());
    if (!BRepCheck_Analyzer(cad.solid).IsValid()) throw inputError("the solid is not valid (BRepCheck failed)");
  }
  for (TopExp_Explorer it(cad.solid, TopAbs_SHELL); it.More(); it.Next())
    if (!BRep_Tool::IsClosed(it.Current())) throw inputError("the solid's shell is not closed");
  TopExp::MapShapes(cad.solid, TopAbs_FACE, cad.faces);
  storePlanarCurves(cad.faces);
  TopExp::MapShapes(cad.solid, TopAbs_EDGE, cad.edges);
  TopExp::MapShapes(cad.solid, TopAbs_VERTEX, cad.vertices);
  cad.volume = volumeOf(cad.solid, kVolumeTolerance).first;
  if (!(cad.volume > 0)) throw inputError("the solid has no positive volume (inside out or empty)");
  Bnd_Box box;
  BRepBndLib::Add(cad.solid, box);
  cad.diagonal = std::sqrt(box.SquareExtent());
  triangulateFaces(cad.solid, 0.002 * cad.diagonal);  // for sampling the faces (thickness rays, bubble candidates)
  return cad;
}

Vec3 normalAtEdge(const TopoDS_Face& face, const TopoDS_Edge& edge) {
  double first = 0, last = 0;
  const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
  if (pcurve.IsNull()) return Vec3::Zero();
  const gp_Pnt2d uv = pcurve->Value(0.5 * (first + last));
  return outwardNormal(face, uv.X(), uv.Y());
}

std::pair<double, Vec3> volumeOf(const TopoDS_Shape& solid, double relativeError) {
  bool planes = true;  // the Gauss-Kronrod rule refines without end along a plane's edges oblique to its axes (100 s on
                       // a box turned 30 degrees): a solid of planes only by the Gauss rule, exact on them
  for (TopExp_Explorer it(solid, TopAbs_FACE); it.More() && planes; it.Next()) planes = isFlat(it.Current());
  GProp_GProps props;
  if (planes)
    BRepGProp::VolumeProperties(solid, props, relativeError, false);
  else
    BRepGProp::VolumePropertiesGK(solid, props, relativeError, false, true);
  const gp_Pnt c = props.CentreOfMass();
  return {props.Mass(), Vec3(c.X(), c.Y(), c.Z())};
}

void triangulateFaces(const TopoDS_Shape& shape, double deflection) {
  IMeshTools_Parameters p;
  p.Deflection = deflection;
  p.Angle = 0.3;
  p.InParallel = true;
  p.MeshAlgo = IMeshTools_MeshAlgoType_Delabella;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(it.Current(), TopAbs_EDGE, edges);
    if (edges.Extent() > kManyEdges) BRepMesh_IncrementalMesh(it.Current(), p);
  }
  p.MeshAlgo = IMeshTools_MeshAlgoType_Watson;  // the other faces, and any Delabella left without triangles
  BRepMesh_IncrementalMesh(shape, p);
}

double largestTolerance(const TopoDS_Shape& shape) {
  return std::max({BRep_Tool::MaxTolerance(shape, TopAbs_VERTEX), BRep_Tool::MaxTolerance(shape, TopAbs_EDGE),
                   BRep_Tool::MaxTolerance(shape, TopAbs_FACE)});
}

std::optional<gp_Pln> planeOf(const TopoDS_Shape& face, double tolerance) {
  const BRepAdaptor_Surface surface(TopoDS::Face(face));
  if (surface.GetType() == GeomAbs_Plane) return surface.Plane();
  GeomLib_IsPlanarSurface planar(BRep_Tool::Surface(TopoDS::Face(face)), tolerance);
  if (!planar.IsPlanar()) return std::nullopt;
  return planar.Plan();
}

bool isFlat(const TopoDS_Shape& face) {
  return planeOf(face, 10 * BRep_Tool::Tolerance(TopoDS::Face(face))).has_value();
}

std::optional<gp_Cylinder> cylinderOf(const TopoDS_Shape& face, double tolerance) {
  constexpr int kSamples = 6;             // intervals per parameter direction of the sampling grid
  constexpr double kAcrossAxis = 1e-12;   // mean squared normal component along the axis: the normals are across it
  constexpr double kCurvedAround = 1e-6;  // and that of the next axis: not all parallel (a plane)
  const BRepAdaptor_Surface surface(TopoDS::Face(face));
  if (surface.GetType() == GeomAbs_Cylinder) return surface.Cylinder();
  if (surface.GetType() != GeomAbs_BSplineSurface && surface.GetType() != GeomAbs_BezierSurface) return std::nullopt;
  std::vector<Vec3> points, normals;
  for (int i = 0; i <= kSamples; ++i)
    for (int k = 0; k <= kSamples; ++k) {
      const double u =
          surface.FirstUParameter() + (surface.LastUParameter() - surface.FirstUParameter()) * i / kSamples;
      const double v =
          surface.FirstVParameter() + (surface.LastVParameter() - surface.FirstVParameter()) * k / kSamples;
      gp_Pnt p;
      gp_Vec du, dv;
      surface.D1(u, v, p, du, dv);
      const gp_Vec n = du.Crossed(dv);
      if (n.Magnitude() <= 0) continue;
      const gp_Vec d = n.Normalized();
      points.push_back(toVec(p)), normals.emplace_back(d.X(), d.Y(), d.Z());
    }
  if (points.size() < 3) return std::nullopt;
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();  // the axis: the direction the normals have no part along
  for (const Vec3& n : normals) m += n * n.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(m / static_cast<double>(normals.size()));
  if (eigen.eigenvalues()(0) > kAcrossAxis || eigen.eigenvalues()(1) < kCurvedAround) return std::nullopt;
  const Vec3 axis = eigen.eigenvectors().col(0), e1 = eigen.eigenvectors().col(1), e2 = eigen.eigenvectors().col(2);
  // the circle through the points seen along the axis: 2 c . q + (r^2 - |c|^2) = |q|^2, least squares (Kasa)
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].dot(e1), y = points[i].dot(e2);
    a.row(static_cast<Eigen::Index>(i)) << 2 * x, 2 * y, 1;
    b(static_cast<Eigen::Index>(i)) = x * x + y * y;
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
  const double r2 = c(2) + c(0) * c(0) + c(1) * c(1);
  if (!(r2 > 0)) return std::nullopt;
  const double r = std::sqrt(r2);
  const Vec3 centre = c(0) * e1 + c(1) * e2;
  for (const Vec3& p : points) {
    const Vec3 q = p - centre - axis * (p - centre).dot(axis);
    if (std::abs(q.norm() - r) > tolerance) return std::nullopt;
  }
  return gp_Cylinder(gp_Ax3(gp_Pnt(centre.x(), centre.y(), centre.z()), gp_Dir(axis.x(), axis.y(), axis.z()),
                            gp_Dir(e1.x(), e1.y(), e1.z())),
                     r);
}

Vec3 outwardNormal(const TopoDS_Shape& face, double u, double v, double* length) {
  // The surface's derivatives, placed as the face is, crossed and turned with the face's orientation (as
  // BRepGProp_Face does, without its adaptor's parameter bounds: those walk every edge of the face).
  TopLoc_Location place;
  const Handle(Geom_Surface)& surface = BRep_Tool::Surface(TopoDS::Face(face), place);
  gp_Pnt p;
  gp_Vec du, dv;
  surface->D1(u, v, p, du, dv);
  du.Transform(place.Transformation()), dv.Transform(place.Transformation());
  gp_Vec n = du.Crossed(dv);
  if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
  const double len = n.Magnitude();
  if (length) *length = len;
  if (!(len > 0)) return Vec3::Zero();
  return Vec3(n.X(), n.Y(), n.Z()) / len;
}

std::vector<gp_Pnt2d> vertexParameters(const TopoDS_Face& face) {
  NCollection_DataMap<TopoDS_Shape, gp_Pnt2d, TopTools_ShapeMapHasher> at;  // each vertex, from its first edge
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge, first, last);
    gp_Pnt2d atFirst, atLast;
    BRep_Tool::UVPoints(edge, face, atFirst, atLast);
    for (const auto& [v, uv] : {std::pair(first, atFirst), std::pair(last, atLast)})
      if (!v.IsNull() && !at.IsBound(v))  // a point-on-surface record comes first, as in BRep_Tool::Parameters
        at.Bind(v, static_cast<const BRep_TVertex*>(v.TShape().get())->Points().IsEmpty()
                       ? uv
                       : BRep_Tool::Parameters(v, face));
  }
  std::vector<gp_Pnt2d> uvs;
  for (TopExp_Explorer v(face, TopAbs_VERTEX); v.More(); v.Next()) {
    const gp_Pnt2d* uv = at.Seek(v.Current());
    uvs.push_back(uv ? *uv : BRep_Tool::Parameters(TopoDS::Vertex(v.Current()), face));
  }
  return uvs;
}

long eulerCharacteristic(const CadSolid& cad) {
  long wires = 0, edges = 0;
  for (int f = 1; f <= cad.faces.Extent(); ++f)
    for (TopExp_Explorer w(cad.faces(f), TopAbs_WIRE); w.More(); w.Next()) ++wires;
  for (int e = 1; e <= cad.edges.Extent(); ++e)
    edges += !BRep_Tool::Degenerated(TopoDS::Edge(cad.edges(e)));  // a sphere's pole is no edge
  const long faces = cad.faces.Extent();
  return cad.vertices.Extent() - edges + 2 * faces - wires;
}

std::optional<double> filletRadius(const TopoDS_Shape& face) {
  constexpr double kSameCurvature = 0.02;  // relative: a fillet's curvature across it varies less
  const BRepAdaptor_Surface s(TopoDS::Face(face));
  double u0, u1, v0, v1;
  BRepTools::UVBounds(TopoDS::Face(face), u0, u1, v0, v1);
  std::vector<double> curvature;
  bool concave = true;
  for (int i = 1; i <= 3; ++i)
    for (int k = 1; k <= 3; ++k) {
      const double u = u0 + 0.25 * i * (u1 - u0), v = v0 + 0.25 * k * (v1 - v0);
      BRepLProp_SLProps props(s, u, v, 2, Precision::Confusion());
      if (!props.IsCurvatureDefined()) return std::nullopt;
      const double kMax = props.MaxCurvature(), kMin = props.MinCurvature();
      const double kappa = std::abs(kMax) >= std::abs(kMin) ? kMax : kMin;  // signed along props.Normal()
      if (!(std::abs(kappa) > 0)) return std::nullopt;
      const gp_Dir n = props.Normal();
      const Vec3 towardsCentre = Vec3(n.X(), n.Y(), n.Z()) * (1 / kappa);  // the centre of curvature from the point
      concave = concave && outwardNormal(face, u, v).dot(towardsCentre) > 0;
      curvature.push_back(std::abs(kappa));
    }
  const auto [least, most] = std::minmax_element(curvature.begin(), curvature.end());
  if (!concave || *most - *least > kSameCurvature * *most) return std::nullopt;
  return 1 / *most;
}

}  // namespace hexlayer
