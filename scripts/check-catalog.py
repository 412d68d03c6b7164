#!/usr/bin/env python3
"""Validate data/catalog.json against the files in data/nk.

Usage: scripts/check-catalog.py [DATA_DIR]      (default: <repo>/data)

Checks:
  * the document has the metalfit.catalog/1 shape (keys, types, kinds);
  * every material has a primary; ids are unique;
  * the optional coverage (range_nm, points_360_830) has its shape;
  * every "file" exists, is relative to DATA_DIR, and is nk/<id>/<source>.yml;
  * aliases contain the id and the name and are unique across the whole
    catalog, compared case-insensitively;
  * every *.yml file under DATA_DIR/nk is referenced exactly once.
Prints one line per problem and exits 1 if there is any; python3 stdlib only.
"""
import json
import os
import sys

KINDS = {"metal", "alloy", "intermetallic", "nitride", "carbide"}
SOURCE_KEYS = ["source", "file", "reference", "doi", "licence", "database_path", "note"]
# The table's coverage, written by scripts/catalog-coverage.py (metalfit list reads it instead of the table); optional,
# both or neither.
COVERAGE_KEYS = ["range_nm", "points_360_830"]
MATERIAL_KEYS = ["id", "name", "aliases", "kind", "primary", "alternates"]
DATABASE_KEYS = ["name", "repository", "commit", "licence", "citation"]


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    data_dir = argv[1] if len(argv) > 1 else os.path.join(here, "..", "data")
    data_dir = os.path.normpath(data_dir)
    catalog_path = os.path.join(data_dir, "catalog.json")
    errors = []

    def err(msg):
        errors.append(msg)

    try:
        with open(catalog_path, encoding="utf-8") as fh:
            cat = json.load(fh)
    except (OSError, ValueError) as e:
        print(f"{catalog_path}: cannot read: {e}")
        return 1

    if cat.get("schema") != "metalfit.catalog/1":
        err(f"schema: expected 'metalfit.catalog/1', got {cat.get('schema')!r}")
    db = cat.get("database")
    if not isinstance(db, dict):
        err("database: missing or not an object")
    else:
        for k in DATABASE_KEYS:
            if not isinstance(db.get(k), str) or not db.get(k):
                err(f"database.{k}: missing or not a non-empty string")
        extra = set(db) - set(DATABASE_KEYS)
        if extra:
            err(f"database: unknown keys {sorted(extra)}")
    materials = cat.get("materials")
    if not isinstance(materials, list) or not materials:
        err("materials: missing, empty or not a list")
        materials = []
    extra = set(cat) - {"schema", "database", "materials"}
    if extra:
        err(f"top level: unknown keys {sorted(extra)}")

    referenced = {}   # normalised relative path -> list of "where" strings
    alias_owner = {}  # lower-case alias -> material id
    ids = set()

    def check_source(mid, where, src):
        if not isinstance(src, dict):
            err(f"{where}: not an object")
            return
        missing = [k for k in SOURCE_KEYS if k not in src]
        extra = set(src) - set(SOURCE_KEYS) - set(COVERAGE_KEYS)
        present = [k for k in COVERAGE_KEYS if k in src]
        if present and len(present) != len(COVERAGE_KEYS):
            err(f"{where}: {present} without {[k for k in COVERAGE_KEYS if k not in src]} (both or neither)")
        if "range_nm" in src:
            r = src["range_nm"]
            if not (isinstance(r, list) and len(r) == 2 and all(isinstance(x, (int, float)) for x in r) and r[0] < r[1]):
                err(f"{where}.range_nm: must be [min, max] in nm, got {r!r}")
        if "points_360_830" in src:
            v = src["points_360_830"]
            if not isinstance(v, int) or isinstance(v, bool) or v < 0:
                err(f"{where}.points_360_830: must be a non-negative integer, got {v!r}")
        if missing:
            err(f"{where}: missing keys {missing}")
        if extra:
            err(f"{where}: unknown keys {sorted(extra)}")
        for k in SOURCE_KEYS:
            v = src.get(k)
            if k == "doi":
                if v is not None and (not isinstance(v, str) or not v or v.startswith("doi:")):
                    err(f"{where}.doi: must be null or a bare DOI string, got {v!r}")
            elif k == "note":
                if not isinstance(v, str):
                    err(f"{where}.note: must be a string (empty when none)")
            elif not isinstance(v, str) or not v:
                err(f"{where}.{k}: missing or not a non-empty string")
        if "*" in str(src.get("reference", "")):
            err(f"{where}.reference: contains markdown '*'")
        f = src.get("file")
        if not isinstance(f, str):
            return
        if os.path.isabs(f) or f.replace("\\", "/") != os.path.normpath(f).replace("\\", "/"):
            err(f"{where}.file: must be a normalised path relative to data/: {f!r}")
        expected = f"nk/{mid}/{src.get('source')}.yml"
        if f != expected:
            err(f"{where}.file: expected {expected!r}, got {f!r}")
        full = os.path.join(data_dir, f)
        if not os.path.isfile(full):
            err(f"{where}.file: {f} does not exist under {data_dir}")
        referenced.setdefault(os.path.normpath(f), []).append(where)

    for i, m in enumerate(materials):
        where = f"materials[{i}]"
        if not isinstance(m, dict):
            err(f"{where}: not an object")
            continue
        mid = m.get("id")
        if isinstance(mid, str):
            where = f"materials[{i}] ({mid})"
        else:
            err(f"{where}.id: missing or not a string")
            mid = "?"
        if mid in ids:
            err(f"{where}: duplicate id {mid!r}")
        ids.add(mid)
        missing = [k for k in MATERIAL_KEYS if k not in m]
        extra = set(m) - set(MATERIAL_KEYS)
        if missing:
            err(f"{where}: missing keys {missing}")
        if extra:
            err(f"{where}: unknown keys {sorted(extra)}")
        name = m.get("name")
        if not isinstance(name, str) or not name or name != name.lower():
            err(f"{where}.name: must be a non-empty lower-case string, got {name!r}")
        if m.get("kind") not in KINDS:
            err(f"{where}.kind: {m.get('kind')!r} is not one of {sorted(KINDS)}")
        aliases = m.get("aliases")
        if not isinstance(aliases, list) or not all(isinstance(a, str) and a for a in aliases):
            err(f"{where}.aliases: must be a list of non-empty strings")
            aliases = []
        if mid not in aliases:
            err(f"{where}.aliases: does not contain the id {mid!r}")
        if name not in aliases:
            err(f"{where}.aliases: does not contain the name {name!r}")
        for a in aliases:
            key = a.casefold()
            if key in alias_owner:
                err(f"{where}.aliases: {a!r} already used by {alias_owner[key]!r} (case-insensitive)")
            else:
                alias_owner[key] = mid
        if m.get("primary") is None:
            err(f"{where}.primary: missing")
        else:
            check_source(mid, f"{where}.primary", m["primary"])
        alts = m.get("alternates")
        if not isinstance(alts, list):
            err(f"{where}.alternates: must be a list (empty when none)")
            alts = []
        for j, a in enumerate(alts):
            check_source(mid, f"{where}.alternates[{j}]", a)

    for f, wheres in sorted(referenced.items()):
        if len(wheres) > 1:
            err(f"{f}: referenced {len(wheres)} times: {', '.join(wheres)}")

    nk_dir = os.path.join(data_dir, "nk")
    on_disk = set()
    for root, _dirs, files in os.walk(nk_dir):
        for fn in files:
            if fn.endswith(".yml") or fn.endswith(".yaml"):
                on_disk.add(os.path.normpath(os.path.relpath(os.path.join(root, fn), data_dir)))
    for f in sorted(on_disk - set(referenced)):
        err(f"{f}: file under data/nk is not referenced by catalog.json")

    for e in errors:
        print(f"{catalog_path}: {e}")
    n_src = sum(len(w) for w in referenced.values())
    if errors:
        print(f"check-catalog: FAILED, {len(errors)} problem(s)")
        return 1
    print(f"check-catalog: OK: {len(materials)} materials, {n_src} source files, "
          f"{len(alias_owner)} aliases, {len(on_disk)} files under data/nk")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
