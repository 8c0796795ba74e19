"""What the end-to-end tests read from a CAD file themselves, with Gmsh's OpenCASCADE, to check hexlayer against:
the topology of the part's surface and the faces a message names.

Gmsh numbers the faces of a solid in the file's order, as FreeCAD's FaceN does (the names hexlayer prints and
writes): checked face by face, by area and centre of mass, against FreeCAD 0.20.2 on the L-bracket and the
U-channel of shared/parts/real and on tests/data/robustness/t_junction.step (51, 34 and 14 faces, all equal).
"""
import collections
import contextlib
import math
import re

import numpy as np

# "(x, y, z) [FaceA FaceB ...]": where a junction sheet is (the centre of its faces) and its faces, in a
# T-junction message.
JUNCTION = re.compile(r"\(([-+\d.e]+), ([-+\d.e]+), ([-+\d.e]+)\) \[((?:Face\d+ ?)+)\]")


@contextlib.contextmanager
def opened(step):
    """Gmsh with the CAD file `step` imported, for the block's length."""
    import gmsh
    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.occ.importShapes(step)
        gmsh.model.occ.synchronize()
        yield gmsh
    finally:
        gmsh.finalize()


def cad_volume(step):
    """The volume of the solids in `step`, or of the solid its faces close if it holds none (a shell)."""
    with opened(step) as gmsh:
        if not gmsh.model.getEntities(3):
            gmsh.model.occ.addVolume([gmsh.model.occ.addSurfaceLoop([t for _, t in gmsh.model.getEntities(2)])])
            gmsh.model.occ.synchronize()
        return sum(gmsh.model.occ.getMass(3, tag) for _, tag in gmsh.model.getEntities(3))


def write_placed(gmsh, path, scale=1.0, turn=0.0, axis=(1, 2, 3)):
    """The model's solids (Gmsh's OpenCASCADE, built) turned `turn` degrees about `axis` through the origin, scaled by
    `scale` (Gmsh's dilate, which makes the faces B-splines) and written to `path`."""
    occ = gmsh.model.occ
    occ.synchronize()
    volumes = gmsh.model.getEntities(3)
    if turn:
        occ.rotate(volumes, 0, 0, 0, *axis, math.radians(turn))
    if scale != 1:
        occ.dilate(volumes, 0, 0, 0, scale, scale, scale)
    occ.synchronize()
    gmsh.write(path)


def write_as_bsplines(step, path, scale=1.0):
    """The solids of `step` with every face a B-spline (Gmsh's affine transform, as another CAD system may write the
    same part), scaled by `scale`, written to `path`."""
    with opened(step) as gmsh:
        gmsh.model.occ.affineTransform(gmsh.model.getEntities(3), [scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0])
        gmsh.model.occ.synchronize()
        gmsh.write(path)


def junctions_named(message):
    """The junction sheets a T-junction message names: [((x, y, z), [face numbers])]."""
    return [((float(x), float(y), float(z)), [int(f[4:]) for f in faces.split()])
            for x, y, z, faces in JUNCTION.findall(message)]


def face_group(step, faces):
    """The faces numbered `faces` of the part in `step`, measured by OpenCASCADE: their total area, their
    area-weighted centre, the diagonal of their bounding box, and the same area and diagonal of the whole part."""
    with opened(step) as gmsh:
        every = [tag for _, tag in gmsh.model.getEntities(2)]
        missing = set(faces) - set(every)
        if missing:
            raise AssertionError(f"the part has no face {sorted(missing)} (it has {len(every)})")
        areas = {tag: gmsh.model.occ.getMass(2, tag) for tag in every}
        area = sum(areas[f] for f in faces)
        centre = sum(areas[f] * np.array(gmsh.model.occ.getCenterOfMass(2, f)) for f in faces) / area
        return {"area": area, "centre": centre, "diagonal": diagonal(gmsh, [(2, f) for f in faces]),
                "part_area": sum(areas.values()), "part_diagonal": diagonal(gmsh, gmsh.model.getEntities(3))}


