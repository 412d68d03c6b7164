"""Checks metalfit's Blender scripts (blender/<stem>.py of `metalfit export --format blender`, docs/export.md).

Two ways, one set of checks:
  blender -b --factory-startup --python-exit-code 1 --python tests/blender_export_check.py -- RECORD SCRIPT...
      Blender itself runs each script and the material it made is read back (the branch of that Blender's version).
  python3 tests/blender_export_check.py --published RECORD SCRIPT...
      Each script runs against the node inputs Blender publishes (PUBLISHED below, copied from Blender's sources) for
      Blender 4.3 (Metallic BSDF) and 4.0 (Principled BSDF v2): a socket, node type or enum value Blender does not
      have is an error, and the values set are read back as from Blender.

RECORD is metalfit_export.json of the same export (with --format json): the expected values are computed here from
the written parameters it holds, with this file's own formulas (F0 of n, k; Gulbrandsen's r, g -> n, k).
"""
import json
import math
import os
import runpy
import sys
import types

# Blender's published node inputs (the socket names and kinds; "colour" takes RGBA, "vector" XYZ, "float" one value)
# and enum values, from blender/blender:
#  - ShaderNodeBsdfMetallic: source/blender/nodes/shader/nodes/node_shader_bsdf_metallic.cc (node_declare; added in
#    Blender 4.3, release notes 4.3 Rendering, commit 6ccb33e9fe; file read at commit 1cb373e980e1) — IOR and
#    Extinction .min(0).max(100); fresnel_type and distribution from the Python API reference
#    (bpy.types.ShaderNodeBsdfMetallic, Blender 5.0 manual: 'PHYSICAL_CONDUCTOR', 'F82'; 'BECKMANN', 'GGX',
#    'MULTI_GGX').
#  - ShaderNodeBsdfPrincipled of Blender >= 4.0: node_shader_bsdf_principled.cc (node_declare, file read at commit
#    a68d39e9d98d): "Specular Tint" is a colour ("metallic reflection at near-grazing incidence").
#  - ShaderNodeBsdfPrincipled of Blender < 4.0: Debian's Blender 3.4.1 (the real run of this file).
PUBLISHED = {
    (4, 3, 0): {
        "ShaderNodeBsdfMetallic": {
            "inputs": {"Base Color": "colour", "Edge Tint": "colour", "IOR": "vector", "Extinction": "vector",
                       "Roughness": "float", "Anisotropy": "float", "Rotation": "float", "Normal": "vector",
                       "Tangent": "vector", "Weight": "float", "Thin Film Thickness": "float",
                       "Thin Film IOR": "float"},
            "ranges": {"IOR": (0.0, 100.0), "Extinction": (0.0, 100.0), "Roughness": (0.0, 1.0)},
            "enums": {"fresnel_type": {"PHYSICAL_CONDUCTOR", "F82"},
                      "distribution": {"BECKMANN", "GGX", "MULTI_GGX"}},
            "outputs": {"BSDF"},
        },
    },
    (4, 0, 0): {
        "ShaderNodeBsdfPrincipled": {
            "inputs": {"Base Color": "colour", "Metallic": "float", "Roughness": "float", "IOR": "float",
                       "Alpha": "float", "Normal": "vector", "Weight": "float", "Diffuse Roughness": "float",
                       "Subsurface Weight": "float", "Subsurface Radius": "vector", "Subsurface Scale": "float",
                       "Subsurface IOR": "float", "Subsurface Anisotropy": "float", "Specular IOR Level": "float",
                       "Specular Tint": "colour", "Anisotropic": "float", "Anisotropic Rotation": "float",
                       "Tangent": "vector", "Transmission Weight": "float", "Coat Weight": "float",
                       "Coat Roughness": "float", "Coat IOR": "float", "Coat Tint": "colour",
                       "Coat Normal": "vector", "Sheen Weight": "float", "Sheen Roughness": "float",
                       "Sheen Tint": "colour", "Emission Color": "colour", "Emission Strength": "float",
                       "Thin Film Thickness": "float", "Thin Film IOR": "float"},
            "ranges": {"Metallic": (0.0, 1.0), "Roughness": (0.0, 1.0)},
            "enums": {"distribution": {"GGX", "MULTI_GGX"}, "subsurface_method": {"BURLEY", "RANDOM_WALK",
                                                                                   "RANDOM_WALK_SKIN"}},
            "outputs": {"BSDF"},
        },
    },
}
OUTPUT_NODE = {"inputs": {"Surface": "shader", "Volume": "shader", "Displacement": "vector", "Thickness": "float"},
               "ranges": {}, "enums": {"target": {"ALL", "EEVEE", "CYCLES"}}, "outputs": set()}

