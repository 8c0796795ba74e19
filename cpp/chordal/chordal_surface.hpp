// Chordal surface (paper §5): the tets cut at the midpoints of their top-bottom edges, with the
// unit normal and the radius (half-thickness) function at its vertices (§5.5, Eq. 1-3).
#pragma once
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "tets/tet_mesh.hpp"

namespace hexlayer {

struct ChordalSurface {
  std::vector<Vec3> vertices;               // v = (v_t + v_b) / 2 of a top-bottom tet edge
  std::vector<std::array<int, 2>> tetEdge;  // that edge's (top node, bottom node) in the tet mesh
  std::vector<std::array<int, 4>> facets;   // triangles end with -1; each turns counter-clockwise seen from the top
  std::vector<Vec3> normals;                // unit average normal n̄ per vertex (Eq. 2)
  std::vector<double> radius;               // r = n̄ · (v_t - v) per vertex (Eq. 3)
  std::size_t triangles = 0, quads = 0;
  std::size_t pinchedFacetsDropped = 0;  // facets of ears where the rim passed a vertex twice
  std::size_t islandFacetsDropped = 0;   // facets of islands apart from the surface (dropIslands)
};

// Cuts every tet that spans top and bottom: a 3-1 or 1-3 tet gives a triangle, a 2-2 tet a quad
// (§5, Figure 3). A chordal vertex belongs to its tet edge, so neighbouring tets share it and the
// facets form one connected surface. The side labels of the nodes (from the CAD faces) decide the
// cut, so every tet is "simple" here: no incremental processing of complex tets (§5.4) is needed.
// Where the rim passes a vertex twice (an ear of one or two tets touching the rest at the vertex only, beside
// a concave rim such as a hole's rounded one), the smaller fans of facets there are dropped, and so are islands of a
// few facets apart from the rest (dropIslands).
// Throws geometryError if the surface is non-manifold (an edge in more than two facets), naming where in
// the input's units: the tets' lengths are `unit` per input length (CadSolid::unit).
ChordalSurface buildChordalSurface(const TetMesh& tets, double unit = 1);

// The rim loops (edges of one facet): a hole's or the outer rim (loops that touch at a vertex count as one).
struct RimLoops {
  std::vector<int> loopOf;     // per vertex, its loop; -1 off the rim
  std::vector<double> length;  // per loop, the length of its edges
};
// [in] chordal. Returns its rim loops, numbered in the order of their lowest vertex.
RimLoops rimLoops(const ChordalSurface& chordal);

// For every facet edge (lower vertex id first), how many facets use it: 1 on the rim, 2 inside;
// sorted by edge.
std::vector<std::pair<std::pair<int, int>, int>> facetEdgeUses(const ChordalSurface& chordal);

// Whether a and b are the ends of an edge in `edges` (facetEdgeUses's, sorted).
bool isFacetEdge(const std::vector<std::pair<std::pair<int, int>, int>>& edges, int a, int b);

// Unit average normal n̄ at every vertex (Eq. 2), zero where the facet normals around it cancel.
std::vector<Vec3> vertexNormals(const ChordalSurface& chordal);

// Normal (Eq. 1-2) and radius (Eq. 3) at every chordal vertex.
// [in,out] chordal: normals and radius set; [in] tets: the kept tets it was cut from.
void computeNormalsAndRadius(ChordalSurface& chordal, const TetMesh& tets);

// Unit normal of one facet (Eq. 1): e2 x e1 with e1 = v1 - v2, e2 = v3 - v2 for a triangle and the
// diagonals e1 = v4 - v2, e2 = v3 - v1 for a quad.
Vec3 facetNormal(const ChordalSurface& chordal, const std::array<int, 4>& facet);

// Where a tapered wall runs out to a knife edge (a rim cut very obliquely, a wedge's tip), the radius
// function goes to zero at the rim and sweep lines there converge into the tip. Facets at the rim with
// a vertex of radius below minRadius are dropped, again at the new rim until none is left, and the
// unused vertices with them, so the mesh ends where the wall is still 2 x minRadius thick.
// [in,out] chordal: with normals and radius computed. Returns the number of facets dropped.
std::size_t trimKnifeEdges(ChordalSurface& chordal, double minRadius);

// Drops the parts of the surface (facets joined by their corners) whose area is under 1 % of the largest part's: a
// few tets spanning the wall apart from the rest, where a rim corner pinches it (a tall rim's corner at a bend).
// [in,out] chordal. Returns the number of facets dropped.
std::size_t dropIslands(ChordalSurface& chordal);

// Keeps the vertices the facets use, renumbered in their order (with their normals and radius if computed).
// [in,out] chordal. Returns the number of facets.
std::size_t dropUnusedVertices(ChordalSurface& chordal);

// Drops the facets round each rim vertex where the rim passes twice (fans of facets touching at the vertex
// only), but the largest fan, until the rim passes every vertex once; and the vertices no facet uses then.
// [in,out] chordal. Returns the number of facets dropped.
std::size_t dropPinchedFacets(ChordalSurface& chordal);

// The facets as triangles, in facet order, each quad split on its diagonal from corner 0 (0-1-2, 0-2-3), or from corner
// 1 (0-1-3, 1-2-3) where the first diagonal is an edge of the surface: a triangle beside the quad on that edge (a fold
// the tets leave) would give the edge four triangles, which Gmsh's parametrization refuses.
std::vector<std::array<int, 3>> chordalTriangles(const ChordalSurface& chordal);

// Area of the chordal surface (a quad facet as the two triangles (0,1,2) and (0,2,3)).
double chordalArea(const ChordalSurface& chordal);

// Table 1 (§5.3): how many tets have (exterior triangles, exterior edges), keyed "tri/edge".
std::map<std::string, std::size_t> classifyTets(const TetMesh& tets);

}  // namespace hexlayer
