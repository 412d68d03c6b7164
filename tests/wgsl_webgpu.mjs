// ctest export.wgsl_webgpu: the WGSL export of the whole catalog compiled and run by WebGPU in Debian's chromium
// (headless, driven by playwright-core, WebGPU on SwiftShader's Vulkan, so Tint, chromium's WGSL compiler, validates
// it): one compute shader holds wgsl/metalfit_models.wgsl and every material file, unchanged, and writes each material
// function's F(mu) at 35 values of mu (0 to 1 by 1/32, and -0.25 and 1.25, which the models clamp). Each result must
// equal libfit's own evaluation of the model in double (model_values, at the constants the file writes) within
// 1e-5 + 1e-5 |F| per channel (float arithmetic of the same formulas; export_gpu_tests' tolerance for the GLSL):
// lazanyi-comp's gold fit, k at its bound 1e4, loses 7.5e-6 to float. Any compilation error fails.
// Usage: node wgsl_webgpu.mjs NODE_MODULES CHROMIUM MODEL_VALUES EXPORT_DIR
import { createRequire } from "node:module";
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

const [modules, executable, modelValues, exportDir] = process.argv.slice(2);
if (!exportDir) {
  console.error("usage: node wgsl_webgpu.mjs NODE_MODULES CHROMIUM MODEL_VALUES EXPORT_DIR");
  process.exit(2);
}
const require = createRequire(path.join(path.resolve(modules), "noop.js"));
const { chromium } = require("playwright-core");

const wgslDir = path.join(exportDir, "wgsl");
const modelsFile = fs.readFileSync(path.join(wgslDir, "metalfit_models.wgsl"), "utf8");
const materials = [];  // {file, stem, fn, values: [numbers, channel by channel per parameter]}
for (const name of fs.readdirSync(wgslDir).sort()) {
  if (name === "metalfit_models.wgsl" || !name.endsWith(".wgsl")) continue;
  const text = fs.readFileSync(path.join(wgslDir, name), "utf8");
  const constants = new Map();
  for (const m of text.matchAll(/^const (\w+) = vec3f\(([^)]*)\);$/gm))
    constants.set(m[1], m[2].split(",").map(Number));
  const call = text.match(/^fn (\w+)\(mu: f32\) -> vec3f \{\n {4}return (\w+)\(([^)]*)\);\n\}$/m);
  if (!call) throw new Error(`${name}: no material function`);
  const args = call[3].split(",").map((s) => s.trim());
  if (args.pop() !== "mu" || args.some((a) => !constants.has(a))) throw new Error(`${name}: unexpected call ${call[0]}`);
  materials.push({ file: name, text, stem: call[1], fn: call[2], values: args.flatMap((a) => constants.get(a)) });
}
if (materials.length === 0) throw new Error(`no material files in ${wgslDir}`);
const mus = [...Array.from({ length: 33 }, (_, i) => i / 32), -0.25, 1.25];

const calls = materials.map((m, j) =>
  `    v = ${m.stem}(mu);\n    out[(${j}u * ${mus.length}u + i) * 3u] = v.x;\n` +
  `    out[(${j}u * ${mus.length}u + i) * 3u + 1u] = v.y;\n    out[(${j}u * ${mus.length}u + i) * 3u + 2u] = v.z;\n`);
const shader = [modelsFile, ...materials.map((m) => m.text),
  "@group(0) @binding(0) var<storage, read> mus: array<f32>;",
  "@group(0) @binding(1) var<storage, read_write> out: array<f32>;",
  "@compute @workgroup_size(1) fn metalfit_test_main(@builtin(global_invocation_id) id: vec3u) {",
  "    let i = id.x;\n    let mu = mus[i];\n    var v: vec3f;", ...calls, "}"].join("\n");

