#include "geometry/cad_solid.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeFix_Solid.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <XSControl_Reader.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace hexlayer {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

TopoDS_Shape readWithTranslator(XSControl_Reader& reader, const std::string& path) {
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw inputError("cannot read '" + path + "': not a valid " + lowerExtension(path).substr(1) + " file");
  reader.TransferRoots();
  return reader.OneShape();
}

TopoDS_Shape readShape(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".step" || ext == ".stp") {
    STEPControl_Reader reader;
    return readWithTranslator(reader, path);
  }
  if (ext == ".iges" || ext == ".igs") {
    IGESControl_Reader reader;
    return readWithTranslator(reader, path);
  }
  if (ext == ".brep" || ext == ".brp") {
    TopoDS_Shape shape;
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder))
      throw inputError("cannot read '" + path + "': not a valid BREP file");
    return shape;
  }
  throw inputError("unknown input format '" + ext + "' of '" + path + "': use .step, .stp, .iges, .igs or .brep");
}

// The solid a closed shell bounds, its faces turned outward.
TopoDS_Solid solidOfClosedShell(const TopoDS_Shell& shell) {
  BRepBuilderAPI_MakeSolid make(shell);
  ShapeFix_Solid fix(make.Solid());
  fix.Perform();
  const TopoDS_Shape fixed = fix.Solid();
  return fixed.ShapeType() == TopAbs_SOLID ? TopoDS::Solid(fixed) : make.Solid();
}

}  // namespace

std::vector<TopoDS_Solid> readSolids(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw inputError("input file '" + path + "' does not exist");
  if (std::filesystem::file_size(path, ec) == 0) throw inputError("input file '" + path + "' is empty");
  if (!std::ifstream(path).good()) throw inputError("input file '" + path + "' cannot be opened");
  const TopoDS_Shape shape = readShape(path);
  std::vector<TopoDS_Solid> solids;
  if (!shape.IsNull())
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) solids.push_back(TopoDS::Solid(it.Current()));
  if (solids.empty() && !shape.IsNull())  // a closed shell bounds a solid: sheet-metal files often hold only that
    for (TopExp_Explorer it(shape, TopAbs_SHELL); it.More(); it.Next())
      if (BRep_Tool::IsClosed(it.Current())) solids.push_back(solidOfClosedShell(TopoDS::Shell(it.Current())));
  if (solids.empty()) throw inputError("'" + path + "' contains no solid (only surfaces, curves or nothing)");
  return solids;
}

CadSolid prepareSolid(const TopoDS_Solid& input) {
  CadSolid cad;
  cad.solid = input;
  BRepCheck_Analyzer check(cad.solid);
  if (!check.IsValid()) {
    ShapeFix_Solid fix(cad.solid);  // heal small tolerance defects before giving up
    fix.Perform();
    if (fix.Solid().ShapeType() == TopAbs_SOLID) cad.solid = TopoDS::Solid(fix.Solid());
    if (!BRepCheck_Analyzer(cad.solid).IsValid()) throw inputError("the solid is not valid (BRepCheck failed)");
  }
  for (TopExp_Explorer it(cad.solid, TopAbs_SHELL); it.More(); it.Next())
    if (!BRep_Tool::IsClosed(it.Current())) throw inputError("the solid's shell is not closed");
  TopExp::MapShapes(cad.solid, TopAbs_FACE, cad.faces);
  TopExp::MapShapes(cad.solid, TopAbs_EDGE, cad.edges);
  TopExp::MapShapes(cad.solid, TopAbs_VERTEX, cad.vertices);
  GProp_GProps props;
  BRepGProp::VolumeProperties(cad.solid, props);
  cad.volume = props.Mass();
  if (!(cad.volume > 0)) throw inputError("the solid has no positive volume (inside out or empty)");
  Bnd_Box box;
  BRepBndLib::Add(cad.solid, box);
  cad.diagonal = std::sqrt(box.SquareExtent());
  // Triangulation used for sampling the faces (thickness rays, bubble candidates).
  BRepMesh_IncrementalMesh(cad.solid, 0.002 * cad.diagonal, false, 0.3, false);
  return cad;
}

Vec3 outwardNormal(const TopoDS_Shape& face, double u, double v) {
  BRepGProp_Face prop(TopoDS::Face(face));  // applies the face orientation
  gp_Pnt p;
  gp_Vec n;
  prop.Normal(u, v, p, n);
  const double len = n.Magnitude();
  if (!(len > 0)) return Vec3::Zero();
  return Vec3(n.X(), n.Y(), n.Z()) / len;
}

long eulerCharacteristic(const CadSolid& cad) {
  long wires = 0;
  for (int f = 1; f <= cad.faces.Extent(); ++f)
    for (TopExp_Explorer w(cad.faces(f), TopAbs_WIRE); w.More(); w.Next()) ++wires;
  const long faces = cad.faces.Extent();
  return cad.vertices.Extent() - cad.edges.Extent() + 2 * faces - wires;
}

}  // namespace hexlayer
