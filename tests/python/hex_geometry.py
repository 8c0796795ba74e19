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
