// The MaterialX library itself (MaterialX 1.39.4's WebAssembly build in the npm package @needle-tools/materialx,
// node_modules/) reading every .mtlx an export wrote: each document loads, passes validate() against the standard
// libraries, keeps its provenance doc through a write and read, and every surfacematerial generates GLSL (MaterialX's
// GlslShaderGenerator) whose vertex and pixel stages glslangValidator compiles.
// Usage: node materialx_consumer.mjs NODE_MODULES GLSLANG_VALIDATOR SCRATCH FILE.mtlx...
import { createRequire } from "node:module";
import { execFileSync } from "node:child_process";
import { createHash } from "node:crypto";
import fs from "node:fs";
import path from "node:path";

const [nodeModules, validator, scratch, ...files] = process.argv.slice(2);
const dir = path.join(nodeModules, "@needle-tools", "materialx");
// The emscripten build is CommonJS-minded: it reads its data file with require("fs") relative to __dirname.
globalThis.require = createRequire(import.meta.url);
globalThis.__dirname = path.join(dir, "bin");
const MaterialX = (await import(path.join(dir, "bin", "JsMaterialXGenShader.js"))).default;
const mx = await MaterialX({
  locateFile: (p) => path.join(dir, "bin", p.includes(".data") ? "JsMaterialXGenShader.data.txt" : p),
});
const version = JSON.parse(fs.readFileSync(path.join(dir, "bin", "revision.json"), "utf8")).version;
const generator = mx.GlslShaderGenerator.create();
const context = new mx.GenContext(generator);
const stdlib = mx.loadStandardLibraries(context);

let failed = 0, documents = 0, materials = 0, stages = 0;
// The generated sources by SHA-256 (documents differ in values only): each distinct one is written once and compiled
// after the loop by one glslang process for all of them (a process per source spent most of its time starting glslang).
const sources = new Map();  // hash → the file written
const uses = [];            // [document, stage, hash]
const fail = (file, what) => { failed++; console.log(`FAIL ${file}: ${what}`); };
for (const file of files) {
  const text = fs.readFileSync(file, "utf8");
  const doc = mx.createDocument();
  try {
    await mx.readFromXmlString(doc, text);
  } catch (e) {
    fail(file, `does not load: ${e}`);
    continue;
  }
  doc.setDataLibrary(stdlib);
  if (!doc.validate()) { fail(file, "validate() is false"); continue; }
  const nodes = doc.getMaterialNodes();
  if (nodes.length !== 1) { fail(file, `${nodes.length} surfacematerials, expected 1`); continue; }
  // A write and a read keep the provenance (MaterialX drops comments, keeps doc).
  const again = mx.createDocument();
  await mx.readFromXmlString(again, mx.writeToXmlString(doc));
  const provenance = nodes[0].getAttribute("doc");
  if (!provenance.startsWith("metalfit ") || !provenance.includes("\ndata source: ") ||
      again.getMaterialNodes()[0].getAttribute("doc") !== provenance)
    fail(file, "the surfacematerial's doc does not carry the provenance through a round trip");
  for (const node of nodes) {
    let shader;
    try {
      shader = generator.generate(node.getNamePath(), node, context);
    } catch (e) {
      fail(file, `GLSL generation failed: ${e}`);
      continue;
    }
    materials++;
    for (const [stage, ext] of [["vertex", "vert"], ["pixel", "frag"]]) {
      const source = shader.getSourceCode(stage);
      const hash = createHash("sha256").update(source).digest("hex");
      stages++;
      if (!sources.has(hash)) {
        const out = path.join(scratch, `${hash.slice(0, 16)}.${ext}`);
        fs.writeFileSync(out, source);
        sources.set(hash, out);
      }
      uses.push([file, stage, hash]);
    }
  }
  documents++;
}
// glslangValidator without -l compiles each file on its own (no link between them) and prints each file's name on a
// line of its own before that file's messages: a file's verdict is what follows its name, up to the next name.
const outs = [...sources.values()];
let output = "", status = 0;
if (outs.length > 0) {
  try {
    output = execFileSync(validator, outs, { stdio: "pipe", maxBuffer: 64 << 20 }).toString();
  } catch (e) {
    output = `${e.stdout}`;
    status = e.status ?? 1;
  }
}
const messages = new Map();  // file written → glslang's lines about it
let current = null;
for (const line of output.split("\n")) {
  if (outs.includes(line)) messages.set((current = line), []);
  else if (current !== null && line.trim() !== "") messages.get(current).push(line);
}
const compiled = new Map();  // hash → glslang's verdict ("" when it compiles)
for (const [hash, out] of sources) {
  const lines = messages.get(out);
  if (lines === undefined) compiled.set(hash, `glslang (exit ${status}) did not report on it: ${output.split("\n").slice(0, 6).join(" | ")}`);
  else if (lines.some((l) => l.includes("ERROR"))) compiled.set(hash, lines.slice(0, 6).join(" | "));
  else compiled.set(hash, "");
}
// An exit status that no file's messages explain is a failure too.
if (status !== 0 && [...compiled.values()].every((v) => v === ""))
  fail("glslang", `exit ${status} with no error in any file: ${output.split("\n").slice(0, 6).join(" | ")}`);
for (const [file, stage, hash] of uses)
  if (compiled.get(hash)) fail(file, `generated GLSL ${stage} stage does not compile: ${compiled.get(hash)}`);
console.log(`materialx consumer (MaterialX ${version}): ${documents} of ${files.length} documents loaded and valid, ` +
            `${materials} materials generated as GLSL, ${stages} stages (${sources.size} distinct) compiled by glslang; ` +
            `${failed} failed`);
process.exit(failed || documents !== files.length || documents === 0 ? 1 : 0);
