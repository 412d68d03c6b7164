// The report in a real browser (docs/report.md): Debian's chromium, headless, driven by playwright-core, opens the
// pages of a report folder from file:// with a new empty profile and no network. Every page must load with no
// console error, no page error and no request other than file://; every chart container must hold an SVG with marks;
// the heat map must have one cell per material × model; the render (or the "renders skipped" line) must be there;
// the interactive sphere (viewer.js) is driven and its canvas read back at known μ (checkViewer).
// A screenshot of each page type goes into the output folder.
//
// Reports of a filmed material given after CHROMIUM: its page shows, beside its stack, what each renderer's thin film
// draws (report.json's renderer_film), or why it is not scored (checkFilmedPages).
//
// Usage: node tests/report_browser.mjs REPORT_DIR SCREENSHOT_DIR [CHROMIUM [FILMED_REPORT_DIR…]]
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [reportDir, shotDir, executable = '/usr/bin/chromium', ...filmedDirs] = process.argv.slice(2);
if (!reportDir || !shotDir) {
  console.error('usage: node tests/report_browser.mjs REPORT_DIR SCREENSHOT_DIR [CHROMIUM]');
  process.exit(2);
}
fs.mkdirSync(shotDir, { recursive: true });
const report = JSON.parse(fs.readFileSync(path.join(reportDir, 'report.json'), 'utf8'));
const failures = [];
let checks = 0;
const check = (ok, what) => { checks += 1; if (!ok) failures.push(what); };

// report-data.js is report.json's bytes, wrapped: one source of numbers.
const data = fs.readFileSync(path.join(reportDir, 'assets', 'report-data.js'), 'utf8');
const json = fs.readFileSync(path.join(reportDir, 'report.json'), 'utf8');
check(data === 'metalfitReport(' + json + ');\n', 'assets/report-data.js is not report.json wrapped in metalfitReport(...)');

const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'metalfit-chromium-'));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: executable,
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
         '--disable-sync', '--no-first-run'],
  viewport: { width: 1400, height: 1000 },
  offline: true,
});

async function openPage(relative, label, dir = reportDir) {
  const page = await context.newPage();
  const errors = [];
  const network = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('request', (r) => { if (!r.url().startsWith('file://')) network.push(r.url()); });
  await page.route((url) => url.protocol !== 'file:', (route) => route.abort());
  const url = pathToFileURL(path.join(dir, relative)).href;
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => document.body.dataset.rendered !== undefined, null, { timeout: 60000 });
  check(await page.evaluate(() => document.body.dataset.rendered) === 'true', `${label}: the page script did not finish`);
  check(errors.length === 0, `${label}: console errors: ${errors.join(' | ')}`);
  check(network.length === 0, `${label}: network requests: ${network.join(' ')}`);
  const charts = await page.evaluate(() => [...document.querySelectorAll('.chart')].map((c) => ({
    id: c.id,
    svg: c.querySelectorAll('svg').length,
    marks: c.querySelectorAll('svg g.role-mark > *').length,
  })));
  check(charts.length > 0, `${label}: no chart container`);
  for (const c of charts) check(c.svg > 0 && c.marks > 0, `${label}: chart ${c.id} has ${c.svg} SVG, ${c.marks} marks`);
  return { page, charts };
}

