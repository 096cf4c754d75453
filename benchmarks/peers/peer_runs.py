"""What the peer benchmarks share (paired_getfem.py, ../newton_contact.py):
the gmsh meshes of the Hertz cases, made from their .geo files when
missing, and values of a tribos summary.txt. Standard library only."""

import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))

# mesh file: gmsh arguments (run in this folder)
MESHES = {"hertz_2d_13k.msh": ["-2", "-setnumber", "hf", "0.00775",
                               "hertz_2d.geo"],
          "hertz_2d_49k.msh": ["-2", "-setnumber", "hf", "0.00338",
                               "hertz_2d.geo"],
          "hertz_3d_20k.msh": ["-3", "hertz_3d.geo"]}


def mesh(name):
    """The path of mesh name of MESHES, made with gmsh if missing (gmsh
    4.8: the same files)."""
    path = os.path.join(HERE, name)
    if not os.path.exists(path):
        subprocess.run(["gmsh"] + MESHES[name] + ["-o", path], cwd=HERE,
                       stdout=subprocess.DEVNULL, check=True)
    return path


def summary_value(folder, key):
    """The first word after key on the line of folder/summary.txt that
    starts with key ("" if none)."""
    for line in open(os.path.join(folder, "summary.txt")):
        if line.startswith(key):
            return line[len(key):].split()[0]
    return ""
