#!/usr/bin/env python3
"""The house drawn from the imports: each stage folder of libfit and of glpreview includes only earlier stages (the
data flow of docs/development.md), never a later one. Prints every include that points up the flow; exit 1 if any.

Usage: scripts/check-layering.py [SOURCE_DIR]
"""
import os
import re
import sys

# The stage order of each library, as docs/development.md draws it. A tuple is one stage of several folders:
# glpreview's effects are the renderer's plug-ins (the renderer calls the registry, each effect uses the renderer).
LIBRARIES = {
    "libfit": (["libfit/include/libfit", "libfit/src"], "libfit",
               ["base", "spectral", "io", "optics", "color", "reference", "models", "fit", "export", "report"]),
    "glpreview": (["glpreview/include/glpreview", "glpreview/src"], "glpreview",
                  ["scene", "graph", "gl", "io", ("render", "effects")]),
}


def includes(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
            if m:
                yield number, m.group(1)


def main(root):
    upward = 0
    for name, (trees, prefix, stages) in LIBRARIES.items():
        # folder → its stage's position
        order = {folder: i for i, stage in enumerate(stages) for folder in (stage if isinstance(stage, tuple) else (stage,))}
        seen = 0
        for tree in trees:
            for folder, _, files in os.walk(os.path.join(root, tree)):
                for file in files:
                    path = os.path.join(folder, file)
                    stage = os.path.relpath(path, os.path.join(root, tree)).split(os.sep)[0]
                    if stage not in order:
                        continue
                    seen += 1
                    for number, target in includes(path):
                        parts = target.split("/")
                        if parts[0] == prefix:
                            parts = parts[1:]
                        if len(parts) > 1 and parts[0] in order and order[parts[0]] > order[stage]:
                            print(f"{os.path.relpath(path, root)}:{number}: {stage}/ includes {target}, a later stage")
                            upward += 1
        if seen == 0:
            print(f"{name}: no stage folders found under {root}")
            upward += 1
    print(f"layering: {upward} include(s) against the data flow")
    return 1 if upward else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
