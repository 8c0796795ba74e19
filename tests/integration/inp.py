"""Reads back what the end-to-end tests need of a CalculiX/Abaqus .inp written by hexlayer: the
nodes, the elements (a data line ending with a comma continues on the next line), the node sets and
the element-face surfaces."""
import numpy as np


def read_inp(path):
    """Returns (nodes {id: (x, y, z)}, elements [(id, [node ids])], node sets {NAME: [ids]})."""
    nodes, elements, sets = {}, [], {}
    block, pending = None, []
    with open(path) as f:
        lines = f.readlines()
    for line in lines:
        if line.startswith("**"):
            continue
        if line.startswith("*"):
            keyword = line.upper()
            block = ("node" if keyword.startswith("*NODE") else "element" if keyword.startswith("*ELEMENT")
                     else "set" if keyword.startswith("*NSET") else None)
            if block == "set":
                name = keyword.split("NSET=")[1].split(",")[0].strip()
                sets[name] = []
            continue
        fields = [x for x in line.replace(",", " ").split()]
        if not fields:
            continue
        if block == "node":
            nodes[int(fields[0])] = tuple(float(x) for x in fields[1:4])
        elif block == "element":
            pending += [int(x) for x in fields]
            if not line.rstrip().endswith(","):
                elements.append((pending[0], pending[1:]))
                pending = []
        elif block == "set":
            sets[name] += [int(x) for x in fields]
    return nodes, elements, sets


def hex_arrays(nodes, elements):
    """read_inp's nodes and elements as arrays: (coordinates (N, 3), elements as rows of indices into them, the
    index {node id: row})."""
    ids = sorted(nodes)
    index = {n: i for i, n in enumerate(ids)}
    return np.array([nodes[n] for n in ids]), np.array([[index[n] for n in e] for _, e in elements]), index


def read_surfaces(path):
    """Element-face surfaces of an .inp: {NAME: [(element id, face number 1..6 of "S1".."S6")]}."""
    surfaces, name = {}, None
    with open(path) as f:
        for line in f:
            if line.startswith("**"):
                continue
            if line.startswith("*"):
                keyword = line.upper()
                name = keyword.split("NAME=")[1].split(",")[0].strip() if keyword.startswith("*SURFACE") else None
                if name:
                    surfaces[name] = []
                continue
            if name and line.strip():
                element, face = [x.strip() for x in line.split(",")]
                surfaces[name].append((int(element), int(face.upper().lstrip("S"))))
    return surfaces
