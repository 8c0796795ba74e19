#include "geometry/face_sampling.hpp"

#include <BRepGProp_Face.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopoDS.hxx>

#include <cmath>

namespace hexlayer {
namespace {

double area3d(const Triangle2d& t) {
  const gp_Vec a(t.xyz[0], t.xyz[1]), b(t.xyz[0], t.xyz[2]);
  return 0.5 * a.Crossed(b).Magnitude();
}

}  // namespace

std::vector<Triangle2d> faceTriangles(const TopoDS_Face& face) {
  TopLoc_Location loc;
  const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
  std::vector<Triangle2d> out;
  if (tri.IsNull() || !tri->HasUVNodes()) return out;
  out.reserve(tri->NbTriangles());
  for (int t = 1; t <= tri->NbTriangles(); ++t) {
    int n[3];
    tri->Triangle(t).Get(n[0], n[1], n[2]);
    Triangle2d td;
    for (int k = 0; k < 3; ++k) {
      td.uv[k] = tri->UVNode(n[k]);
      td.xyz[k] = tri->Node(n[k]).Transformed(loc.Transformation());
    }
    out.push_back(td);
  }
  return out;
}

Triangle spaceTriangle(const Triangle2d& t) {
  auto toVec = [](const gp_Pnt& p) { return Vec3(p.X(), p.Y(), p.Z()); };
  return {toVec(t.xyz[0]), toVec(t.xyz[1]), toVec(t.xyz[2])};
}

double triangulatedArea(const TopoDS_Shape& face) {
  double a = 0;
  for (const Triangle2d& t : faceTriangles(TopoDS::Face(face))) a += area3d(t);
  return a;
}

std::vector<FaceSample> sampleFace(const TopoDS_Shape& shape, double spacing) {
  const TopoDS_Face face = TopoDS::Face(shape);
  BRepGProp_Face surface(face);  // evaluates points and normals with the face's orientation
  std::vector<FaceSample> samples;
  for (const Triangle2d& t : faceTriangles(face)) {
    const double area = area3d(t);
    if (area <= 0) continue;
    // Barycentric lattice with k divisions per side gives k(k+1)/2 interior-ish points.
    const int k = std::max(1, static_cast<int>(std::ceil(std::sqrt(2.0 * area) / spacing)));
    const double weight = area / (k * (k + 1) / 2.0);
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j) {
        const double a = (i + 1.0 / 3.0) / k, b = (j + 1.0 / 3.0) / k, c = 1.0 - a - b;
        FaceSample s;
        s.u = a * t.uv[0].X() + b * t.uv[1].X() + c * t.uv[2].X();
        s.v = a * t.uv[0].Y() + b * t.uv[1].Y() + c * t.uv[2].Y();
        gp_Pnt p;
        gp_Vec n;
        surface.Normal(s.u, s.v, p, n);
        s.point = Vec3(p.X(), p.Y(), p.Z());
        s.normal = n.Magnitude() > 0 ? Vec3(Vec3(n.X(), n.Y(), n.Z()).normalized()) : Vec3(Vec3::Zero());
        s.area = weight;
        if (s.normal.squaredNorm() > 0) samples.push_back(s);
      }
  }
  return samples;
}

}  // namespace hexlayer