FLOAT_TOLERANCE = 2e-7  # Blender holds socket values as 32-bit floats: relative


def fail(message):
    raise AssertionError(message)


# ---------------------------------------------------------------- the expected values, from the record

def f0_of_nk(n, k):
    return ((n - 1.0) ** 2 + k * k) / ((n + 1.0) ** 2 + k * k)


def gulbrandsen_nk(r, g):
    # Gulbrandsen, "Artist Friendly Metallic Fresnel", JCGT 3(4), 2014: n between n_min (g = 1) and n_max (g = 0).
    n_min = (1.0 - r) / (1.0 + r)
    n_max = (1.0 + math.sqrt(r)) / (1.0 - math.sqrt(r))
    n = g * n_min + (1.0 - g) * n_max
    k2 = ((n + 1.0) ** 2 * r - (n - 1.0) ** 2) / (1.0 - r)
    return n, math.sqrt(max(k2, 0.0))


def file_stem(material_id, model, prefix="metalfit"):
    # docs/export.md: <prefix>_<material>_<model> in lower case, every other byte '_'
    text = f"{prefix}_{material_id}_{model}".lower().encode("utf-8")
    return "".join(chr(b) if chr(b).isascii() and chr(b).isalnum() else "_" for b in text)


def expectations(record, script):
    """What the script must set: F0 at normal incidence, the F82-tint form, n, k where an n, k curve is written."""
    stem = os.path.basename(script)
    for material_id, material in record["materials"].items():
        for model, entry in material["models"].items():
            if file_stem(material_id, model) + ".py" != stem:
                continue
            p = entry["export"]["params"]
            ex = {"id": material_id, "model": model, "name": f"{material['name']} (metalfit {model})",
                  "roughness": entry["export"]["roughness"]}
            if model in ("schlick", "f82-tint"):
                ex["f0_curve"] = p["F0"]
            elif "n" in p and "k" in p:
                ex["f0_curve"] = [f0_of_nk(n, k) for n, k in zip(p["n"], p["k"])]
            elif model == "gulbrandsen":
                ex["f0_curve"] = p["r"]
            else:
                fail(f"{stem}: no independent F0 for {model} in this checker")
            if model == "conductor-rgb":
                ex["nk"] = (p["n"], p["k"])
            elif model == "gulbrandsen":
                pairs = [gulbrandsen_nk(r, g) for r, g in zip(p["r"], p["g"])]
                ex["nk"] = ([a for a, _ in pairs], [b for _, b in pairs])
            if ex.get("nk") and not all(0.0 <= v <= 100.0 for v in ex["nk"][0] + ex["nk"][1]):
                ex["nk"] = None  # beyond the Metallic BSDF's sockets: the script writes the F82-tint form
            if model == "f82-tint":
                ex["f82"] = (p["F0"], p["tint"])
            elif model in ("schlick", "lazanyi"):  # Schlick (lazanyi: with F0 of its n, k): tint 1
                ex["f82"] = (ex["f0_curve"], [1.0, 1.0, 1.0])
            else:  # the stand-in: the material's f82-tint parameters (exported beside it by the test)
                f = material["models"].get("f82-tint")
                if f is None:
                    fail(f"{stem}: export f82-tint too: the stand-in's values are checked against it")
                ex["f82"] = (f["export"]["params"]["F0"], f["export"]["params"]["tint"])
            return ex
    fail(f"{script}: no material and model of the record matches it")