// The catalog page.
{
  const { page, charts } = await openPage('index.html', 'index.html');
  const ids = charts.map((c) => c.id);
  for (const id of ['heatmap', 'swatches']) check(ids.includes(id), `index.html: no ${id} chart`);
  // A cell per material and model, plus the outline of each material's recommended model.
  const recommended = report.materials.filter((m) => m.recommendation && m.recommendation.chosen != null).length;
  const heatmapCells = () => page.evaluate(() => document.querySelectorAll('#heatmap svg g.mark-rect.role-mark > path').length);
  const cells = await heatmapCells();
  check(cells === report.materials.length * report.models.length + recommended,
        `index.html: heat map has ${cells} rects, expected ${report.materials.length} × ${report.models.length} + ${recommended} outlines`);
  // The metric menu redraws it for each metric, with the metric in its title.
  for (const metric of ['f0_err', 'de2000_max', 'max_rel', 'rel_rms']) {
    await page.selectOption('#heatmap-metric', metric);
    await page.waitForFunction(() => document.querySelectorAll('#heatmap svg').length > 0);
    const title = await page.evaluate(() => document.querySelector('#heatmap svg').textContent);
    const expected = { f0_err: '|F0 error|', de2000_max: 'ΔE2000 max', max_rel: 'max_rel', rel_rms: 'rel_rms' }[metric];
    check(title.includes(expected), `index.html: heat map for ${metric} is not titled ${expected}`);
    check(await heatmapCells() === cells, `index.html: heat map for ${metric} has another number of cells`);
  }
  const rows = await page.evaluate(() => document.querySelectorAll('#catalog-table tbody tr').length);
  check(rows === report.materials.length, `index.html: table has ${rows} rows`);
  // Sorting by a model column puts its values in ascending order.
  await page.click('#catalog-table thead th[data-column="4"]');
  const sorted = await page.evaluate(() => [...document.querySelectorAll('#catalog-table tbody tr')].map((tr) => Number(tr.children[4].dataset.sort)));
  check(sorted.every((v, i) => i === 0 || sorted[i - 1] <= v), 'index.html: sorting the first model column does not sort it');
  const links = await page.evaluate(() => [...document.querySelectorAll('#catalog-table tbody a')].map((a) => a.getAttribute('href')));
  for (const m of report.materials) check(links.includes(m.page), `index.html: no link to ${m.page}`);
  await page.screenshot({ path: path.join(shotDir, 'index.png'), fullPage: true });
  await page.close();
}

