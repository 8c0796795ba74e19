// Which CAD faces a point lies on, and how far it is from one: what FreeCAD's FemMesh.getNodesByFace
// asks of a mesh node (distance to the trimmed face below the face's tolerance).
#pragma once
#include <Bnd_Box.hxx>
#include <TopoDS_Face.hxx>

#include <vector>

#include "core/types.hpp"
#include "geometry/cad_solid.hpp"

namespace hexlayer {

// A point's faces: the face it was put on (first, whatever its distance) and every face sharing a
// vertex with that one that the point lies on within the face's tolerance (a CAD edge or vertex).
struct FacesAtPoint {
  std::vector<int> faces;  // 0-based indices into CadSolid::faces
  double distance = 0;     // from the point to the face it was put on
};

class CadFaces {
 public:
  explicit CadFaces(const CadSolid& cad);
  int count() const { return static_cast<int>(faces_.size()); }
  // Distance from p to the trimmed face `face` (OpenCASCADE BRepExtrema: inside, edges and vertices).
  double distance(int face, const Vec3& p) const;
  // True if p is closer to `face` than the face's tolerance (BRep_Tool::Tolerance, ~1e-7), FreeCAD's test.
  bool lies(int face, const Vec3& p) const;
  double tolerance(int face) const { return tolerance_[face]; }
  FacesAtPoint facesAt(int face, const Vec3& p) const;

 private:
  std::vector<TopoDS_Face> faces_;
  std::vector<Bnd_Box> boxes_;               // each enlarged by its face's tolerance
  std::vector<double> tolerance_;
  std::vector<std::vector<int>> neighbours_;  // faces sharing a vertex, ascending
};

}  // namespace hexlayer
