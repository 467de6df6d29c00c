// acdream-physics view: one scene's collision shapes and its movers' recorded frames, in 3D, offline.
import {
  ArrowHelper, BufferGeometry, CircleGeometry, Color, DirectionalLight, DoubleSide, Float32BufferAttribute,
  HemisphereLight, LineBasicMaterial, LineLoop, LineSegments, Mesh, MeshLambertMaterial, Object3D, OctahedronGeometry,
  OrthographicCamera, PerspectiveCamera, Points, PointsMaterial, Quaternion, Scene, SphereGeometry, Vector3,
  WebGLRenderer, Group, Line, EdgesGeometry,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import * as C from './colors.js';
import { FLAG, blockOffset, drawPosition, hex, isContact, quat, rotate, vec } from './data.js';
import { panelHtml } from './panel.js';
import { buildWorld } from './world.js';

Object3D.DEFAULT_UP.set(0, 0, 1);
const opened = performance.now();
const data = JSON.parse(document.getElementById('view-data').textContent);

// ---- layout
document.body.innerHTML = `
<div id="app">
  <div id="bar">
    <button id="v3d" class="on" title="3D orbit camera (drag to turn, right-drag to pan, wheel to zoom)">3D</button>
    <button id="vtop" title="top view, orthographic">top</button>
    <button id="vside" title="side view along +y, orthographic">side</button>
    <select id="mover" title="the mover whose frames the slider steps"></select>
    <button id="prev" title="previous frame (left arrow)">&#9664; 1</button>
    <button id="play" title="play or pause (space)">play</button>
    <button id="next" title="next frame (right arrow)">1 &#9654;</button>
    <button id="contact" title="the next frame with a collision normal or a hit (n)">next contact</button>
    <input id="slider" type="range" min="0" max="0" value="0">
    <span id="frameLabel"></span>
    <label><input id="follow" type="checkbox"> follow</label>
    <label><input id="allMovers" type="checkbox"> all movers</label>
    <label><input id="byCell" type="checkbox"> cells by id</label>
    <label><input id="showTerrain" type="checkbox" checked> terrain</label>
  </div>
  <div id="stage"></div>
  <div id="panel"></div>
  <div id="legend"></div>
</div>`;
const $ = (id) => document.getElementById(id);
const stage = $('stage');

// ---- legend
{
  const key = (color, text, shape = '') => `<span><span class="key" style="background:${color};${shape}"></span>${text}</span>`;
  const items = C.OUTCOMES.map((o) => key(o.color, `frame: ${o.name}`, 'border-radius:50%'));
  for (const s of Object.values(C.SOURCES)) items.push(key(s.color, s.name));
  items.push(key(C.BACK_FACE, 'back of a one-sided polygon'));
  items.push(key(C.NON_COLLIDING, 'object shape never tested (its rung of the dispatch)'));
  items.push(key(C.HIT, 'object hit this frame, or the polygon its collision normal came from'));
  items.push(key(C.MOVER, 'mover spheres'));
  items.push(key(C.CONTACT_PLANE, 'contact plane'));
  items.push(key(C.COLLISION_NORMAL, 'collision normal'));
  items.push(key(C.SLIDING_NORMAL, 'sliding normal'));
  items.push(key(C.CELL_OUTLINE, "the frame's cell"));
  items.push(key(C.REPORT, 'reported position (interpolateTo)'));
  items.push(key(C.PATH_AHEAD, 'path still to come; gaps are blips/teleports'));
  $('legend').innerHTML = items.join('');
}

// ---- three.js scene
const scene = new Scene();
scene.background = new Color(C.BACKGROUND);
scene.add(new HemisphereLight('#ffffff', '#707060', 2.2));
const sun = new DirectionalLight('#ffffff', 1.2);
sun.position.set(0.4, -0.6, 1);
scene.add(sun);
const world = buildWorld(data);
scene.add(world.group);
const terrainMeshes = world.group.children.filter((o) => o.userData.source === 'terrain');

let renderer = null;
try {
  renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  stage.appendChild(renderer.domElement);
} catch (e) {
  stage.textContent = `WebGL is not available in this browser, so only the panel works: ${e.message}`;
}

// ---- movers: paths, markers, spheres, normals
const outcomeColors = C.OUTCOMES.map((o) => new Color(o.color));
const movers = data.movers.map((mover, index) => {
  const n = mover.frames;
  const points = [mover.start];
  for (let f = 0; f < n; f++) points.push(drawPosition(data, mover, f));
  const breaks = new Set(mover.breaks);
  // Segment k joins point k-1 to point k (frame k-1); a break leaves it out. segmentsUpTo[f]: segments through frame f.
  const pos = [], col = [], segmentsUpTo = new Int32Array(n);
  let count = 0;
  for (let f = 0; f < n; f++) {
    if (!breaks.has(f)) {
      const a = points[f], b = points[f + 1], c = outcomeColors[mover.outcome[f]];
      pos.push(...a, ...b);
      col.push(c.r, c.g, c.b, c.r, c.g, c.b);
      count++;
    }
    segmentsUpTo[f] = count;
  }
  const segGeometry = new BufferGeometry();
  segGeometry.setAttribute('position', new Float32BufferAttribute(pos, 3));
  segGeometry.setAttribute('color', new Float32BufferAttribute(col, 3));
  const done = new LineSegments(segGeometry, new LineBasicMaterial({ vertexColors: true }));
  const ahead = new LineSegments(segGeometry, new LineBasicMaterial({ color: C.PATH_AHEAD, transparent: true, opacity: 0.8 }));
  const markerPos = [], markerCol = [];
  for (let f = 0; f < n; f++) {
    const c = outcomeColors[mover.outcome[f]];
    markerPos.push(...points[f + 1]);
    markerCol.push(c.r, c.g, c.b);
  }
  const markerGeometry = new BufferGeometry();
  markerGeometry.setAttribute('position', new Float32BufferAttribute(markerPos, 3));
  markerGeometry.setAttribute('color', new Float32BufferAttribute(markerCol, 3));
  const markers = new Points(markerGeometry, new PointsMaterial({ vertexColors: true, size: 5, sizeAttenuation: false }));
  const body = new Group();
  const sphereMaterial = new MeshLambertMaterial({ color: C.OTHER_MOVER, transparent: true, opacity: 0.35, depthWrite: false });
  const sphereEdges = new LineBasicMaterial({ color: C.OTHER_MOVER });
  for (const [x, y, z, r] of mover.spheres) {
    const g = new SphereGeometry(r, 18, 12);
    g.translate(x, y, z);
    body.add(new Mesh(g, sphereMaterial), new LineSegments(new EdgesGeometry(g, 25), sphereEdges));
  }
  if (mover.spheres.length === 0) body.add(new Mesh(new SphereGeometry(0.1, 8, 6), sphereMaterial));
  const group = new Group();
  group.add(ahead, done, markers, body);
  if (mover.reports.length) {
    const g = new OctahedronGeometry(0.15);
    const m = new MeshLambertMaterial({ color: C.REPORT });
    for (let i = 0; i < mover.reports.length; i += 3) {
      const d = new Mesh(g, m);
      d.position.set(mover.reports[i], mover.reports[i + 1], mover.reports[i + 2]);
      group.add(d);
    }
  }
  scene.add(group);
  return { mover, index, points, segmentsUpTo, done, markers, body, sphereMaterial, sphereEdges, group };
});

// Per-frame helpers for the selected mover.
const contactPlane = new Mesh(new CircleGeometry(0.8, 32), new MeshLambertMaterial({ color: C.CONTACT_PLANE, transparent: true, opacity: 0.45, side: DoubleSide, depthWrite: false }));
const collisionArrow = new ArrowHelper(new Vector3(1, 0, 0), new Vector3(), 0.9, C.COLLISION_NORMAL, 0.22, 0.12);
const slidingArrow = new ArrowHelper(new Vector3(1, 0, 0), new Vector3(), 0.7, C.SLIDING_NORMAL, 0.2, 0.1);
const headingLine = new Line(new BufferGeometry().setFromPoints([new Vector3(), new Vector3(0, 0.8, 0)]), new LineBasicMaterial({ color: C.HEADING }));
const targetCross = new LineSegments(new BufferGeometry().setFromPoints([
  new Vector3(-0.15, 0, 0), new Vector3(0.15, 0, 0), new Vector3(0, -0.15, 0), new Vector3(0, 0.15, 0), new Vector3(0, 0, -0.15), new Vector3(0, 0, 0.15)]),
new LineBasicMaterial({ color: C.TARGET }));
const cellOutline = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ color: C.CELL_OUTLINE, depthTest: false, transparent: true }));
cellOutline.renderOrder = 10;
const landOutline = new LineLoop(new BufferGeometry(), new LineBasicMaterial({ color: C.CELL_OUTLINE, depthTest: false, transparent: true }));
landOutline.renderOrder = 10;
scene.add(contactPlane, collisionArrow, slidingArrow, headingLine, targetCross, cellOutline, landOutline);

