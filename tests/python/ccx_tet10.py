"""Independent references for the CalculiX tests: a CAD part (STEP or BREP) meshed by Gmsh in second-order
tetrahedra, a C3D10 deck written here and solved by ccx. Nothing of HexLayer takes part, so a HexLayer result
compared with it is checked against the elasticity problem, not against HexLayer on a finer mesh.

The load is a uniform traction on one planar face, as equivalent (consistent) nodal forces of each 6-node
triangle: nothing on its corners, a third of its share on each mid-side node. That is the rule FreeCAD's Force
constraint uses on a tet10 mesh, and the work-equivalent of the traction for a quadratic triangle. The same
weights give the area mean of the displacement over the face; the tests compare the plain mean over the face's
nodes, as the HexLayer side measures it, and the area mean is returned beside it.

Plain Python with gmsh and NumPy: /usr/bin/python3, or FreeCAD's interpreter (the same on Debian 12)."""
import os
import subprocess
import tempfile
from collections import namedtuple

import numpy as np

# Gmsh's 10-node tetrahedron lists its last two mid-side nodes as (2-3, 1-3), CalculiX's C3D10 as (1-3, 2-3).
GMSH_TO_C3D10 = (0, 1, 2, 3, 4, 5, 6, 7, 9, 8)
GMSH_TET10, GMSH_TRI6 = 11, 9

Tet10Mesh = namedtuple("Tet10Mesh", "nodes tets faces")  # {id: xyz}, (M, 10) ids in C3D10 order, [(centre, (K, 6) ids)]
Tet10Result = namedtuple("Tet10Result", "mean area_mean area load_nodes nodes elements")


def mesh_tet10(cad, size):
    """Meshes the solid of `cad` by Gmsh with tetrahedra of edge `size`, order 2. Returns a Tet10Mesh: the nodes,
    the tets in C3D10 order and, for each planar CAD face, its centre and its 6-node triangles."""
    import gmsh
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(cad)
        gmsh.option.setNumber("Mesh.MeshSizeMin", size)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
        gmsh.model.mesh.generate(3)
        gmsh.model.mesh.setOrder(2)
        ids, xyz, _ = gmsh.model.mesh.getNodes()
        nodes = dict(zip(ids.astype(int), xyz.reshape(-1, 3)))
        _, tets = gmsh.model.mesh.getElementsByType(GMSH_TET10)
        tets = tets.astype(int).reshape(-1, 10)[:, GMSH_TO_C3D10]
        faces = [(np.array(gmsh.model.occ.getCenterOfMass(2, tag)),
                  gmsh.model.mesh.getElementsByType(GMSH_TRI6, tag)[1].astype(int).reshape(-1, 6))
                 for _, tag in gmsh.model.getEntities(2) if gmsh.model.getType(2, tag) == "Plane"]
    finally:
        gmsh.finalize()
    return Tet10Mesh(nodes, tets, faces)


def face_triangles(mesh, where):
    """The 6-node triangles of the one planar face whose centre satisfies where(centre)."""
    found = [triangles for centre, triangles in mesh.faces if where(centre)]
    if len(found) != 1:
        raise ValueError("expected one face, found {}".format(len(found)))
    return found[0]


def midside_weights(mesh, triangles):
    """{node id: area} of the mid-side nodes of the 6-node triangles: a third of each (flat) triangle's area,
    the integral of the node's shape function over it (a corner's is 0)."""
    weights = {}
    for triangle in triangles:
        a, b, c = (mesh.nodes[n] for n in triangle[:3])
        area = 0.5 * np.linalg.norm(np.cross(b - a, c - a))
        for n in triangle[3:]:
            weights[n] = weights.get(n, 0.0) + area / 3.0
    return weights


def write_deck(path, mesh, held, loads, elastic, printed):
    """A static C3D10 deck: `held` [(node, first DOF, last DOF)] fixed to 0, `loads` {node: force (3,)} as *CLOAD,
    linear elastic `elastic` (E, nu), the displacements of the nodes `printed` to the .dat file."""
    with open(path, "w") as f:
        # CalculiX reads at most 20 characters of a number: 13 significant digits
        f.write("*NODE, NSET=NALL\n" + "".join("{}, {:.12e}, {:.12e}, {:.12e}\n".format(n, *x)
                                               for n, x in sorted(mesh.nodes.items())))
        f.write("*ELEMENT, TYPE=C3D10, ELSET=EALL\n")
        f.write("".join("{}, {}\n".format(i, ", ".join(map(str, tet))) for i, tet in enumerate(mesh.tets, start=1)))
        f.write("*NSET, NSET=PRINTED\n" + "".join("{},\n".format(n) for n in sorted(printed)))
        f.write("*MATERIAL, NAME=MAT\n*ELASTIC\n{!r}, {!r}\n".format(*elastic))
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=MAT\n*BOUNDARY\n")
        f.write("".join("{}, {}, {}\n".format(*h) for h in held))
        f.write("*STEP\n*STATIC\n*CLOAD\n")
        f.write("".join("{}, {}, {:.12e}\n".format(n, dof + 1, force[dof])
                        for n, force in sorted(loads.items()) for dof in range(3) if force[dof] != 0.0))
        f.write("*NODE PRINT, NSET=PRINTED\nU\n*END STEP\n")


def run_ccx(work, job="job"):
    """Runs ccx on work/job.inp (one thread); {node id: displacement (3,)} of the printed nodes."""
    done = subprocess.run(["ccx", "-i", job], cwd=work, capture_output=True, text=True, timeout=1800,
                          env=dict(os.environ, OMP_NUM_THREADS="1"))
    if done.returncode != 0 or "*ERROR" in done.stdout:
        raise AssertionError("ccx failed:\n" + done.stdout[-2000:])
    displacement, reading = {}, False
    with open(os.path.join(work, job + ".dat")) as f:
        for line in f:
            reading = reading or "displacements" in line
            fields = line.split()
            if reading and len(fields) == 4 and fields[0].isdigit():
                displacement[int(fields[0])] = np.array([float(x) for x in fields[1:]])
    return displacement


def clamp(nodes):
    """Every DOF of every node held (FreeCAD's Fixed constraint)."""
    return [(n, 1, 3) for n in sorted(nodes)]


def solve_tet10(cad, size, fixed, loaded, force, elastic, hold=clamp):
    """The part of `cad` meshed at `size` in tet10 and solved by ccx: the face fixed(centre) held by hold(its
    nodes), the total `force` (3,) spread as a uniform traction over the face loaded(centre). Returns a
    Tet10Result: mean displacement (3,) of the loaded face's nodes, its area mean, the face's area, its node
    count, the mesh's node and element counts."""
    mesh = mesh_tet10(cad, size)
    held = hold({int(n) for n in face_triangles(mesh, fixed).flat})
    triangles = face_triangles(mesh, loaded)
    weights = midside_weights(mesh, triangles)
    area = sum(weights.values())
    loads = {n: np.asarray(force, float) * w / area for n, w in weights.items()}
    face_nodes = {int(n) for n in triangles.flat}
    with tempfile.TemporaryDirectory(prefix="ccx_tet10_") as work:
        write_deck(os.path.join(work, "job.inp"), mesh, held, loads, elastic, face_nodes)
        u = run_ccx(work)
    mean = np.mean([u[n] for n in face_nodes], axis=0)
    area_mean = sum(u[n] * w for n, w in weights.items()) / area
    return Tet10Result(mean, area_mean, area, len(face_nodes), len(mesh.nodes), len(mesh.tets))