def close(got, want, what):
    got = list(got)
    if len(got) != len(want):
        fail(f"{what}: {len(got)} components, expected {len(want)}")
    for g, w in zip(got, want):
        if not abs(g - w) <= FLOAT_TOLERANCE * max(1.0, abs(w)):
            fail(f"{what}: {got} != {want}")


# ---------------------------------------------------------------- the checks (real Blender or the published table)

def check_material(bpy, material, ex, script):
    what = os.path.basename(script)
    if material.name != ex["name"]:
        fail(f"{what}: material name {material.name!r}, expected {ex['name']!r}")
    if material["metalfit"]["material"] != ex["id"] or material["metalfit"]["model"] != ex["model"]:
        fail(f"{what}: metalfit property {dict(material['metalfit'])}")
    tree = material.node_tree
    outputs = [n for n in tree.nodes if n.bl_idname == "ShaderNodeOutputMaterial"]
    if len(outputs) != 1 or len(tree.nodes) != 2:
        fail(f"{what}: nodes {[n.bl_idname for n in tree.nodes]}, expected one BSDF and one output")
    links = [l for l in tree.links if l.to_node == outputs[0] and l.to_socket.name == "Surface"]
    if len(links) != 1 or links[0].from_socket.name != "BSDF":
        fail(f"{what}: the BSDF is not linked to the output's Surface")
    bsdf = links[0].from_node
    inputs = bsdf.inputs
    version = tuple(bpy.app.version)
    close([inputs["Roughness"].default_value], [ex["roughness"]], f"{what} Roughness")
    if version >= (4, 3, 0):
        if bsdf.bl_idname != "ShaderNodeBsdfMetallic" or bsdf.distribution != "MULTI_GGX":
            fail(f"{what}: {bsdf.bl_idname} ({getattr(bsdf, 'distribution', None)}), expected a Metallic BSDF")
        if ex.get("nk"):
            if bsdf.fresnel_type != "PHYSICAL_CONDUCTOR":
                fail(f"{what}: fresnel_type {bsdf.fresnel_type}, expected PHYSICAL_CONDUCTOR for n, k")
            close(inputs["IOR"].default_value, ex["nk"][0], f"{what} IOR")
            close(inputs["Extinction"].default_value, ex["nk"][1], f"{what} Extinction")
            # and the n, k give back the curve's F0 (Gulbrandsen's r; conductor-rgb's own)
            close([f0_of_nk(n, k) for n, k in zip(*ex["nk"])], ex["f0_curve"], f"{what} F0 of IOR, Extinction")
        else:
            if bsdf.fresnel_type != "F82":
                fail(f"{what}: fresnel_type {bsdf.fresnel_type}, expected F82")
            close(inputs["Base Color"].default_value, ex["f82"][0] + [1.0], f"{what} Base Color")
            close(inputs["Edge Tint"].default_value, ex["f82"][1] + [1.0], f"{what} Edge Tint")
    else:
        if bsdf.bl_idname != "ShaderNodeBsdfPrincipled":
            fail(f"{what}: {bsdf.bl_idname}, expected the Principled BSDF before Blender 4.3")
        close([inputs["Metallic"].default_value], [1.0], f"{what} Metallic")
        if version >= (4, 0, 0):
            close(inputs["Base Color"].default_value, ex["f82"][0] + [1.0], f"{what} Base Color")
            close(inputs["Specular Tint"].default_value, ex["f82"][1] + [1.0], f"{what} Specular Tint")
        else:
            close(inputs["Base Color"].default_value, ex["f0_curve"] + [1.0], f"{what} Base Color")
            close([inputs["Specular"].default_value], [1.0], f"{what} Specular")
    return f"{what}: {bsdf.bl_idname} in Blender {'.'.join(map(str, version))}: {material.name!r} as expected"


# ---------------------------------------------------------------- Blender's published inputs as a bpy to run against

class Socket:
    def __init__(self, node, name, kind):
        self.node, self.name, self.kind, self._value = node, name, kind, None

    @property
    def default_value(self):
        return self._value

    @default_value.setter
    def default_value(self, value):
        size = {"colour": 4, "vector": 3, "float": None}[self.kind]
        values = [value] if size is None else list(value)
        if size is not None and len(values) != size:
            fail(f"{self.node.bl_idname} '{self.name}' is a {self.kind} of {size}, set with {len(values)} values")
        low, high = self.node.spec["ranges"].get(self.name, (-math.inf, math.inf))
        if not all(low <= float(v) <= high for v in values):
            fail(f"{self.node.bl_idname} '{self.name}' = {values} outside Blender's [{low}, {high}] (it would clamp)")
        self._value = value if size is None else tuple(float(v) for v in values)