// ---- cameras
const home = (() => {
  // The box around every mover's path up to its first teleport (so a 150 m jump does not set the scale), else the world.
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  const grow = (p) => { for (let i = 0; i < 3; i++) { min[i] = Math.min(min[i], p[i]); max[i] = Math.max(max[i], p[i]); } };
  for (const m of movers) {
    grow(m.points[0]);
    for (let f = 0; f < m.mover.frames; f++) {
      const a = m.points[f], b = m.points[f + 1];
      if (Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) > 50) break;
      grow(b);
    }
  }
  if (!isFinite(min[0]))
    for (const s of data.shapes) {
      if (s.form === 'polygon') for (let i = 0; i < s.vertices.length; i += 3) grow(s.vertices.slice(i, i + 3));
      else grow(s.center);
    }
  if (!isFinite(min[0])) { min.fill(0); max.fill(10); }
  const center = min.map((v, i) => (v + max[i]) / 2);
  const size = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2], 2) + 6;
  return { center: new Vector3(...center), size };
})();

const perspective = new PerspectiveCamera(50, 1, 0.05, 5000);
perspective.position.set(home.center.x - home.size * 0.45, home.center.y - home.size * 0.75, home.center.z + home.size * 0.55);
const top = new OrthographicCamera(-1, 1, 1, -1, -5000, 5000);
top.position.set(home.center.x, home.center.y, home.center.z + 1000);
top.up.set(0, 1, 0);
const side = new OrthographicCamera(-1, 1, 1, -1, -5000, 5000);
side.position.set(home.center.x, home.center.y - 1000, home.center.z);
const views = {};
let active = 'v3d';
for (const [id, camera] of [['v3d', perspective], ['vtop', top], ['vside', side]]) {
  const controls = renderer ? new OrbitControls(camera, renderer.domElement) : null;
  if (controls) {
    controls.target.copy(home.center);
    controls.screenSpacePanning = true;
    if (camera !== perspective) controls.enableRotate = false;
    controls.enabled = id === active;
    controls.addEventListener('change', () => requestRender());
    controls.update();
  }
  if (camera.isOrthographicCamera) camera.zoom = 1;
  views[id] = { camera, controls };
}

