// metalfit report: builds each page from report.json (loaded through report-data.js, which calls metalfitReport
// with it) — the tables from its numbers, the charts by embedding its Vega-Lite specs with datasets made from its
// numbers. No number is written into the pages themselves; nothing is fetched.
(function () {
  'use strict';

  const CHANNELS = ['red', 'green', 'blue'];
  const pct = (v, digits = 3) => (v == null || Number.isNaN(v) ? '—' : (100 * v).toFixed(digits) + ' %');
  // A cost as the table gives it, to 3 significant digits (measured ratios carry more digits than their noise).
  const costText = (v) => (v == null ? '—' : String(Number(Number(v).toPrecision(3))));
  const num = (v, digits = 4) => (v == null || Number.isNaN(v) ? '—' : Number(v).toFixed(digits));
  const rgbText = (v, f = num) => (v == null ? '—' : v.map((x) => f(x)).join(' / '));

  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (v == null) continue;
      if (k === 'text') e.textContent = v;
      else if (k === 'style') e.style.cssText = v;
      else e.setAttribute(k, v);
    }
    for (const c of children) if (c != null) e.append(c);
    return e;
  }

  // A table whose header cells sort it (numbers by their data-sort value, text otherwise; click again to reverse).
  function sortableTable(id, headers, rows) {
    const thead = el('thead', {}, el('tr', {}, ...headers.map((h, i) => el('th', { 'data-column': i, title: 'sort' }, h))));
    const tbody = el('tbody', {}, ...rows);
    const table = el('table', { id, class: 'sortable' }, thead, tbody);
    thead.addEventListener('click', (event) => {
      const th = event.target.closest('th');
      if (!th) return;
      const column = Number(th.dataset.column);
      const descending = th.dataset.order === 'ascending';
      thead.querySelectorAll('th').forEach((h) => delete h.dataset.order);
      th.dataset.order = descending ? 'descending' : 'ascending';
      const key = (tr) => {
        const cell = tr.children[column];
        const v = cell.dataset.sort;
        return v === undefined ? cell.textContent : v === '' ? Infinity : Number(v);
      };
      const sorted = [...tbody.children].sort((a, b) => {
        const x = key(a), y = key(b);
        const order = typeof x === 'number' && typeof y === 'number' ? x - y : String(x).localeCompare(String(y));
        return descending ? -order : order;
      });
      tbody.append(...sorted);
    });
    return table;
  }

  const cell = (content, sortValue) => el('td', sortValue === undefined ? {} : { 'data-sort': sortValue == null ? '' : sortValue }, content);

  // Embeds a Vega-Lite spec of report.json with the given datasets into a new chart container.
  function chart(id, spec, datasets, into) {
    const container = el('div', { id, class: 'chart' });
    into.append(container);
    const s = JSON.parse(JSON.stringify(spec));
    s.datasets = datasets;
    return vegaEmbed(container, s, { mode: 'vega-lite', renderer: 'svg', actions: false });
  }

  function section(title, ...children) {
    return el('section', {}, el('h2', { text: title }), ...children);
  }

  function provenanceLine(report) {
    const p = report.provenance;
    return `${p.color_space}, ${p.cmf}, illuminant ${p.illuminant}; ${p.metric} metric, ${p.weight} weight, ` +
      `${p.nodes} nodes; OCIO config ${p.ocio_config.file} (${p.ocio_config.origin}); display: ${p.display}; metalfit ${p.metalfit_version}`;
  }

  function costLine(report) {
    return report.costs
      ? `cost: ${report.costs.source} (${report.costs.unit})`
      : 'cost: no cost table given (metalfit report does not take --costs yet), so the cost column is empty and there is no error-vs-cost chart';
  }

  function rendersSkipped(report) {
    return report.renders.skipped === undefined ? null : el('p', { class: 'renders-skipped', text: 'renders skipped: ' + report.renders.skipped });
  }

  // The heat map's metrics: the worst channel of each fit's rel_rms, |err_f0| and max_rel, and its ΔE2000 max.
  const worstOf = (values) => (values == null || values.some((v) => v == null) ? null : Math.max(...values));
  const HEATMAP_METRICS = [
    { key: 'rel_rms', title: 'worst-channel rel_rms', percent: true, value: (f) => worstOf(f.metrics.rel_rms) },
    { key: 'f0_err', title: 'worst-channel |F0 error|', percent: true, value: (f) => worstOf(f.err_f0 && f.err_f0.map((v) => (v == null ? null : Math.abs(v)))) },
    { key: 'de2000_max', title: 'ΔE2000 max', percent: false, value: (f) => f.metrics.de2000_max },
    { key: 'max_rel', title: 'worst-channel max_rel', percent: true, value: (f) => worstOf(f.metrics.max_rel) },
  ];
  const heatmapMetric = (key) => HEATMAP_METRICS.find((m) => m.key === key);

  function heatmapData(report, key) {
    const metric = heatmapMetric(key);
    const cells = [];
    report.materials.forEach((mat) => report.models.forEach((m) => {
      const fit = mat.models[m.id] && mat.models[m.id].fit;
      const v = fit ? metric.value(fit) : null;
      cells.push({ material: mat.id, model: m.id, worst: v, label: metric.percent ? pct(v, 2) : num(v, 2),
                   recommended: mat.recommendation != null && mat.recommendation.chosen === m.id });
    }));
    const positive = cells.map((c) => c.worst).filter((v) => v != null && v > 0);
    const lo = Math.log(Math.min(...positive)), hi = Math.log(Math.max(...positive));
    cells.forEach((c) => { c.dark = c.worst != null && c.worst > 0 && hi > lo && (Math.log(c.worst) - lo) / (hi - lo) < 0.55; });
    return cells;
  }

  function heatmapSpec(base, key) {
    const metric = heatmapMetric(key);
    const spec = JSON.parse(JSON.stringify(base));
    spec.title = `${metric.title} of the fit, material × model (log colour scale${metric.percent ? '; value in %' : ''})`;
    const colour = spec.layer[0].encoding.color;
    colour.title = metric.key;
    colour.legend = { format: metric.percent ? '.2~%' : '.2~f' };
    return spec;
  }

  // The first screen of a material page: the model to use, its constants for the target, why the cheaper ones fail.
  function recommendationSection(mat) {
    const r = mat.recommendation;
    if (!r) return null;
    const t = r.tolerance;
    const limits = `rel_rms ≤ ${pct(t.rel_rms, 2)}, |F0 error| ≤ ${pct(t.f0_err, 2)}, ΔE2000 max ≤ ${t.de2000_max}`;
    const chosen = r.candidates.find((c) => c.model === r.chosen);
    const head = chosen
      ? el('p', { class: 'recommended' }, 'Use ', el('strong', { text: r.chosen }), ` for ${r.target}: rel_rms ${pct(chosen.values.rel_rms, 3)}, ` +
          `|F0 error| ${pct(chosen.values.f0_err, 3)}, ΔE2000 max ${num(chosen.values.de2000_max, 3)} (${limits}; cost: ${r.cost_table})`)
      : el('p', { class: 'recommended none', text: `No model meets ${limits} for ${r.target} (cost: ${r.cost_table}).` });
    const cheaper = [];
    for (const c of r.candidates) {
      if (c.model === r.chosen) break;
      cheaper.push(el('li', { text: `${c.model}: ${c.reason}` }));
    }
    return section('Recommended model', head,
      chosen ? el('pre', { class: 'constants', text: r.constants }) : null,
      cheaper.length ? el('p', { text: chosen ? 'Cheaper models fail:' : 'Every model fails:' }) : null,
      cheaper.length ? el('ul', { class: 'cheaper' }, ...cheaper) : null);
  }

  // ---------------------------------------------------------------------------------------------- catalog page
  function catalogPage(report, main) {
    const models = report.models;
    const materials = report.materials;
    main.append(el('h1', { text: `metalfit report: ${materials.length} material${materials.length === 1 ? '' : 's'} × ${models.length} model${models.length === 1 ? '' : 's'}` }));
    main.append(el('p', { class: 'provenance', text: provenanceLine(report) }));
    main.append(el('p', { class: 'cost', text: costLine(report) }));
    const charts = report.charts.catalog;
    const done = [];

    const overview = section('Where the cheap models fail');
    main.append(overview);
    const target = materials.map((m) => m.recommendation).find((r) => r != null);
    if (target) {
      const t = target.tolerance;
      overview.append(el('p', { class: 'recommendation-note', text: `outlined: the cheapest model for ${target.target} meeting ` +
        `rel_rms ≤ ${pct(t.rel_rms, 2)}, |F0 error| ≤ ${pct(t.f0_err, 2)} and ΔE2000 max ≤ ${t.de2000_max} in every channel (each material's page says why the cheaper ones fail)` }));
    }
    const picker = el('select', { id: 'heatmap-metric' },
      ...HEATMAP_METRICS.map((m) => el('option', { value: m.key, text: m.title })));
    overview.append(el('p', {}, el('label', { for: 'heatmap-metric', text: 'metric: ' }), picker));
    const holder = el('div', {});
    overview.append(holder);
    const drawHeatmap = (key) => {
      holder.replaceChildren();
      return chart('heatmap', heatmapSpec(charts.heatmap, key), { heatmap: heatmapData(report, key) }, holder);
    };
    picker.addEventListener('change', () => drawHeatmap(picker.value));
    done.push(drawHeatmap(HEATMAP_METRICS[0].key));

    const headers = ['material', 'name', 'source', 'kind', ...models.map((m) => m.id), 'best fit'];
    if (report.budget != null) headers.push(`budget ${pct(report.budget, 2)}`);
    if (target) headers.push(`recommended for ${target.target}`);
    const rows = materials.map((mat, i) => {
      let best = null;
      models.forEach((m) => { const v = m.fit_worst_rel_rms.per_material[i]; if (v != null && (best == null || v < best.v)) best = { id: m.id, v }; });
      const tr = el('tr', {},
        cell(el('a', { href: mat.page, text: mat.id })), cell(mat.name), cell(mat.source), cell(mat.provenance.kind || 'file'),
        ...models.map((m) => cell(pct(m.fit_worst_rel_rms.per_material[i], 2), m.fit_worst_rel_rms.per_material[i])),
        cell(best ? best.id : '—'));
      if (report.budget != null) tr.append(cell(mat.budget_choice ? (mat.budget_choice.model || 'none') : '—'));
      if (target) tr.append(cell(mat.recommendation ? (mat.recommendation.chosen || 'none') : '—'));
      return tr;
    });
    const summaryRows = ['median', 'worst'].map((which) => el('tr', { class: 'summary' },
      cell(which), cell(''), cell(''), cell(''), ...models.map((m) => cell(pct(m.fit_worst_rel_rms[which], 2))), cell('')));
    const table = sortableTable('catalog-table', headers, rows);
    table.append(el('tfoot', {}, ...summaryRows));
    const tableSection = section('Worst-channel rel_rms of every fit (click a column to sort)', table,
      el('p', { class: 'note', text: 'cost per model: ' + models.map((m) => `${m.id} ${costText(m.cost)}`).join(', ') }));
    main.append(tableSection);

    if (charts.pareto) {
      const pareto = models.filter((m) => m.cost != null).map((m) => ({ model: m.id, cost: m.cost, median: m.fit_worst_rel_rms.median, on_front: m.pareto_front ? 'on the front' : 'dominated' }));
      const front = pareto.filter((p) => p.on_front === 'on the front').sort((a, b) => a.cost - b.cost);
      const s = section('Error vs cost');
      main.append(s);
      done.push(chart('pareto', charts.pareto, { pareto, pareto_front: front }, s));
    }

    const swatches = [];
    materials.forEach((mat) => ['F0', 'F82'].forEach((which) => swatches.push({ material: mat.id, which, color: mat.swatch[which] })));
    const sw = section('Colours');
    main.append(sw);
    done.push(chart('swatches', charts.swatches, { swatches }, sw));
    return done;
  }

  // --------------------------------------------------------------------------------------------- material page
  function provenanceTable(report, mat) {
    const p = report.provenance, d = mat.provenance;
    const rows = [
      ['material', `${mat.name} (${mat.id})`], ['kind', d.kind || 'user file'], ['source', mat.source], ['reference', d.reference],
      ['DOI', d.doi || '—'], ['licence', d.licence || '—'], ['data file', d.file], ['database path', d.database_path || '—'],
      ['file sha256', d.sha256], ['format', `${d.format}, ${d.data_type}`],
      ...(d.stack ? [['stack', d.stack.description],
                     ...['coat', 'film'].filter((l) => d.stack[l]).map((l) => [`${l} data`,
                       `${d.stack[l].name} (${d.stack[l].source}), ${d.stack[l].file || 'constant'}${d.stack[l].sha256 ? `, sha256 ${d.stack[l].sha256}` : ''}`])] : []),
      ['colour space', p.color_space], ['CMF', p.cmf], ['illuminant', p.illuminant], ['white balance', p.white_balance],
      ['interpolation', `${p.interpolation}, out of range: ${p.out_of_range}`],
      ['nodes', `${p.nodes} (${p.quadrature})`], ['metric', p.metric], ['weight', p.weight],
      ['OCIO config', `${p.ocio_config.file} (${p.ocio_config.origin}, sha256 ${p.ocio_config.sha256})`], ['display transform', p.display],
      ['metalfit version', p.metalfit_version]];
    return el('table', { id: 'provenance', class: 'provenance' }, ...rows.map(([k, v]) => el('tr', {}, el('th', { text: k }), el('td', { text: v }))));
  }

  function paramsText(params) {
    return Object.entries(params).map(([name, v]) => `${name} = ${rgbText(v)}`).join('; ');
  }

  function modelsTable(report, mat) {
    const headers = ['model', 'parameters', 'parameter values (R / G / B)', 'rel_rms', 'abs_rms', 'max_rel', 'max_abs', 'ΔE2000 mean', 'ΔE2000 max', 'albedo error', 'cost', 'budget'];
    const rows = [];
    const chosen = mat.budget_choice && mat.budget_choice.model;
    for (const m of report.models) {
      const r = mat.models[m.id];
      const kinds = [['fit', r.fit]];
      if (r.closed.form) kinds.push([`closed ${r.closed.form}`, r.closed]);
      for (const [which, e] of kinds) {
        const x = e.metrics;
        rows.push(el('tr', { class: which === 'fit' ? 'fit' : 'closed' },
          cell(`${m.id}`, m.id), cell(which),
          // A fit on a bound of its model is marked (fit.at_bound: which channel, which parameter).
          cell(e.at_bound ? el('span', {}, paramsText(e.params), el('div', { class: 'at-bound', text: 'on a bound: ' +
            e.at_bound.map((b, k) => (b ? `${'RGB'[k]} ${b}` : null)).filter((b) => b).join('; ') })) : paramsText(e.params)),
          cell(rgbText(x.rel_rms, pct), Math.max(...x.rel_rms.map((v) => (v == null ? Infinity : v)))),
          cell(rgbText(x.abs_rms, pct), Math.max(...x.abs_rms)),
          cell(rgbText(x.max_rel, pct), Math.max(...x.max_rel.map((v) => (v == null ? Infinity : v)))),
          cell(rgbText(x.max_abs, pct), Math.max(...x.max_abs)),
          cell(num(x.de2000_mean, 3), x.de2000_mean), cell(num(x.de2000_max, 3), x.de2000_max),
          cell(rgbText(x.albedo_err, pct), Math.max(...x.albedo_err.map(Math.abs))),
          cell(costText(m.cost), m.cost),
          cell(which === 'fit' && chosen === m.id ? 'recommended' : '')));
      }
      if (!r.closed.form) rows.push(el('tr', { class: 'closed' }, cell(m.id, m.id), cell('closed'), cell('undefined: ' + r.closed.undefined),
        ...Array.from({ length: 9 }, () => cell('—', null))));
    }
    return sortableTable('models-table', headers, rows);
  }

  // What each consumer renders (docs/export.md): the fit's worst-channel rel_rms, |F0 error| and ΔE2000 max (what
  // GLSL, HLSL, C++, MSL, WGSL and JSON evaluate) next to those of the curve MaterialX, OpenPBR, a glTF viewer and
  // Blender render for the same model; a cell that differs from the fit's is marked.
  function consumersTable(report, mat) {
    const formats = [];
    for (const m of report.models) for (const f of Object.keys(mat.models[m.id].consumers || {})) if (!formats.includes(f)) formats.push(f);
    const label = { mtlx: 'MaterialX', openpbr: 'OpenPBR', gltf: 'glTF viewer', blender: 'Blender ≥ 4.3' };
    const figures = (worst, f0, de) => `${pct(worst, 2)} · ${pct(f0, 2)} · ${num(de, 2)}`;
    const headers = ['model', 'the model (GLSL, HLSL, C++, MSL, WGSL, JSON)', ...formats.map((f) => label[f] || f)];
    const rows = report.models.map((m) => {
      const r = mat.models[m.id], x = r.fit.metrics;
      const fitF0 = Math.max(...r.fit.err_f0.map((v) => (v == null ? Infinity : Math.abs(v))));
      const own = figures(r.worst_rel_rms, fitF0, x.de2000_max);
      return el('tr', {}, cell(m.id, m.id), cell(own, r.worst_rel_rms),
        ...formats.map((f) => {
          const c = (r.consumers || {})[f];
          if (!c) return cell('—', null);
          if (c.not_evaluated) return cell('not evaluated', null);
          const text = figures(c.worst_rel_rms, c.worst_f0_err, c.de2000_max);
          const td = cell(text + (c.model !== m.id ? ` (${c.model})` : ''), c.worst_rel_rms);
          td.title = c.curve;
          if (text !== own) td.classList.add('consumer-differs');
          return td;
        }));
    });
    return [el('p', { class: 'note', text: 'Worst-channel rel_rms · |F0 error| · ΔE2000 max of the curve each consumer renders for the model ' +
      '(hover a cell for the curve; marked where it is not the fit\'s own curve: a stand-in, MaterialX\'s clamp, a glTF viewer\'s Schlick from baseColorFactor).' }),
      sortableTable('consumers-table', headers, rows)];
  }

  // A filmed material: what each renderer's thin film draws at the film's thickness against the exact stack
  // (report.json's renderer_film, the record of `metalfit table METAL --film FILM --thickness D --renderers`), or why
  // it is not scored (a coat over the film).
  function rendererFilmSection(r) {
    if (r.not_scored) return [el('p', { class: 'renderer-film-not-scored', text: r.not_scored })];
    const k = r.constants, row = r.rows[0];
    const worstSigned = (v) => v.reduce((w, x) => (x == null || w == null ? null : Math.abs(x) > Math.abs(w) ? x : w));
    const headers = ['renderer', 'what it evaluates', 'worst rel_rms', 'err_f0 (furthest channel)', 'ΔE2000 mean', 'ΔE2000 max', 'F0 (R / G / B)', 'F0 → F82 ΔE2000'];
    const title = Object.fromEntries(r.renderers.map((x) => [x.id, x.title]));
    const rows = [el('tr', { class: 'truth' }, cell('exact stack'), cell('the spectral reference curve'), cell('—', null), cell('—', null),
      cell('—', null), cell('—', null), cell(rgbText(row.truth.F0)), cell(num(row.truth.shift_de2000, 2), row.truth.shift_de2000))];
    for (const s of row.scores) {
      const rel = worstOf(s.metrics.rel_rms), f0 = worstSigned(s.err_f0);
      rows.push(el('tr', {}, cell(s.renderer), cell(title[s.renderer] || ''), cell(pct(rel, 2), rel), cell(pct(f0, 2), f0),
        cell(num(s.metrics.de2000_mean, 2), s.metrics.de2000_mean), cell(num(s.metrics.de2000_max, 2), s.metrics.de2000_max),
        cell(rgbText(s.F0)), cell(num(s.shift_de2000, 2), s.shift_de2000)));
    }
    return [el('p', { class: 'note', text: `${r.description}: each renderer's thin film against the stack's ` +
        `spectral curve (${r.space}), scored as the fits are. MaterialX and Belcour & Barla are given the bare metal's conductor-rgb fit ` +
        `(n ${rgbText(k.conductor_n)}, k ${rgbText(k.conductor_k)}) and the film's n(${k.film_ior_at_nm} nm) = ${num(k.film_ior)}; ` +
        `airy-3 the stack's own indices at ${k.three_wavelengths_nm.join(', ')} nm. The same figures as metalfit table --renderers.` }),
      sortableTable('renderer-film-table', headers, rows)];
  }

  function sourcesTable(mat) {
    const ds = mat.data_sources;
    const headers = ['source', 'F0 (R / G / B)', 'F82 (R / G / B)'];
    const rows = ds.sources.map((s) => el('tr', {}, cell(s.source + (s.primary ? ' (primary, fitted)' : '')),
      cell(s.F0 ? rgbText(s.F0) : 'undefined: ' + s.undefined), cell(s.F82 ? rgbText(s.F82) : '—')));
    const spread = ds.spread;
    const compare = el('table', { id: 'spread-table' },
      el('thead', {}, el('tr', {}, el('th', { text: '' }), el('th', { text: 'at F0 (R / G / B)' }), el('th', { text: 'at F82 (R / G / B)' }))),
      el('tbody', {},
        el('tr', { class: 'spread' }, cell('spread between the sources (max − min)'), cell(spread ? rgbText(spread.F0) : '—'), cell(spread ? rgbText(spread.F82) : '—')),
        ...Object.entries(mat.models).map(([id, r]) => el('tr', {}, cell(`|error| of ${id} (fit)`), cell(rgbText(r.error_at.F0)), cell(rgbText(r.error_at.F82))))));
    return [sortableTable('sources-table', headers, rows), compare];
  }

  function materialPage(report, id, main) {
    const mat = report.materials.find((m) => m.id === id);
    if (!mat) throw new Error('report.json has no material ' + id);
    const charts = report.charts.material;
    const done = [];
    main.append(el('p', {}, el('a', { href: '../index.html', text: '← catalog' })));
    main.append(el('h1', { text: `${mat.name} (${mat.id}, ${mat.source})` }));
    main.append(recommendationSection(mat) || '');
    main.append(el('p', { class: 'cost', text: costLine(report) }));
    if (mat.budget_choice) main.append(el('p', { class: 'budget', text: `budget ${pct(report.budget, 2)}: ${mat.budget_choice.model || 'no model'} — ${mat.budget_choice.note}` }));
    main.append(section('Provenance', provenanceTable(report, mat), ...mat.warnings.map((w) => el('p', { class: 'warning', text: 'warning: ' + w }))));

    const colours = section('Colour',
      el('p', {}, 'F0 ', el('span', { class: 'swatch', style: `background:${mat.swatch.F0}`, title: mat.swatch.F0 }), ` = ${rgbText(mat.F0)}`,
        mat.out_of_gamut_F0.length ? ` (out of gamut in ${mat.out_of_gamut_F0.join(', ')}, kept)` : '',
        ';  F82 ', el('span', { class: 'swatch', style: `background:${mat.swatch.F82}`, title: mat.swatch.F82 }), ` = ${rgbText(mat.F82)}`));
    main.append(colours);
    if (mat.renderer_film) main.append(section('What renderers draw for this film', ...rendererFilmSection(mat.renderer_film)));

    const data = section('The data');
    main.append(data);
    const nk = [];
    mat.nk.nm.forEach((nm, i) => { nk.push({ nm, quantity: 'n', value: mat.nk.n[i] }); nk.push({ nm, quantity: 'k', value: mat.nk.k[i] }); });
    done.push(chart('nk', charts.nk, { nk, visible: [{ from: mat.nk.visible[0], to: mat.nk.visible[1] }] }, data));
    const spectral = [];
    mat.spectral_reflectance.theta_deg.forEach((t, a) => mat.spectral_reflectance.nm.forEach((nm, i) => spectral.push({ nm, angle: t + '°', R: mat.spectral_reflectance.R[a][i] })));
    done.push(chart('spectral', charts.spectral, { spectral }, data));

    main.append(section('Every model (fitted parameters and the best closed form; click a column to sort)', modelsTable(report, mat)));
    main.append(section('What each consumer renders', ...consumersTable(report, mat)));

    const curves = section('Against the angle');
    main.append(curves);
    const c = mat.curves;
    const reflectance = [], relError = [], de2000 = [], stripes = [];
    const step = c.theta_deg.length > 1 ? c.theta_deg[1] - c.theta_deg[0] : 1;
    c.theta_deg.forEach((theta, i) => {
      const mu = c.mu[i];
      CHANNELS.forEach((channel, k) => reflectance.push({ theta, mu, channel, series: 'exact', R: c.exact[k][i] }));
      stripes.push({ row: 'exact', theta0: theta, theta1: theta + step, color: c.stripe[i] });
    });
    for (const m of report.models) {
      const r = mat.models[m.id];
      c.theta_deg.forEach((theta, i) => {
        const mu = c.mu[i];
        CHANNELS.forEach((channel, k) => {
          const R = r.curve[k][i], exact = c.exact[k][i];
          reflectance.push({ theta, mu, channel, series: m.id, R });
          relError.push({ theta, mu, channel, series: m.id, rel_percent: 100 * (R - exact) / exact });
        });
        de2000.push({ theta, mu, series: m.id, de: r.de2000[i] });
        stripes.push({ row: m.id, theta0: theta, theta1: theta + step, color: r.stripe[i] });
      });
    }
    done.push(chart('reflectance', charts.reflectance, { reflectance }, curves));
    done.push(chart('rel_error', charts.rel_error, { rel_error: relError }, curves));
    done.push(chart('de2000', charts.de2000, { de2000 }, curves));
    done.push(chart('stripes', charts.stripes, { stripes }, curves));

    // The interactive sphere (viewer.js): the reference and each model under a sky and a movable light.
    const viewer = el('div', { id: 'viewer' });
    main.append(section('Interactive sphere (WebGL2)', viewer));
    done.push(window.metalfitViewer(viewer, report, mat));

    const renders = section('Renders');
    main.append(renders);
    const skipped = rendersSkipped(report);
    if (skipped) renders.append(skipped);
    else if (mat.render_row == null) renders.append(el('p', { class: 'renders-skipped', text: 'renders skipped: glpreview rendered no row for ' + mat.id }));
    else {
      // Per model of the report one render: reference | model | its signed error (false colour), one line per roughness, each cell
      // cropped from the material's row image (unlabelled: each line captioned here, with the error view's scale).
      const r = report.renders, row = r.rows[mat.render_row];
      const [w, h] = r.cell;
      const crop = (column, alt, id) => el('div', { class: 'sheet-crop', style: `width:${w}px;height:${h}px` },
        el('img', { class: 'render-cell', ...(id ? { id } : {}), src: '../' + row.image, alt,
          style: `margin-left:${-column * w}px` }));
      let first = true;
      for (const m of row.models) {
        const labels = [r.columns[0], m.model, r.columns[2]];
        const lines = m.cells.map((c) => el('div', { class: 'sheet-line' },
          crop(c.reference, `${row.material}: reference, roughness ${c.roughness}`, first ? 'render' : null),
          crop(c.model, `${row.material}: ${m.model}, roughness ${c.roughness}`),
          crop(c.difference, `${row.material}: ${m.model} / reference - 1 in false colour (log scale), roughness ${c.roughness}`),
          el('span', { class: 'sheet-row-label', text: `roughness ${c.roughness}, image RMSE ${c.image_rmse.toPrecision(2)}, error view ±${c.error_view[0].toPrecision(2)}..${c.error_view[1].toPrecision(2)} (log)` })));
        first = false;
        renders.append(el('figure', { class: 'sheet render-model', 'data-model': m.model },
          el('figcaption', { text: `${row.material}: ${m.model}` }),
          el('div', { class: 'sheet-columns', style: `width:${3 * w}px` }, ...labels.map((l) => el('span', { style: `width:${w}px`, text: l }))),
          ...lines));
      }
      renders.append(el('p', { class: 'note', text: r.by }));
    }

    if (mat.data_sources) main.append(section('Data sources: how much the measurements disagree vs how much each model errs', ...sourcesTable(mat)));
    return done;
  }

  window.metalfitReport = function (report) {
    const body = document.body;
    const main = document.getElementById('content');
    let done;
    try {
      done = body.dataset.page === 'catalog' ? catalogPage(report, main) : materialPage(report, body.dataset.material, main);
    } catch (error) {
      body.dataset.rendered = 'error';
      throw error;
    }
    Promise.all(done).then(() => { body.dataset.rendered = 'true'; },
      (error) => { body.dataset.rendered = 'error'; console.error(error); });
  };
})();
