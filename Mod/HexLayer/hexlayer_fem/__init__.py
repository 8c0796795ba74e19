"""FreeCAD side of Hex-Layer: the mesh object, its view provider, task panel and command.

The meshing itself is the hexlayer executable, run as a child process (mesher.py), installed in bin/ beside this
package by scripts/install-workbench.sh; the workbench imports no compiled module of its own.
"""
import os

ICONS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Resources", "icons")


def icon(name):
    """Path of the workbench's icon NAME.svg."""
    return os.path.join(ICONS, name + ".svg")


class Stateless:
    """A proxy with nothing to save: its object's properties hold everything.
    FreeCAD 0.20 calls __getstate__/__setstate__, FreeCAD 1.x dumps/loads."""

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None