function resize() {
  if (!renderer) return;
  const w = Math.max(stage.clientWidth, 1), h = Math.max(stage.clientHeight, 1);
  renderer.setSize(w, h, false);
  perspective.aspect = w / h;
  perspective.updateProjectionMatrix();
  const half = home.size / 2;
  for (const cam of [top, side]) {
    cam.left = -half * w / h; cam.right = half * w / h; cam.top = half; cam.bottom = -half;
    cam.updateProjectionMatrix();
  }
  requestRender();
}

// ---- state and drawing
let current = 0;
let frame = 0;
let playing = false;
let pending = false;
let lastRenderMs = 0;
let inferred = 0;

function requestRender() {
  if (pending || !renderer) return;
  pending = true;
  requestAnimationFrame(() => { pending = false; renderNow(); });
}

function renderNow() {
  if (!renderer) return;
  const t = performance.now();
  renderer.render(scene, views[active].camera);
  lastRenderMs = performance.now() - t;
}

const up = new Vector3(0, 0, 1);
function place(m, f) {
  const mover = m.mover;
  const g = Math.min(f, mover.frames - 1);
  if (g < 0) return;
  m.done.geometry.setDrawRange(0, 2 * m.segmentsUpTo[g]);
  m.done.geometry.drawRange.count = 2 * m.segmentsUpTo[g];
  m.markers.geometry.setDrawRange(0, g + 1);
  const p = m.points[g + 1];
  m.body.position.set(p[0], p[1], p[2]);
  if (mover.rotation) {
    const [w, x, y, z] = quat(mover.rotation, g);
    m.body.quaternion.set(x, y, z, w);
  }
}

function frameBreak(m, f) {
  if (!m.mover.breaks.includes(f)) return null;
  const a = m.points[f], b = m.points[f + 1];
  return Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
}

