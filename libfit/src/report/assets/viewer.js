// metalfit report: the interactive sphere of a material page (docs/report.md, "The viewer"). A mirror sphere, drawn
// by three.js in WebGL2, under a procedural sky and a movable light, or in a white furnace, shading with the exact
// reference (report.json's 1D LUT of R_c(μ) as a float texture) or with a fitted model (its GLSL from report.json,
// the text the GLSL export writes, called with the fit's parameters), or showing |model − reference| per channel.
//
// The sphere is ray-traced per pixel in the fragment shader under an orthographic view: the normal at a pixel is
// exact, so μ = N·V of every pixel is known in closed form (the browser test reads pixels back at known μ).
// Display: the working space's linear values, clamped to [0, 1], through the sRGB transfer function (IEC 61966-2-1),
// no gamut conversion and no tone mapping; the difference view writes its scaled values without the transfer function.
(function () {
  'use strict';

  // three.js arrives as text from assets/three.js (loaded after this file): imported through blob: URLs, the core
  // module first, three.module.js's import of './three.core.js' pointed at it.
  let three = null;
  window.metalfitThree = function (sources) {
    const url = (text) => URL.createObjectURL(new Blob([text], { type: 'text/javascript' }));
    const core = url(sources['three.core.js']);
    const parts = sources['three.module.js'].split("'./three.core.js'");
    if (parts.length < 2) throw new Error('three.module.js does not import ./three.core.js: the viewer cannot load it');
    three = import(url(parts.join(JSON.stringify(core))));
  };

  // Canvas pixels (device pixel ratio 1: one canvas pixel per drawn pixel), odd: the middle pixel's centre is the
  // sphere's, where μ = 1 exactly.
  const SIZE = 321;
  const RADIUS = 0.92;       // the sphere's radius in clip space
  const LIGHT_RADIANCE = 8;  // the light's radiance, the sky's being about 1
  const LIGHT_DEGREES = 4;   // the light's angular radius
  const DIFFERENCE_SCALES = [10, 30, 100];

  const VERTEX = `
in vec3 position;
void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }
`;

  // The fragment shader around one shading function: `shade(mu)` is the reference or a model; `reference(mu)` is
  // the LUT, linearly interpolated between its two nearest samples (texelFetch: no filtering by the GPU).
  function fragmentShader(modelSource, shadeCall) {
    return `
precision highp float;
precision highp int;
precision highp sampler2D;
uniform sampler2D lut;
uniform int lutSize;
uniform vec2 canvasSize;
uniform float radius;
uniform int view;         // 0: the shaded sphere, 1: |shade − reference| × differenceScale
uniform int environment;  // 0: sky and light, 1: white furnace (radiance 1 everywhere)
uniform vec3 lightDirection;
uniform float lightCos;
uniform float lightRadiance;
uniform float differenceScale;
uniform vec3 p0, p1, p2, p3, p4, p5;
out vec4 fragColor;

${modelSource}

vec3 reference(float mu) {
    float x = clamp(mu, 0.0, 1.0) * float(lutSize - 1);
    int i = min(int(floor(x)), lutSize - 2);
    float t = x - float(i);
    return mix(texelFetch(lut, ivec2(i, 0), 0).rgb, texelFetch(lut, ivec2(i + 1, 0), 0).rgb, t);
}

vec3 shade(float mu) { return ${shadeCall}; }

// The sky: blue above, warm ground below with a checker to read the reflection by, and the light, a disc.
vec3 sky(vec3 d) {
    vec3 c;
    if (d.y >= 0.0) {
        c = mix(vec3(0.95, 0.92, 0.85), vec3(0.45, 0.62, 0.95), sqrt(d.y));
    } else {
        vec2 g = d.xz / max(-d.y, 0.02);
        float checker = mod(floor(g.x) + floor(g.y), 2.0);
        c = mix(vec3(0.30, 0.26, 0.22), vec3(0.12, 0.10, 0.09), checker) * (0.5 + 0.5 * sqrt(-d.y));
    }
    float disc = smoothstep(lightCos - 0.0004, lightCos + 0.0004, dot(d, lightDirection));
    return mix(c, vec3(lightRadiance), disc);
}

float encode(float v) {  // the sRGB transfer function
    v = clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

void main() {
    vec2 p = (gl_FragCoord.xy / canvasSize * 2.0 - 1.0) / radius;
    float rr = dot(p, p);
    if (rr > 1.0) {  // around the sphere: the environment (a white furnace is white), black behind the difference
        vec3 b = view == 1 ? vec3(0.0) : environment == 1 ? vec3(1.0) : sky(normalize(vec3(0.6 * p, -1.0)));
        fragColor = vec4(view == 1 ? b : vec3(encode(b.r), encode(b.g), encode(b.b)), 1.0);
        return;
    }
    float mu = sqrt(1.0 - rr);      // N·V: the view looks down −z, V = (0, 0, 1)
    vec3 n = vec3(p, mu);
    vec3 r = 2.0 * mu * n - vec3(0.0, 0.0, 1.0);  // the mirror direction
    if (view == 1) {
        fragColor = vec4(clamp(abs(shade(mu) - reference(mu)) * differenceScale, 0.0, 1.0), 1.0);
        return;
    }
    vec3 c = shade(mu) * (environment == 1 ? vec3(1.0) : sky(r));
    fragColor = vec4(encode(c.r), encode(c.g), encode(c.b), 1.0);
}
`;
  }

  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) if (v != null) k === 'text' ? (e.textContent = v) : e.setAttribute(k, v);
    for (const c of children) if (c != null) e.append(c);
    return e;
  }

  const select = (id, options) => el('select', { id }, ...options.map(([value, text]) => el('option', { value, text })));
  const labelled = (text, control) => el('label', { class: 'viewer-control' }, text + ' ', control);

  // Builds the viewer into `into`; resolves once the first frame is drawn.
  window.metalfitViewer = async function (into, report, mat) {
    if (!three) throw new Error('assets/three.js did not load: the viewer has no three.js');
    const THREE = await three;

    const canvas = el('canvas', { id: 'viewer-canvas', width: SIZE, height: SIZE, 'data-radius': RADIUS, style: `width:${SIZE}px;height:${SIZE}px` });
    const models = report.models.map((m) => m.id);
    const modelSelect = select('viewer-model', [['reference', 'reference (exact, the LUT)'], ...models.map((id) => [id, id])]);
    const viewSelect = select('viewer-view', [['image', 'shaded'], ['difference', '|model − reference|']]);
    const scaleSelect = select('viewer-scale', DIFFERENCE_SCALES.map((s) => [String(s), `× ${s}`]));
    const environmentSelect = select('viewer-environment', [['sky', 'sky and light'], ['white', 'white furnace (shows R_c itself)']]);
    const azimuth = el('input', { id: 'viewer-azimuth', type: 'range', min: -180, max: 180, step: 1, value: 35 });
    const elevation = el('input', { id: 'viewer-elevation', type: 'range', min: -90, max: 90, step: 1, value: 30 });
    const legend = el('div', { id: 'viewer-legend', class: 'viewer-legend' });
    into.append(
      el('div', { class: 'viewer-controls' },
        labelled('shading:', modelSelect), labelled('view:', viewSelect), labelled('difference scale:', scaleSelect),
        labelled('environment:', environmentSelect), labelled('light azimuth:', azimuth), labelled('elevation:', elevation)),
      el('div', { class: 'viewer-row' }, canvas, legend),
      el('p', { class: 'note', text: 'A mirror sphere (orthographic view, exact normal per pixel). The reference is ' +
        `R_c(μ) of ${mat.id} from a ${mat.lut[0].length}-sample LUT in μ (report.json's materials[].lut, linear ` +
        `interpolation); a model is its fitted curve, evaluated by the model's GLSL (the GLSL export's text). Colours: ` +
        `${report.provenance.color_space} values clamped to [0, 1] through the sRGB transfer function, no gamut conversion ` +
        '(the swatches and stripes above use the OCIO display transform). Drag on the sphere to put the light\'s ' +
        'reflection there.' }));

    const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    renderer.setPixelRatio(1);
    renderer.setSize(SIZE, SIZE, false);
    const lutSize = mat.lut[0].length;
    const texels = new Float32Array(4 * lutSize);
    for (let i = 0; i < lutSize; ++i) {
      for (let c = 0; c < 3; ++c) texels[4 * i + c] = mat.lut[c][i];
      texels[4 * i + 3] = 1;
    }
    const lut = new THREE.DataTexture(texels, lutSize, 1, THREE.RGBAFormat, THREE.FloatType);
    lut.minFilter = lut.magFilter = THREE.NearestFilter;
    lut.generateMipmaps = false;
    lut.needsUpdate = true;
    const uniforms = {
      lut: { value: lut }, lutSize: { value: lutSize }, canvasSize: { value: new THREE.Vector2(SIZE, SIZE) },
      radius: { value: RADIUS }, view: { value: 0 }, environment: { value: 0 },
      lightDirection: { value: new THREE.Vector3() }, lightCos: { value: Math.cos(LIGHT_DEGREES * Math.PI / 180) },
      lightRadiance: { value: LIGHT_RADIANCE }, differenceScale: { value: DIFFERENCE_SCALES[0] },
    };
    for (let i = 0; i < 6; ++i) uniforms['p' + i] = { value: new THREE.Vector3() };

    // One shader per shading (the reference, each model); a model's parameters bound to p0, p1, … in its order.
    const materials = new Map();
    function materialOf(id) {
      if (materials.has(id)) return materials.get(id);
      let source = '', call = 'reference(mu)', own = {};
      if (id !== 'reference') {
        const model = report.models.find((m) => m.id === id);
        const params = mat.models[id].fit.params;
        if (model.parameters.length > 6) throw new Error(`viewer: ${id} has more than 6 parameters`);
        own = Object.fromEntries(model.parameters.map((name, i) => ['p' + i, { value: new THREE.Vector3(...params[name]) }]));
        source = model.glsl.source;
        call = `${model.glsl.function}(${model.parameters.map((_, i) => 'p' + i).concat('mu').join(', ')})`;
      }
      const material = new THREE.RawShaderMaterial({
        glslVersion: THREE.GLSL3, vertexShader: VERTEX, fragmentShader: fragmentShader(source, call),
        uniforms: { ...uniforms, ...own }, depthTest: false, depthWrite: false,
      });
      materials.set(id, material);
      return material;
    }

    const mesh = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), materialOf('reference'));
    mesh.frustumCulled = false;
    const scene = new THREE.Scene();
    scene.add(mesh);
    const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, -1, 1);

    function drawLegend(scale) {
      legend.replaceChildren(
        el('div', { class: 'viewer-legend-bar' }),
        el('div', { class: 'viewer-legend-ticks' }, el('span', { text: '0' }), el('span', { text: `≥ ${(100 / scale).toPrecision(2)} %` })),
        el('p', { text: `each channel: |model − reference| × ${scale}, linear (no transfer function): full intensity at an ` +
          `error of ${(1 / scale).toPrecision(2)} (${(100 / scale).toPrecision(2)} % reflectance) or more; black outside the sphere.` }));
    }

    function draw() {
      const id = modelSelect.value;
      const difference = viewSelect.value === 'difference';
      mesh.material = materialOf(id);
      uniforms.view.value = difference ? 1 : 0;
      uniforms.environment.value = environmentSelect.value === 'white' ? 1 : 0;
      uniforms.differenceScale.value = Number(scaleSelect.value);
      const a = Number(azimuth.value) * Math.PI / 180, e = Number(elevation.value) * Math.PI / 180;
      uniforms.lightDirection.value.set(Math.cos(e) * Math.sin(a), Math.sin(e), Math.cos(e) * Math.cos(a));
      if (difference) drawLegend(Number(scaleSelect.value));
      else legend.replaceChildren();
      scaleSelect.disabled = !difference;
      renderer.render(scene, camera);
      canvas.dataset.shading = id;
      canvas.dataset.view = viewSelect.value;
      canvas.dataset.frames = String(Number(canvas.dataset.frames || 0) + 1);
    }

    // Dragging on the sphere puts the light where the mirror direction of that point goes: its reflection follows.
    function pointTo(event) {
      const box = canvas.getBoundingClientRect();
      const x = ((event.clientX - box.left) / box.width * 2 - 1) / RADIUS;
      const y = (1 - (event.clientY - box.top) / box.height * 2) / RADIUS;
      const rr = x * x + y * y;
      if (rr > 1) return;
      const mu = Math.sqrt(1 - rr);
      const r = [2 * mu * x, 2 * mu * y, 2 * mu * mu - 1];
      azimuth.value = String(Math.round(Math.atan2(r[0], r[2]) * 180 / Math.PI));
      elevation.value = String(Math.round(Math.asin(Math.max(-1, Math.min(1, r[1]))) * 180 / Math.PI));
      draw();
    }
    canvas.addEventListener('pointerdown', (event) => { canvas.setPointerCapture(event.pointerId); pointTo(event); });
    canvas.addEventListener('pointermove', (event) => { if (canvas.hasPointerCapture(event.pointerId)) pointTo(event); });
    for (const control of [modelSelect, viewSelect, scaleSelect, environmentSelect, azimuth, elevation]) {
      control.addEventListener('input', draw);
      control.addEventListener('change', draw);
    }
    draw();
  };
})();
