# Hex-Layer workbench, start-up without GUI (freecadcmd and GUI alike): the meshing needs the compiled
# module pyhexlayer, which scripts/install-workbench.sh puts beside this file. Say so at once if it is missing.
import FreeCAD

try:
    import pyhexlayer  # noqa: F401
except ImportError as error:
    FreeCAD.Console.PrintError(
        "Hex-Layer: the Python module pyhexlayer cannot be imported ({}): build HexLayer and run "
        "scripts/install-workbench.sh.\n".format(error))