function show() {
  const m = movers[current];
  if (!m) return;
  const mover = m.mover;
  frame = Math.max(0, Math.min(frame, mover.frames - 1));
  const all = $('allMovers').checked;
  for (const other of movers) {
    other.group.visible = all || other === m;
    place(other, frame);
    const selected = other === m;
    other.sphereMaterial.color.set(selected ? C.MOVER : C.OTHER_MOVER);
    other.sphereEdges.color.set(selected ? C.MOVER : C.OTHER_MOVER);
  }
  if (mover.frames === 0) return;
  const f = frame, flags = mover.flags[f];
  const p = m.points[f + 1];
  const lowest = mover.spheres.length ? Math.min(...mover.spheres.map((s) => s[2] - s[3])) : 0;
  const centre = mover.spheres.length ? mover.spheres[0] : [0, 0, 0, 0];
  const middle = new Vector3(p[0], p[1], p[2] + centre[2]);
  // Contact plane: n.x + d = 0 in the contact cell's landblock; drawn under the mover.
  contactPlane.visible = (flags & FLAG.contactPlaneValid) !== 0;
  if (contactPlane.visible) {
    const n = vec(mover.contactNormal, f), o = blockOffset(data, mover.contactCell[f] || mover.cell[f]);
    const d = mover.contactD[f] - (n[0] * o[0] + n[1] * o[1] + n[2] * o[2]);
    const foot = [p[0], p[1], p[2] + lowest];
    const s = n[0] * foot[0] + n[1] * foot[1] + n[2] * foot[2] + d;
    contactPlane.position.set(foot[0] - s * n[0], foot[1] - s * n[1], foot[2] - s * n[2]);
    contactPlane.quaternion.setFromUnitVectors(up, new Vector3(...n).normalize());
  }
  collisionArrow.visible = (flags & FLAG.collisionNormalValid) !== 0;
  if (collisionArrow.visible) {
    collisionArrow.position.copy(middle);
    collisionArrow.setDirection(new Vector3(...vec(mover.collisionNormal, f)).normalize());
  }
  slidingArrow.visible = (flags & FLAG.slidingNormalValid) !== 0;
  if (slidingArrow.visible) {
    slidingArrow.position.copy(middle).add(new Vector3(0, 0, 0.15));
    slidingArrow.setDirection(new Vector3(...vec(mover.slidingNormal, f)).normalize());
  }
  headingLine.visible = !!mover.rotation;
  if (mover.rotation) {
    const fwd = rotate(quat(mover.rotation, f), [0, 0.8, 0]);
    headingLine.geometry.setFromPoints([new Vector3(p[0], p[1], p[2] + 0.05), new Vector3(p[0] + fwd[0], p[1] + fwd[1], p[2] + 0.05 + fwd[2])]);
  }
  targetCross.visible = !!mover.targetOrigin && mover.targetCell[f] !== 0;
  if (targetCross.visible) {
    const t = vec(mover.targetOrigin, f), o = blockOffset(data, mover.targetCell[f]);
    targetCross.position.set(t[0] + o[0], t[1] + o[1], t[2] + o[2]);
  }
  world.highlight(mover.collided[f]);
  // No object hit but a collision normal: light up the cell or building polygon it most likely came from.
  inferred = 0;
  if (mover.collided[f].length === 0 && (flags & FLAG.collisionNormalValid) !== 0 && mover.spheres.length) {
    const q = mover.rotation ? quat(mover.rotation, f) : [1, 0, 0, 0];
    const centres = mover.spheres.map((s) => { const r = rotate(q, s); return [p[0] + r[0], p[1] + r[1], p[2] + r[2]]; });
    inferred = world.inferHit(vec(mover.collisionNormal, f), centres, Math.max(...mover.spheres.map((s) => s[3])));
  } else world.inferHit([0, 0, 0], [], 0);
  const cell = mover.cell[f];
  const edges = (cell & 0xffff) >= 0x100 ? world.cellEdges(cell) : null;
  cellOutline.visible = !!edges;
  if (edges) { cellOutline.geometry.dispose(); cellOutline.geometry = edges; }
  landOutline.visible = !edges && (cell & 0xffff) >= 1 && (cell & 0xffff) <= 64;
  if (landOutline.visible) {
    const i = (cell & 0xffff) - 1, o = blockOffset(data, cell);
    const x = Math.floor(i / 8) * 24 + o[0], y = (i % 8) * 24 + o[1], z = p[2] + 0.02;
    landOutline.geometry.setFromPoints([new Vector3(x, y, z), new Vector3(x + 24, y, z), new Vector3(x + 24, y + 24, z), new Vector3(x, y + 24, z)]);
  }
  if ($('follow').checked && views[active].controls) {
    const c = views[active].controls;
    const shift = middle.clone().sub(c.target);
    c.target.add(shift);
    views[active].camera.position.add(shift);
    c.update();
  }
  $('slider').value = String(f);
  $('frameLabel').textContent = `frame ${f} / ${mover.frames - 1}`;
  $('panel').innerHTML = panelHtml(data, current, f, frameBreak(m, f), inferred);
  requestRender();
}

