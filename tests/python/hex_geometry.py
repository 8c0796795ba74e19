"""Geometry of linear hexes for the tests (plain NumPy, any interpreter)."""
import numpy as np

# A hex in CalculiX's C3D8 / HexLayer's node order, as 6 tets around its diagonal 0-6.
HEX_TETS = ((0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6))


def hex_volumes(nodes, hexes):
    """Volume of each hex (rows of 8 node indices into nodes (N, 3)); negative if inverted."""
    x = np.asarray(nodes)[np.asarray(hexes)]
    volume = np.zeros(len(hexes))
    for a, b, c, d in HEX_TETS:
        volume += np.einsum("ij,ij->i", x[:, b] - x[:, a], np.cross(x[:, c] - x[:, a], x[:, d] - x[:, a])) / 6.0
    return volume


# Each corner's three edge neighbours, in the order that makes the corner's Jacobian positive for a
# well-shaped hex (corners 0-3 the bottom quad, counter-clockwise seen from above, 4-7 the quad above).
CORNER_EDGES = ((1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7), (7, 5, 0), (4, 6, 1), (5, 7, 2), (6, 4, 3))


def hex_scaled_jacobians(nodes, hexes):
    """Scaled Jacobian of each hex: the smallest, over its 8 corners, determinant of the corner's three unit
    edge vectors (1 for a brick, <= 0 for an inverted corner)."""
    x = np.asarray(nodes)[np.asarray(hexes)]
    worst = np.full(len(hexes), np.inf)
    for corner, (a, b, c) in enumerate(CORNER_EDGES):
        e = [x[:, k] - x[:, corner] for k in (a, b, c)]
        e = [v / np.linalg.norm(v, axis=1)[:, None] for v in e]
        worst = np.minimum(worst, np.einsum("ij,ij->i", e[0], np.cross(e[1], e[2])))
    return worst


# A hex's 12 edges as corner pairs, in the order of its mid-edge nodes 9-20 (CalculiX's C3D20).
HEX_EDGES = ((0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7))


# A hex's six faces (C3D8 corner order).
HEX_FACES = ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def boundary_faces(hexes):
    """The faces used by one hex only (rows of 4 node indices: the mesh's boundary) and the row of that hex."""
    faces = np.asarray(hexes)[:, HEX_FACES].reshape(-1, 4)
    _, first, count = np.unique(np.sort(faces, axis=1), axis=0, return_index=True, return_counts=True)
    rows = first[count == 1]
    return faces[rows], rows // len(HEX_FACES)


def boundary_quads(hexes):
    """The faces used by one hex only (rows of 4 node indices): the mesh's boundary."""
    return boundary_faces(hexes)[0]


def boundary_euler_characteristic(hexes):
    """V - E + F of the mesh's boundary quads (2 - 2 g for a closed surface of genus g)."""
    quads = boundary_quads(hexes)
    edges = np.sort(np.stack([quads, np.roll(quads, -1, axis=1)], axis=2).reshape(-1, 2), axis=1)
    return len(np.unique(quads)) - len(np.unique(edges, axis=0)) + len(quads)
