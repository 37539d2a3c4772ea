#!/usr/bin/python3
"""Check the folder dependency table of the module (README, "Layout"): every
#include "..." of a project header must go to a folder the including folder
may use, and no test, tool or plugin source may include a private header of
Mapper/ (the hov*.h of its stage folders; the public vtk* classes are fine).

    /usr/bin/python3 Utilities/check_layers.py [--table]

Exit code 0 if every include is allowed, 1 otherwise (each offending include
is printed). --table prints the table. ctest runs it as hov.Layers.
"""
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# Folder -> the folders whose headers it may include (its own included).
# Stages, lowest first: Kernels; Filters; Scene (set-up every mode shares);
# the mode backends Projector (CPU_ACCURATE), Regions + OpenGL
# (OPENGL_PROJECTION; Regions has no OpenGL), RayCast; the facade (Mapper/).
TABLE = [
    ("Module/Kernels", []),
    ("Filters", ["Module/Kernels"]),
    ("Mapper/Offscreen", []),
    ("Mapper/Scene", ["Module/Kernels", "Filters"]),
    ("Mapper/Projector", ["Module/Kernels", "Mapper/Scene"]),
    ("Mapper/Regions", ["Module/Kernels", "Mapper/Scene"]),
    ("Mapper/RayCast", ["Module/Kernels", "Mapper/Scene"]),
    ("Mapper/OpenGL", ["Module/Kernels", "Mapper/Scene", "Mapper/Regions"]),
    ("Mapper", ["Module/Kernels", "Filters", "Mapper/Offscreen", "Mapper/Scene",
                "Mapper/Projector", "Mapper/Regions", "Mapper/RayCast", "Mapper/OpenGL"]),
]
PRIVATE = ["Mapper/Scene", "Mapper/Projector", "Mapper/Regions", "Mapper/RayCast", "Mapper/OpenGL"]
# Sources that must use the public interface only.
CLIENTS = ["Testing", "Utilities", "ParaView"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def headers():
    """Project header basename -> its folder (relative to the root)."""
    out = {}
    for top in ("Module", "Filters", "Mapper"):
        for dirpath, _, files in os.walk(os.path.join(ROOT, top)):
            for f in files:
                if f.endswith(".h"):
                    out[f] = os.path.relpath(dirpath, ROOT)
            # Shaders are encoded into <name>.h at build time.
            for f in files:
                if f.endswith(".glsl"):
                    out[f[:-5] + ".h"] = os.path.relpath(dirpath, ROOT)
    return out


def folder_of(path):
    rel = os.path.relpath(os.path.dirname(path), ROOT)
    for folder, _ in sorted(TABLE, key=lambda t: -len(t[0])):
        if rel == folder or rel.startswith(folder + os.sep):
            return folder
    return None


def sources(tops):
    for top in tops:
        for dirpath, _, files in os.walk(os.path.join(ROOT, top)):
            for f in files:
                if f.endswith((".h", ".cxx", ".cpp")):
                    yield os.path.join(dirpath, f)


def main():
    if "--table" in sys.argv:
        for folder, allowed in TABLE:
            print("%-18s may include %s" % (folder, ", ".join(allowed) or "(itself only)"))
        return 0
    where = headers()
    allowed = dict(TABLE)
    bad = []
    for path in sources(["Module", "Filters", "Mapper"]):
        folder = folder_of(path)
        if folder is None:
            continue
        for name in INCLUDE.findall(open(path, encoding="utf-8").read()):
            target = where.get(os.path.basename(name))
            if target and target != folder and target not in allowed[folder]:
                bad.append("%s: includes %s (%s may not include %s)" % (
                    os.path.relpath(path, ROOT), name, folder, target))
    for path in sources(CLIENTS):
        for name in INCLUDE.findall(open(path, encoding="utf-8").read()):
            target = where.get(os.path.basename(name))
            if target in PRIVATE and not os.path.basename(name).startswith("vtk"):
                bad.append("%s: includes %s, a private header of %s" % (
                    os.path.relpath(path, ROOT), name, target))
    for line in bad:
        print(line)
    print("%d include(s) against the folder table" % len(bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