function setMover(i) {
  current = Math.max(0, Math.min(i, movers.length - 1));
  $('mover').value = String(current);
  const m = movers[current];
  $('slider').max = String(Math.max((m ? m.mover.frames : 1) - 1, 0));
  show();
}

function setFrame(f) {
  frame = f;
  show();
}

function nextContact() {
  const mover = movers[current].mover;
  for (let f = frame + 1; f < mover.frames; f++)
    if (isContact(mover, f)) { setFrame(f); return f; }
  return -1;
}

let playStart = 0, playFrom = 0;
function tick(t) {
  if (!playing) return;
  const mover = movers[current].mover;
  const dt = mover.dt ? mover.dt[Math.min(frame, mover.frames - 1)] || 1 / 30 : 1 / 30;
  const f = playFrom + Math.floor((t - playStart) / 1000 / dt);
  if (f >= mover.frames - 1) { setFrame(mover.frames - 1); setPlaying(false); return; }
  if (f !== frame) setFrame(f);
  requestAnimationFrame(tick);
}
function setPlaying(on) {
  playing = on && movers.length > 0;
  $('play').textContent = playing ? 'pause' : 'play';
  if (playing) {
    if (frame >= movers[current].mover.frames - 1) frame = 0;
    playStart = performance.now(); playFrom = frame;
    requestAnimationFrame(tick);
  }
}

// ---- controls
data.movers.forEach((mover, i) => {
  const o = document.createElement('option');
  o.value = String(i);
  o.textContent = `${mover.name} (${mover.frames} frames)`;
  $('mover').appendChild(o);
});
$('mover').addEventListener('change', (e) => setMover(Number(e.target.value)));
$('slider').addEventListener('input', (e) => setFrame(Number(e.target.value)));
$('prev').addEventListener('click', () => setFrame(frame - 1));
$('next').addEventListener('click', () => setFrame(frame + 1));
$('play').addEventListener('click', () => setPlaying(!playing));
$('contact').addEventListener('click', () => nextContact());
$('follow').addEventListener('change', () => show());
$('allMovers').addEventListener('change', () => show());
$('byCell').addEventListener('change', (e) => { world.colorByCell(e.target.checked); requestRender(); });
$('showTerrain').addEventListener('change', (e) => { for (const m of terrainMeshes) m.visible = e.target.checked; requestRender(); });
for (const id of ['v3d', 'vtop', 'vside'])
  $(id).addEventListener('click', () => {
    active = id;
    for (const [k, v] of Object.entries(views)) { $(k).classList.toggle('on', k === id); if (v.controls) v.controls.enabled = k === id; }
    requestRender();
  });
window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement && e.target.type !== 'range') return;
  if (e.key === 'ArrowLeft') { setFrame(frame - 1); e.preventDefault(); }
  else if (e.key === 'ArrowRight') { setFrame(frame + 1); e.preventDefault(); }
  else if (e.key === ' ') { setPlaying(!playing); e.preventDefault(); }
  else if (e.key === 'n') nextContact();
});
window.addEventListener('resize', resize);

resize();
setMover(0);
// The first picture is drawn on the next animation frame (requested by setMover): the page, its panel and its controls
// are ready first, while the browser compiles the shaders.

// For tests and the console: read and drive the page.
window.acdreamView = {
  data,
  openedMs: performance.now() - opened,
  setMover,
  setFrame,
  nextContact,
  setView(id) { $(id).click(); renderNow(); },
  state: () => ({ mover: current, frame }),
  renderNow() { renderNow(); return lastRenderMs; },
  webgl: !!renderer,
  /** Milliseconds from navigation until the GPU has finished the first picture (reads one pixel back, which waits for it). */
  async firstPicture() {
    await new Promise((r) => requestAnimationFrame(r));
    renderNow();
    const gl = renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    return performance.now();
  },
  hex,
  project(x, y, z) {
    // Where a world point lands on the canvas, in CSS pixels from its top-left.
    const v = new Vector3(x, y, z).project(views[active].camera);
    const r = renderer.domElement.getBoundingClientRect();
    return [(v.x + 1) / 2 * r.width, (1 - v.y) / 2 * r.height];
  },
};
window.acdreamView.readyMs = performance.now();
document.body.dataset.ready = 'true';
