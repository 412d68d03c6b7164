// ctest json_schemas.* (json_schemas.sh): validates metalfit's JSON records against the JSON Schemas in schemas/
// with Ajv (npm ajv, pinned in package.json; JSON Schema 2020-12, strict mode: a schema with an unknown keyword fails
// to compile).
//
// Each file given is validated against the schema its `schema` member names (`metalfit.fit/1` → urn:metalfit:schema:fit);
// `metalfit_export.json` against the export schema (the fit record with `export` in every model); a `.gltf` by the
// `extras.metalfit` of each material (metalfit.gltf/1); a `{header, data}` document (physicallybased.info's shape,
// `table --format physicallybased`) against urn:metalfit:schema:physicallybased. A record naming no known schema fails: every record metalfit
// writes has one.
//
// --broken: instead, every file must be valid and every deliberately broken copy of it must be refused: the `schema`
// member changed, each required top-level member removed in turn, an unknown top-level member added, and numbers at up
// to 40 places spread over the document (all depths) replaced by a string, and every input file it names (members
// `file`, `ocio_config`, `cost_table`, up to 10) replaced by an absolute path (records never name one: docs/fit-record.md,
// Paths in records). A broken copy that still validates fails the test: the schemas constrain every part of the records.
//
// Usage: node json_schemas.mjs NODE_MODULES SCHEMAS_DIR [--broken] FILE…
import { readFile, readdir } from "node:fs/promises";
import { createRequire } from "node:module";
import path from "node:path";

const args = process.argv.slice(2);
const [modules, schemasDir] = args;
const broken = args.includes("--broken");
const files = args.slice(2).filter((a) => a !== "--broken");
const require = createRequire(path.join(path.resolve(modules), "noop.js"));
const Ajv2020 = require("ajv/dist/2020").default;
const ajv = new Ajv2020({ strict: true, allErrors: true });
for (const name of (await readdir(schemasDir)).filter((n) => n.endsWith(".schema.json")).sort())
  ajv.addSchema(JSON.parse(await readFile(path.join(schemasDir, name), "utf8")));
// Compile every schema up front: a schema that does not compile (unknown keyword, bad $ref) fails here.
for (const id of Object.keys(ajv.schemas)) if (id.startsWith("urn:metalfit:schema:")) ajv.getSchema(id);

if (files.length === 0) {
  console.error("json_schemas.mjs: no files given");
  process.exit(2);
}

// [label, document, schema id] of each record in a file.
function recordsOf(file, json) {
  if (file.endsWith(".gltf"))
    return (json.materials ?? []).map((m, i) => [`${file} materials[${i}].extras.metalfit`, m.extras?.metalfit, "urn:metalfit:schema:gltf"]);
  if (path.basename(file) === "metalfit_export.json") return [[file, json, "urn:metalfit:schema:export"]];
  // physicallybased.info's shape has no `schema` member: known by its header and data.
  if (json?.header?.schemaVersion !== undefined && Array.isArray(json?.data))
    return [[file, json, "urn:metalfit:schema:physicallybased"]];
  const m = /^metalfit\.([a-z-]+)\/1$/.exec(json?.schema ?? "");
  return [[file, json, m ? `urn:metalfit:schema:${m[1]}` : null]];
}

function check(document, id) {
  const validate = id && ajv.getSchema(id);
  if (!validate) return [`no schema for ${JSON.stringify(document?.schema)}`];
  if (validate(document)) return [];
  return validate.errors.slice(0, 5).map((e) => `${e.instancePath || "/"} ${e.message} ${JSON.stringify(e.params)}`);
}

// JSON pointers of the numbers in a document, in document order.
function numberPaths(value, at = [], out = []) {
  if (typeof value === "number") out.push(at);
  else if (Array.isArray(value)) value.forEach((v, i) => numberPaths(v, [...at, i], out));
  else if (value && typeof value === "object") for (const [k, v] of Object.entries(value)) numberPaths(v, [...at, k], out);
  return out;
}
// JSON pointers of the strings naming input files (docs/fit-record.md, Paths in records), in document order.
const pathMembers = new Set(["file", "ocio_config", "cost_table"]);
function filePaths(value, at = [], out = []) {
  if (Array.isArray(value)) value.forEach((v, i) => filePaths(v, [...at, i], out));
  else if (value && typeof value === "object")
    for (const [k, v] of Object.entries(value)) {
      if (pathMembers.has(k) && typeof v === "string") out.push([...at, k]);
      else filePaths(v, [...at, k], out);
    }
  return out;
}
function setAt(document, at, value) {
  let o = document;
  for (const k of at.slice(0, -1)) o = o[k];
  o[at[at.length - 1]] = value;
}

// The broken copies of one valid record: [what was broken, the copy].
function brokenCopies(document, id) {
  const copies = [];
  const copy = () => structuredClone(document);
  if ("schema" in document) {
    const c = copy();
    c.schema = document.schema.replace(/\/1$/, "/2");
    copies.push(["schema member changed", c]);
  }
  const required = ajv.getSchema(id).schema.required ?? ajv.getSchema("urn:metalfit:schema:fit").schema.required;
  for (const key of required) {
    const c = copy();
    delete c[key];
    copies.push([`required member '${key}' removed`, c]);
  }
  const extra = copy();
  extra.unexpected_member = 1;
  copies.push(["unknown top-level member added", extra]);
  const numbers = numberPaths(document);
  const picks = new Set();
  for (let i = 0; i < Math.min(40, numbers.length); ++i) picks.add(Math.floor((i * numbers.length) / Math.min(40, numbers.length)));
  for (const i of picks) {
    const c = copy();
    setAt(c, numbers[i], "0.5");
    copies.push([`number at /${numbers[i].join("/")} replaced by a string`, c]);
  }
  for (const at of filePaths(document).slice(0, 10)) {
    const c = copy();
    setAt(c, at, "/home/someone/data/nk/Au/Johnson.yml");
    copies.push([`file at /${at.join("/")} replaced by an absolute path`, c]);
  }
  return copies;
}

let records = 0, failed = 0, refused = 0;
for (const file of files) {
  let json;
  try {
    json = JSON.parse(await readFile(file, "utf8"));
  } catch (e) {
    console.log(`${file}: not JSON: ${e.message}`);
    failed++;
    continue;
  }
  const list = recordsOf(file, json);
  if (list.length === 0) {
    console.log(`${file}: no record found`);
    failed++;
  }
  for (const [label, document, id] of list) {
    records++;
    const errors = check(document, id);
    if (errors.length > 0) {
      console.log(`${label}: INVALID against ${id}`);
      for (const e of errors) console.log(`  ${e}`);
      failed++;
      continue;
    }
    if (!broken) {
      console.log(`${label}: valid (${id})`);
      continue;
    }
    const copies = brokenCopies(document, id);
    const accepted = copies.filter(([, c]) => check(c, id).length === 0);
    refused += copies.length - accepted.length;
    console.log(`${label}: ${copies.length - accepted.length} of ${copies.length} broken copies refused (${id})`);
    for (const [what] of accepted) console.log(`  ACCEPTED although broken: ${what}`);
    if (accepted.length > 0) failed++;
  }
}
console.log(broken ? `${records - failed} of ${records} records: every broken copy refused (${refused} refusals)`
                   : `${records - failed} of ${records} records valid`);
process.exit(failed === 0 ? 0 : 1);
