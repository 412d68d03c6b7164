// ctest export.gltf_threejs (gltf_threejs.sh): three.js's GLTFLoader (npm three, pinned in package.json) loads each
// exported .gltf inside Debian's chromium (headless, driven by playwright-core; the page and three.js are served from
// disk through playwright's request routing, nothing else is reachable) and reports what it made of the material and
// the mesh; each must equal what the file says: a MeshStandardMaterial (no KHR_materials_specular: metalfit writes
// none, docs/export.md#gltf) whose linear colour is baseColorFactor (to float precision), metalness 1, roughness =
// roughnessFactor, userData.metalfit = extras.metalfit, one mesh of 482 vertices and 960 triangles.
// Usage: node gltf_threejs.mjs NODE_MODULES CHROMIUM FILE.gltf…
import { createRequire } from "node:module";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

const [modules, executable, ...files] = process.argv.slice(2);
if (files.length === 0) {
  console.error("usage: node gltf_threejs.mjs NODE_MODULES CHROMIUM FILE.gltf…");
  process.exit(2);
}
const require = createRequire(path.join(path.resolve(modules), "noop.js"));
const { chromium } = require("playwright-core");
const threeVersion = JSON.parse(fs.readFileSync(path.join(modules, "three", "package.json"), "utf8")).version;
const origin = "http://metalfit.invalid";
const served = new Map([
  ["/index.html", ["text/html", `<!doctype html><script type="importmap">{"imports": {"three": "/three/build/three.module.js",
   "three/addons/": "/three/examples/jsm/"}}</script><script type="module">
   import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
   window.load = async (name) => {
     const text = await (await fetch("/assets/" + name)).text();
     const gltf = await new GLTFLoader().parseAsync(text, "/assets/" + name.split("/")[0] + "/");
     const meshes = [];
     gltf.scene.traverse((o) => { if (o.isMesh) meshes.push(o); });
     return meshes.map((m) => ({
       type: m.material.type, color: [m.material.color.r, m.material.color.g, m.material.color.b],
       metalness: m.material.metalness, roughness: m.material.roughness, name: m.material.name,
       specularColor: m.material.specularColor ? [m.material.specularColor.r, m.material.specularColor.g, m.material.specularColor.b] : null,
       userData: m.material.userData, vertices: m.geometry.attributes.position.count,
       triangles: m.geometry.index.count / 3 }));
   };
   window.ready = true;
   </script>`]],
]);
const profile = fs.mkdtempSync(path.join(os.tmpdir(), "metalfit-chromium-"));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: executable, headless: true, offline: true,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
         "--disable-sync", "--no-first-run"],
});
const page = await context.newPage();
const errors = [];
page.on("pageerror", (e) => errors.push(String(e)));
page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
await context.route("**/*", async (route) => {
  const url = new URL(route.request().url());
  if (url.origin !== origin) return route.abort();
  if (served.has(url.pathname)) {
    const [type, body] = served.get(url.pathname);
    return route.fulfill({ contentType: type, body });
  }
  const [, root, ...rest] = url.pathname.split("/");
  const file = root === "three" ? path.join(modules, "three", ...rest)
             : root === "assets" && rest.length === 2 ? files[Number(rest[0])] : null;
  if (!file || !fs.existsSync(file)) return route.fulfill({ status: 404, body: "" });
  return route.fulfill({ contentType: file.endsWith(".js") ? "text/javascript" : "model/gltf+json", body: fs.readFileSync(file) });
});
await page.goto(origin + "/index.html");
await page.waitForFunction(() => window.ready === true, null, { timeout: 60000 });

let failed = 0;
for (const [index, file] of files.entries()) {
  const gltf = JSON.parse(fs.readFileSync(file, "utf8"));
  const material = gltf.materials[0], pbr = material.pbrMetallicRoughness;
  const problems = [];
  let meshes = [];
  try {
    meshes = await page.evaluate((name) => window.load(name), `${index}/${path.basename(file)}`);
  } catch (e) {
    problems.push(`GLTFLoader failed: ${e.message}`);
  }
  if (meshes.length !== 1) problems.push(`${meshes.length} meshes, expected 1`);
  for (const m of meshes) {
    if (m.type !== "MeshStandardMaterial") problems.push(`material type ${m.type}`);
    if (m.specularColor !== null) problems.push(`a specular colour ${m.specularColor} (KHR_materials_specular was not written)`);
    for (let c = 0; c < 3; ++c)
      if (!(Math.abs(m.color[c] - pbr.baseColorFactor[c]) <= 1e-6 * Math.max(1, pbr.baseColorFactor[c])))
        problems.push(`color[${c}] ${m.color[c]} != baseColorFactor ${pbr.baseColorFactor[c]}`);
    if (m.metalness !== pbr.metallicFactor || m.metalness !== 1) problems.push(`metalness ${m.metalness}`);
    if (m.roughness !== pbr.roughnessFactor) problems.push(`roughness ${m.roughness} != ${pbr.roughnessFactor}`);
    if (m.name !== material.name) problems.push(`name ${m.name} != ${material.name}`);
    if (JSON.stringify(m.userData.metalfit) !== JSON.stringify(material.extras.metalfit)) problems.push("userData.metalfit != extras.metalfit");
    if (m.vertices !== 482 || m.triangles !== 960) problems.push(`${m.vertices} vertices, ${m.triangles} triangles`);
  }
  const m = meshes[0];
  console.log(`${file}: ${problems.length === 0 ? "loaded as written" : "MISMATCH"}` +
              (m ? ` (color ${m.color.map((v) => v.toFixed(6)).join(", ")}, roughness ${m.roughness})` : ""));
  for (const p of problems) console.log(`  ${p}`);
  if (problems.length > 0) failed++;
}
if (errors.length > 0) {
  console.log(`page errors: ${errors.join(" | ")}`);
  failed++;
}
await context.close();
fs.rmSync(profile, { recursive: true, force: true });
console.log(`${files.length - failed} of ${files.length} assets loaded by three.js r${threeVersion.split(".")[1]} GLTFLoader as written`);
process.exit(failed === 0 ? 0 : 1);