def diagonal(gmsh, entities):
    """Diagonal of the bounding box of Gmsh's `entities` [(dim, tag)]."""
    boxes = np.array([gmsh.model.getBoundingBox(dim, tag) for dim, tag in entities])
    return float(np.linalg.norm(boxes[:, 3:].max(axis=0) - boxes[:, :3].min(axis=0)))


def surface_euler_characteristic(step, size):
    """Euler characteristic V - E + F of the part's surface, from Gmsh's triangulation of its faces with
    triangles of about `size`: the faces share their edges' nodes, so the triangulation has the CAD surface's
    topology whatever the size. Fails unless every triangle edge has exactly two triangles (a closed
    triangulated surface, without the non-manifold glitches a mesher may leave)."""
    with opened(step) as gmsh:
        gmsh.option.setNumber("Mesh.MeshSizeMin", size)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        _, _, nodes = gmsh.model.mesh.getElements(2)
        if any(len(n) % 3 for n in nodes) or len(nodes) != 1:
            raise AssertionError("Gmsh's surface mesh is not one set of triangles")
        triangles = nodes[0].reshape(-1, 3)
    uses = collections.Counter(tuple(sorted(e)) for t in triangles for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])))
    if set(uses.values()) != {2}:
        raise AssertionError(f"Gmsh's triangulation at size {size} is not a closed surface: edge uses "
                             f"{dict(collections.Counter(uses.values()))}")
    return len(np.unique(triangles)) - len(uses) + len(triangles)


# Samples per parameter of a face, to check Gmsh's closest point where it is far (face_distances).
FACE_SAMPLES = 100


def sampled_distances(gmsh, face, points):
    """Distances of points to face `face`'s points on a FACE_SAMPLES x FACE_SAMPLES grid over its parameters, those
    inside the trimmed face (Gmsh's isInside): at least each point's distance to the face (it is to a point of it)."""
    lo, hi = gmsh.model.getParametrizationBounds(2, face)
    u, v = np.meshgrid(np.linspace(lo[0], hi[0], FACE_SAMPLES), np.linspace(lo[1], hi[1], FACE_SAMPLES))
    uv = np.c_[u.ravel(), v.ravel()]
    samples = np.reshape(gmsh.model.getValue(2, face, uv.ravel().tolist()), (-1, 3))
    samples = samples[[gmsh.model.isInside(2, face, p.tolist()) > 0 for p in uv]]
    if len(samples) == 0:
        return np.full(len(points), np.inf)
    return np.array([np.linalg.norm(samples - p, axis=1).min() for p in points])


def face_distances(gmsh, x, index, sets):
    """Per CAD face N, the largest distance of the mesh's nodes grouped on it (the .inp's FACE<N> node sets)
    from that face, by Gmsh's closest point: {N: distance}. x: node coordinates; index: node label -> row of x.
    Gmsh's projection onto a B-spline face can stop at a far local minimum (on a B-spline torus it answered the
    far side, 7.4 mm off, for a node 0.33 mm from it): where a node is farther than 1e-3 of the part's extent, its
    distance to the face's sampled points is taken if smaller (an upper bound of the true one)."""
    far = 1e-3 * float(np.ptp(x, axis=0).max())
    worst = {}
    for name, labels in sets.items():
        if not name.startswith("FACE") or not labels:
            continue
        face = int(name[4:])
        points = x[[index[n] for n in labels]]
        closest, _ = gmsh.model.getClosestPoint(2, face, points.ravel().tolist())
        distances = np.linalg.norm(np.reshape(closest, (-1, 3)) - points, axis=1)
        if (distances > far).any():
            off = distances > far
            distances[off] = np.minimum(distances[off], sampled_distances(gmsh, face, points[off]))
        worst[face] = float(distances.max())
    return worst
