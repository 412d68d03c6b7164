// The report in a real browser (docs/report.md): Debian's chromium, headless, driven by playwright-core, opens the
// pages of a report folder from file:// with a new empty profile and no network. Every page must load with no
// console error, no page error and no request other than file://; every chart container must hold an SVG with marks;
// the heat map must have one cell per material × model; the render (or the "renders skipped" line) must be there.
// A screenshot of each page type goes into the output folder.
//
// Usage: node tests/report_browser.mjs REPORT_DIR SCREENSHOT_DIR [CHROMIUM]
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [reportDir, shotDir, executable = '/usr/bin/chromium'] = process.argv.slice(2);
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

async function openPage(relative, label) {
  const page = await context.newPage();
  const errors = [];
  const network = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('request', (r) => { if (!r.url().startsWith('file://')) network.push(r.url()); });
  await page.route((url) => url.protocol !== 'file:', (route) => route.abort());
  const url = pathToFileURL(path.join(reportDir, relative)).href;
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
  await page.screenshot({ path: path.join(shotDir, `material-${m.id}.png`), fullPage: true });
  await page.close();
}

await context.close();
fs.rmSync(profile, { recursive: true, force: true });
for (const f of failures) console.error('FAIL: ' + f);
console.log(`report in chromium: ${checks - failures.length} passed, ${failures.length} failed`);
process.exit(failures.length ? 1 : 0);