class Sockets(dict):
    def __init__(self, node, spec):
        super().__init__({name: Socket(node, name, kind) for name, kind in spec.items()})
        self.node = node

    def __getitem__(self, name):
        if name not in self:
            fail(f"{self.node.bl_idname} has no socket '{name}' in Blender's published inputs")
        return super().__getitem__(name)


class Node:
    def __init__(self, idname, spec):
        object.__setattr__(self, "bl_idname", idname)
        object.__setattr__(self, "spec", spec)
        object.__setattr__(self, "inputs", Sockets(self, spec["inputs"]))
        object.__setattr__(self, "outputs", Sockets(self, {n: "shader" for n in spec["outputs"]}))
        object.__setattr__(self, "location", (0, 0))

    def __setattr__(self, name, value):
        if name == "location":
            object.__setattr__(self, name, value)
            return
        if name not in self.spec["enums"]:
            fail(f"{self.bl_idname} has no property '{name}' in Blender's published API")
        if value not in self.spec["enums"][name]:
            fail(f"{self.bl_idname}.{name} = {value!r}: not one of {sorted(self.spec['enums'][name])}")
        object.__setattr__(self, name, value)


class Link:
    def __init__(self, from_socket, to_socket):
        self.from_socket, self.to_socket = from_socket, to_socket
        self.from_node, self.to_node = from_socket.node, to_socket.node


class Tree:
    def __init__(self, version):
        self.version, self.links_list = version, []
        tree = self

        class Nodes(list):
            def new(self, idname):
                specs = dict(PUBLISHED[tree.version], ShaderNodeOutputMaterial=OUTPUT_NODE)
                if idname not in specs:
                    fail(f"node type {idname} is not among Blender {tree.version}'s published nodes checked here")
                node = Node(idname, specs[idname])
                self.append(node)
                return node

        class Links(list):
            def new(self, from_socket, to_socket):
                link = Link(from_socket, to_socket)
                self.append(link)
                return link

        self.nodes, self.links = Nodes(), Links()


class Material(dict):
    def __init__(self, name, version):
        super().__init__()
        self.name, self.use_nodes, self.node_tree = name, False, Tree(version)
        # Blender's new material has a Principled BSDF and an output; the script clears them
        self.node_tree.nodes.append(Node("ShaderNodeOutputMaterial", OUTPUT_NODE))


def published_bpy(version):
    bpy = types.ModuleType("bpy")
    bpy.app = types.SimpleNamespace(version=version)
    made = []

    class Materials:
        def new(self, name):
            m = Material(name, version)
            made.append(m)
            return m

    bpy.data = types.SimpleNamespace(materials=Materials())
    return bpy


def main(argv):
    published = argv and argv[0] == "--published"
    if published:
        argv = argv[1:]
    record = json.load(open(argv[0], encoding="utf-8"))
    scripts = argv[1:]
    if not scripts:
        fail("no scripts to check")
    lines = []
    if published:
        for version in sorted(PUBLISHED):
            for script in scripts:
                bpy = published_bpy(version)
                sys.modules["bpy"] = bpy
                namespace = runpy.run_path(script, run_name="__main__")
                lines.append(check_material(bpy, namespace["material"], expectations(record, script), script))
        del sys.modules["bpy"]
    else:
        import bpy
        for script in scripts:
            namespace = runpy.run_path(script, run_name="__main__")
            material = namespace["material"]
            if bpy.data.materials.get(material.name) != material:
                fail(f"{script}: the material is not in bpy.data.materials")
            lines.append(check_material(bpy, material, expectations(record, script), script))
    for line in lines:
        print("blender_export_check:", line)
    print(f"blender_export_check: {len(lines)} materials as expected")


if __name__ == "__main__":
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    main(args)