// The viewer (assets/viewer.js) read back: its canvas's pixels at known μ. The sphere is ray-traced under an
// orthographic view, so the pixel (x, y) (from the bottom left, as readPixels counts) sees μ = sqrt(1 − |p|²) with
// p = ((2(x + ½)/W − 1)/ρ, (2(y + ½)/H − 1)/ρ), ρ the sphere's radius in clip space (the canvas's data-radius).
const srgb = (v) => { v = Math.min(1, Math.max(0, v)); return v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055; };
const code = (v) => 255 * srgb(v);  // the 8-bit code of a linear value, unrounded
// report.json's LUT (R_c at μ = i/(n − 1)), linearly interpolated in μ.
const lutAt = (lut, mu) => lut.map((row) => {
  const x = Math.min(1, Math.max(0, mu)) * (row.length - 1), i = Math.min(Math.floor(x), row.length - 2), t = x - i;
  return row[i] + (row[i + 1] - row[i]) * t;
});
// A curve of report.json (three rows at curves.theta_deg, 0…90 by 1°, so at μ = cos θ), interpolated by
// the cubic through the 4 samples around θ (or around μ): another sampling of R_c than the LUT's, and the only one
// of the models. Where the cubics in θ and in μ disagree, the 1° samples do not resolve the curve (lazanyi-comp with
// a small α: μ(1 − μ)^α is steep at μ = 1) and a pixel there is not compared with them.
const cubic = (xs, rows, x) => {
  let i = 0;
  const up = xs[1] > xs[0];
  while (i < xs.length - 2 && (up ? xs[i + 1] < x : xs[i + 1] > x)) ++i;
  const j0 = Math.max(0, Math.min(i - 1, xs.length - 4));
  const js = [j0, j0 + 1, j0 + 2, j0 + 3];
  const w = js.map((j) => js.reduce((prod, k) => (k === j ? prod : prod * (x - xs[k]) / (xs[j] - xs[k])), 1));
  return rows.map((row) => js.reduce((sum, j, n) => sum + w[n] * row[j], 0));
};
let curveAt = null;  // (rows, θ) for the material page under test: set by checkViewer
const resolvedAt = (theta, mus) => (rows, p) => {
  const a = cubic(theta, rows, p.theta), b = cubic(mus, rows, p.mu);
  return [0, 1, 2].every((c) => 255 * Math.abs(a[c] - b[c]) <= 0.01);
};
async function readViewer(page) {
  const shot = await page.evaluate(() => {
    const c = document.getElementById('viewer-canvas');
    const gl = c.getContext('webgl2');
    const px = new Uint8Array(c.width * c.height * 4);
    gl.readPixels(0, 0, c.width, c.height, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let text = '';
    for (let i = 0; i < px.length; i += 8192) text += String.fromCharCode(...px.subarray(i, i + 8192));
    return { w: c.width, h: c.height, radius: Number(c.dataset.radius), px: btoa(text) };
  });
  shot.px = Buffer.from(shot.px, 'base64');
  return shot;
}
// The sphere's pixels every 4th row and column up to θ = 80° (and the pixel nearest the centre), each with its μ, θ.
function spherePixels(shot) {
  const out = [];
  const at = (x, y) => {
    const px = (2 * (x + 0.5) / shot.w - 1) / shot.radius, py = (2 * (y + 0.5) / shot.h - 1) / shot.radius;
    const rr = px * px + py * py;
    if (rr >= 1) return null;
    const mu = Math.sqrt(1 - rr);
    const i = 4 * (y * shot.w + x);
    return { x, y, mu, theta: Math.acos(mu) * 180 / Math.PI, rgb: [shot.px[i], shot.px[i + 1], shot.px[i + 2]] };
  };
  for (let y = 0; y < shot.h; y += 4) for (let x = 0; x < shot.w; x += 4) {
    const p = at(x, y);
    if (p && p.theta <= 80) out.push(p);
  }
  return { all: out, centre: at(Math.floor(shot.w / 2), Math.floor(shot.h / 2)) };
}
// The largest |pixel − expected code| over the pixels (expected: linear RGB → codes).
const worst = (pixels, expected) => Math.max(...pixels.map((p) => {
  const e = expected(p);
  return Math.max(...p.rgb.map((v, c) => Math.abs(v - e[c])));
}));
let visibleModelError = false;

async function checkViewer(page, m) {
  const label = `${m.page} viewer`;
  curveAt = (rows, thetaDeg) => cubic(m.curves.theta_deg, rows, thetaDeg);
  const resolved = resolvedAt(m.curves.theta_deg, m.curves.theta_deg.map((t) => Math.cos(t * Math.PI / 180)));
  const started = Date.now();
  const state = () => page.evaluate(() => ({ shading: document.getElementById('viewer-canvas').dataset.shading,
                                              view: document.getElementById('viewer-canvas').dataset.view }));
  check(await page.evaluate(() => !!document.getElementById('viewer-canvas').getContext('webgl2')), `${label}: no WebGL2 context`);
  // The white furnace: each pixel shows R_c(μ) itself, through the sRGB transfer function.
  await page.selectOption('#viewer-environment', 'white');
  await page.selectOption('#viewer-view', 'image');
  await page.selectOption('#viewer-model', 'reference');
  const ref = spherePixels(await readViewer(page));
  check(ref.all.length > 1000, `${label}: ${ref.all.length} sphere pixels read`);
  const refLut = worst(ref.all, (p) => lutAt(m.lut, p.mu).map(code));
  check(refLut <= 1, `${label}: reference pixels differ from the LUT's colour at their μ by up to ${refLut.toFixed(2)}/255`);
  const refCurve = worst(ref.all, (p) => curveAt(m.curves.exact, p.theta).map(code));
  check(refCurve <= 1, `${label}: reference pixels differ from curves.exact at their θ by up to ${refCurve.toFixed(2)}/255`);
  check(ref.centre.mu === 1, `${label}: the middle pixel sees μ = ${ref.centre.mu}, not 1`);
  const refF0 = worst([ref.centre], () => m.F0.map(code));
  check(refF0 <= 1, `${label}: the centre pixel ${ref.centre.rgb} is not F0 ${m.F0} (${refF0.toFixed(2)}/255 off)`);
  // Each model: its own curve at every pixel, F0 at the centre; |model − reference| × 10 in the difference view.
  for (const model of report.models) {
    const curve = mat => mat.models[model.id].curve;
    await page.selectOption('#viewer-view', 'image');
    await page.selectOption('#viewer-model', model.id);
    const s = await state();
    check(s.shading === model.id && s.view === 'image', `${label}: selecting ${model.id} shows ${s.shading} ${s.view}`);
    const shaded = spherePixels(await readViewer(page));
    const where = (p) => resolved(curve(m), p) && resolved(m.curves.exact, p);
    const compared = shaded.all.filter(where);
    check(compared.length >= 0.8 * shaded.all.length, `${label}: ${model.id}'s curve resolves only ${compared.length} of ${shaded.all.length} pixels`);
    const e = worst(compared, (p) => curveAt(curve(m), p.theta).map(code));
    check(e <= 1, `${label}: ${model.id} pixels differ from its curve at their θ by up to ${e.toFixed(2)}/255`);
    const f0 = curve(m).map((row) => row[0]);
    const centre = worst([shaded.centre], () => f0.map(code));
    check(centre <= 1, `${label}: ${model.id}'s centre pixel ${shaded.centre.rgb} is not its F0 ${f0} (${centre.toFixed(2)}/255 off)`);
    // Where the model's error shows (≥ 3 codes), the pixels read back differ from the reference's by as much.
    const apart = shaded.all.map((p, i) => ({ p, r: ref.all[i], d: !where(p) ? 0 : Math.max(...[0, 1, 2].map((c) =>
      Math.abs(code(curveAt(curve(m), p.theta)[c]) - code(curveAt(m.curves.exact, p.theta)[c])))) })).filter((x) => x.d >= 3);
    if (apart.length) visibleModelError = true;
    for (const { p, r, d } of apart.slice(0, 50)) {
      const measured = Math.max(...[0, 1, 2].map((c) => Math.abs(p.rgb[c] - r.rgb[c])));
      check(Math.abs(measured - d) <= 2, `${label}: ${model.id} at θ ${p.theta.toFixed(1)}° differs from the reference by ${measured}/255, its error implies ${d.toFixed(1)}`);
    }
    await page.selectOption('#viewer-view', 'difference');
    await page.selectOption('#viewer-scale', '10');
    const diff = spherePixels(await readViewer(page));
    const d = worst(diff.all.filter(where), (p) => {
      const mo = curveAt(curve(m), p.theta), ex = lutAt(m.lut, p.mu);
      return [0, 1, 2].map((c) => 255 * Math.min(1, 10 * Math.abs(mo[c] - ex[c])));
    });
    check(d <= 1, `${label}: ${model.id}'s difference view is off |model − reference| × 10 by up to ${d.toFixed(2)}/255`);
    check(await page.evaluate(() => document.getElementById('viewer-legend').textContent.includes('× 10')), `${label}: no legend of the scale`);
  }
  // The sky and the light: the light straight behind the viewer is reflected at the centre (R_c × its radiance 8,
  // clipped); turned away, the centre reflects the sky's horizon (0.95, 0.92, 0.85).
  await page.selectOption('#viewer-view', 'image');
  await page.selectOption('#viewer-model', 'reference');
  await page.selectOption('#viewer-environment', 'sky');
  const setLight = async (azimuth, elevation) => page.evaluate(([a, e]) => {
    for (const [id, v] of [['viewer-azimuth', a], ['viewer-elevation', e]]) {
      const input = document.getElementById(id);
      input.value = String(v);
      input.dispatchEvent(new Event('input'));
    }
  }, [azimuth, elevation]);
  await setLight(0, 0);
  const lit = spherePixels(await readViewer(page)).centre;
  const litError = worst([lit], () => m.F0.map((v) => code(8 * v)));
  check(litError <= 1, `${label}: the light at the centre gives ${lit.rgb}, not F0 × 8 (${litError.toFixed(2)}/255 off)`);
  await setLight(180, 0);
  const unlit = spherePixels(await readViewer(page)).centre;
  const horizon = [0.95, 0.92, 0.85];
  const unlitError = worst([unlit], () => m.F0.map((v, c) => code(v * horizon[c])));
  check(unlitError <= 1, `${label}: the centre under the horizon gives ${unlit.rgb}, not F0 × the horizon (${unlitError.toFixed(2)}/255 off)`);
  // Dragging on the sphere moves the light's reflection there.
  await page.locator('#viewer-canvas').scrollIntoViewIfNeeded();
  const box = await page.evaluate(() => { const b = document.getElementById('viewer-canvas').getBoundingClientRect(); return { x: b.left, y: b.top, w: b.width, h: b.height }; });
  const target = { x: Math.round(box.w * 0.3), y: Math.round(box.h * 0.35) };
  await page.mouse.move(box.x + target.x + 0.5, box.y + target.y + 0.5);
  await page.mouse.down();
  await page.mouse.up();
  const shot = await readViewer(page);
  const hit = spherePixels(shot).all.reduce((best, p) => {
    const d = Math.hypot(p.x - target.x, p.y - (shot.h - 1 - target.y));
    return best == null || d < best.d ? { p, d } : best;
  }, null).p;
  const hitError = worst([hit], (p) => lutAt(m.lut, p.mu).map((v) => code(8 * v)));
  check(hitError <= 1, `${label}: after a drag to (${target.x}, ${target.y}) the pixel there is ${hit.rgb}, not R_c × 8 (${hitError.toFixed(2)}/255 off)`);
  await page.locator('#viewer-canvas').screenshot({ path: path.join(shotDir, `viewer-${m.id}.png`) });
  console.log(`${label}: ${((Date.now() - started) / 1000).toFixed(1)} s`);
}

// Every material page.
for (const m of report.materials) {
  const { page, charts } = await openPage(m.page, m.page);
  const ids = charts.map((c) => c.id);
  for (const id of ['nk', 'spectral', 'reflectance', 'rel_error', 'de2000', 'stripes']) check(ids.includes(id), `${m.page}: no ${id} chart`);
  // The first screen: the recommended model (or that none meets the tolerance), before the provenance.
  const first = await page.evaluate(() => document.querySelector('main section h2').textContent);
  check(first === 'Recommended model', `${m.page}: the first section is "${first}", not the recommendation`);
  if (m.recommendation.chosen != null) {
    const pre = await page.evaluate(() => document.querySelector('pre.constants').textContent);
    check(pre === m.recommendation.constants, `${m.page}: the constants shown are not report.json's`);
  }
  // Every fit on a bound of its model (fit.at_bound) is marked in the model table.
  const bound = Object.values(m.models).filter((x) => x.fit.at_bound).length;
  const marks = await page.evaluate(() => document.querySelectorAll('#models-table tbody tr.fit .at-bound').length);
  check(marks === bound, `${m.page}: ${marks} fits marked on a bound, report.json has ${bound}`);
  const modelRows = await page.evaluate(() => document.querySelectorAll('#models-table tbody tr.fit').length);
  check(modelRows === report.models.length, `${m.page}: ${modelRows} fitted rows in the model table`);
  // What each consumer renders: one row per model; the glTF viewer's cell is Schlick's, and marked where it is not
  // the fit's own figures.
  const consumers = await page.evaluate(() => [...document.querySelectorAll('#consumers-table tbody tr')].map((tr) =>
    [...tr.children].map((td) => ({ text: td.textContent, title: td.title, differs: td.classList.contains('consumer-differs') }))));
  check(consumers.length === report.models.length, `${m.page}: ${consumers.length} rows in the consumers table`);
  for (const row of consumers) {
    const id = row[0].text, gltf = Object.keys(m.models[id].consumers).indexOf('gltf');
    if (gltf < 0) continue;
    const cellOf = row[2 + gltf];
    check(/Schlick from baseColorFactor/.test(cellOf.title), `${m.page}: ${id}'s glTF cell is not Schlick's (${cellOf.title})`);
    const expected = (100 * m.models[id].consumers.gltf.worst_rel_rms).toFixed(2) + ' %';
    check(cellOf.text.startsWith(expected), `${m.page}: ${id}'s glTF cell "${cellOf.text}" does not start with ${expected}`);
    check(cellOf.differs === (cellOf.text.split(' (')[0] !== row[1].text), `${m.page}: ${id}'s glTF cell marked wrongly`);
  }
  if (report.renders.skipped === undefined && m.render_row != null) {
    const loaded = await page.evaluate(() => { const img = document.getElementById('render'); return img && img.complete && img.naturalWidth > 0; });
    check(loaded, `${m.page}: the render did not load`);
    // One render per shown model (reference | model | its signed error in false colour), each model named once, in the report's order.
    const shown = await page.evaluate(() => [...document.querySelectorAll('figure.render-model')].map((f) => f.dataset.model));
    check(JSON.stringify(shown) === JSON.stringify(report.renders.models), `${m.page}: renders of ${shown.join(',')}, models ${report.renders.models.join(',')}`);
    check(JSON.stringify(shown) === JSON.stringify(report.models.map((x) => x.id)), `${m.page}: the renders are not the report's models`);
    const cells = await page.evaluate(() => document.querySelectorAll('figure.render-model img.render-cell').length);
    check(cells === 3 * report.renders.models.length, `${m.page}: ${cells} render cells, not 3 per model`);
  } else {
    const text = await page.evaluate(() => document.body.innerText);
    check(/renders skipped: /.test(text), `${m.page}: neither a render nor "renders skipped: <reason>"`);
  }
  await checkViewer(page, m);
  await page.screenshot({ path: path.join(shotDir, `material-${m.id}.png`), fullPage: true });
  await page.close();
}

// A filmed material's page: beside its stack, the table of what each renderer's thin film draws, one row per renderer
// after the exact stack's with report.json's figures (ΔE2000 mean and max to 2 decimals, in its order); under a coat
// the reason in its place and no table.
for (const dir of filmedDirs) {
  const filmed = JSON.parse(fs.readFileSync(path.join(dir, 'report.json'), 'utf8'));
  for (const m of filmed.materials) {
    const label = `${path.basename(dir)}/${m.page}`;
    const r = m.renderer_film;
    check(r !== undefined, `${label}: report.json has no renderer_film for a filmed material`);
    if (r === undefined) continue;
    const { page } = await openPage(m.page, label, dir);
    const shown = await page.evaluate(() => ({
      rows: [...document.querySelectorAll('#renderer-film-table tbody tr')].map((tr) => [...tr.children].map((td) => td.textContent)),
      reason: document.querySelector('.renderer-film-not-scored')?.textContent ?? null,
      headings: [...document.querySelectorAll('main section h2')].map((h) => h.textContent),
    }));
    const at = shown.headings.indexOf('What renderers draw for this film');
    check(at > shown.headings.indexOf('Provenance'), `${label}: no renderers' section after the provenance (the stack): ${shown.headings.join(' | ')}`);
    if (r.not_scored) {
      check(shown.reason === r.not_scored && shown.rows.length === 0, `${label}: not "${r.not_scored}" alone but ${JSON.stringify(shown)}`);
    } else {
      const scores = r.rows[0].scores;
      check(shown.rows.length === scores.length + 1 && shown.rows[0][0] === 'exact stack', `${label}: ${shown.rows.length} rows, not the stack's and ${scores.length} renderers'`);
      scores.forEach((s, i) => {
        const row = shown.rows[i + 1] || [];
        const expected = [s.renderer, s.metrics.de2000_mean.toFixed(2), s.metrics.de2000_max.toFixed(2)];
        const got = [row[0], row[4], row[5]];
        check(JSON.stringify(got) === JSON.stringify(expected), `${label}: row ${i + 1} shows ${got}, report.json ${expected}`);
      });
    }
    await page.screenshot({ path: path.join(shotDir, `filmed-${path.basename(dir)}-${m.id}.png`), fullPage: true });
    await page.close();
  }
}

// The model checks are not vacuous: some model's error shows in the viewer.
check(visibleModelError, 'viewer: no model differs visibly (3/255) from the reference: the model checks test nothing');

await context.close();
fs.rmSync(profile, { recursive: true, force: true });
for (const f of failures) console.error('FAIL: ' + f);
console.log(`report in chromium: ${checks - failures.length} passed, ${failures.length} failed`);
process.exit(failures.length ? 1 : 0);