const profile = fs.mkdtempSync(path.join(os.tmpdir(), "metalfit-chromium-"));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: executable, headless: true, offline: true,
  args: ["--headless", "--no-sandbox", "--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader",
         "--enable-features=Vulkan", "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--no-first-run"],
});
let result;
try {
  const page = await context.newPage();
  // WebGPU needs a secure context: a page of http://localhost, served by playwright's routing (nothing is fetched).
  await context.route("**/*", (route) => route.fulfill({ contentType: "text/html", body: "<!doctype html>" }));
  await page.goto("http://localhost/index.html");
  result = await page.evaluate(async ({ code, mus, count }) => {
    if (!navigator.gpu) return { error: "no WebGPU (navigator.gpu) in this chromium" };
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) return { error: "no WebGPU adapter" };
    const device = await adapter.requestDevice();
    const module = device.createShaderModule({ code });
    const info = await module.getCompilationInfo();
    const messages = info.messages.map((m) => `${m.type} ${m.lineNum}:${m.linePos} ${m.message}`);
    if (info.messages.some((m) => m.type === "error")) return { messages };
    device.pushErrorScope("validation");
    const pipeline = device.createComputePipeline({ layout: "auto", compute: { module, entryPoint: "metalfit_test_main" } });
    const size = count * mus.length * 3 * 4;
    const input = device.createBuffer({ size: mus.length * 4, usage: GPUBufferUsage.STORAGE, mappedAtCreation: true });
    new Float32Array(input.getMappedRange()).set(mus);
    input.unmap();
    const output = device.createBuffer({ size, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
    const readback = device.createBuffer({ size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    const bind = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [
      { binding: 0, resource: { buffer: input } }, { binding: 1, resource: { buffer: output } }] });
    const encoder = device.createCommandEncoder();
    const pass = encoder.beginComputePass();
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, bind);
    pass.dispatchWorkgroups(mus.length);
    pass.end();
    encoder.copyBufferToBuffer(output, 0, readback, 0, size);
    device.queue.submit([encoder.finish()]);
    const error = await device.popErrorScope();
    if (error) return { messages, error: error.message };
    await readback.mapAsync(GPUMapMode.READ);
    return { messages, adapter: adapter.info ? [adapter.info.vendor, adapter.info.architecture, adapter.info.description].filter(Boolean).join(" ") : "",
             values: Array.from(new Float32Array(readback.getMappedRange())) };
  }, { code: shader, mus, count: materials.length });
} finally {
  await context.close();
  fs.rmSync(profile, { recursive: true, force: true });
}
if (!result.values) {
  for (const m of result.messages ?? []) console.error(m);
  console.error(`wgsl_webgpu: ${result.error ?? "the WGSL does not compile"}`);
  process.exit(1);
}

// libfit's evaluation at the same (float) mu and the written constants.
const expected = execFileSync(modelValues, mus.map((mu) => String(Math.fround(mu))), {
  input: materials.map((m) => `${m.fn} ${m.values.join(" ")}`).join("\n") + "\n", encoding: "utf8",
}).trim().split("\n").map((line) => line.split(" ").map(Number));
let failures = 0, worstAbs = 0, worstRel = 0;
materials.forEach((m, j) => {
  for (let i = 0; i < mus.length; ++i)
    for (let c = 0; c < 3; ++c) {
      const got = result.values[(j * mus.length + i) * 3 + c], want = expected[j][i * 3 + c];
      const diff = Math.abs(got - want);
      worstAbs = Math.max(worstAbs, diff);
      worstRel = Math.max(worstRel, diff / Math.max(Math.abs(want), 1e-3));
      if (!(diff <= 1e-5 + 1e-5 * Math.abs(want)) && failures++ < 20)
        console.error(`${m.file}: mu ${mus[i]} channel ${"rgb"[c]}: WGSL ${got}, libfit ${want}`);
    }
});
for (const m of result.messages) console.log(`compilation message: ${m}`);
console.log(`wgsl_webgpu: ${materials.length} material functions (${new Set(materials.map((m) => m.fn)).size} models) ` +
            `compiled and run by WebGPU (${result.adapter}) at ${mus.length} mu; largest difference from libfit ` +
            `${worstAbs.toExponential(2)} (relative ${worstRel.toExponential(2)}); ${failures} outside tolerance`);
process.exit(failures === 0 ? 0 : 1);
