// The OpenMSS viewer page (docs/viewer.md): draws the model's GRAPHICS from /scene.json,
// animates the parts from /result.res, plots a request beside the 3-D view.
//
// URL parameters (the browser test uses them; docs/viewer.md, "Test mode"):
//   test=1            flat unlit colours, white background, no triads, no side panel; the
//                     picture is also written as a PNG data URL into <pre id="shot">
//   w=800&h=600       test mode: the size of the picture
//   frame=N           the frame shown first
//   cam=ex,ey,ez,tx,ty,tz  camera position and target (up is +y); fov=degrees (vertical)
//   colors=ID:RRGGBB,...   the colour of each part
//   hideground=1      the ground part's graphics are not drawn
import * as THREE from 'three';
import { OrbitControls } from './OrbitControls.js';
import { parseRes } from './res_reader.js';
import { buildScene, placeParts } from './scene_builder.js';
import { drawPlot } from './plot.js';

const params = new URLSearchParams(location.search);
const test = params.get('test') === '1';
const $ = (id) => document.getElementById(id);
if (test) document.body.classList.add('test');

const PALETTE = [0xc0504d, 0x4f81bd, 0x9bbb59, 0xf79646, 0x8064a2, 0x4bacc6, 0xd4a017, 0x7f7f7f];

function partColors(scene) {
  const given = new Map();
  for (const item of (params.get('colors') || '').split(',').filter(Boolean)) {
    const [id, hex] = item.split(':');
    given.set(Number(id), new THREE.Color(Number.parseInt(hex, 16)));
  }
  const colors = new Map();
  let k = 0;
  for (const p of scene.parts)
    colors.set(p.id, given.get(p.id) || new THREE.Color(p.ground ? 0xa0a4aa : PALETTE[k++ % PALETTE.length]));
  return (id) => colors.get(id) || new THREE.Color(0x888888);
}

async function load() {
  const scene = await (await fetch('scene.json')).json();
  let results = null;
  try {
    const r = await fetch('result.res');
    if (!r.ok) throw new Error('HTTP ' + r.status);
    results = parseRes(await r.text());
  } catch (e) {
    $('error').textContent = 'No results to animate: ' + e.message;
  }
  return { scene, results };
}

function setUpView(scene, results) {
  const container = $('view');
  const renderer = new THREE.WebGLRenderer({ antialias: !test, preserveDrawingBuffer: test });
  renderer.setPixelRatio(test ? 1 : window.devicePixelRatio);
  container.appendChild(renderer.domElement);
  const three = new THREE.Scene();
  three.background = new THREE.Color(test ? 0xffffff : 0xeef1f5);
  const built0 = buildScene(scene, { colorOf: partColors(scene), flat: test, triadSize: 0,
                                     hideGround: params.get('hideground') === '1' });
  three.add(built0.root);
  placeParts(built0, results, 0);
  built0.root.updateMatrixWorld(true);
  const box = new THREE.Box3().setFromObject(built0.root);
  const size = box.isEmpty() ? 1 : box.getSize(new THREE.Vector3()).length();
  const center = box.isEmpty() ? new THREE.Vector3() : box.getCenter(new THREE.Vector3());
  if (!test) {  // marker triads at 4 % of the model's size, behind a checkbox
    three.remove(built0.root);
    const withTriads = buildScene(scene, { colorOf: partColors(scene), flat: false,
                                           triadSize: 0.04 * size, hideGround: false });
    Object.assign(built0, withTriads);
    three.add(built0.root);
    three.add(new THREE.HemisphereLight(0xffffff, 0x667788, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(1, 2, 3);
    three.add(sun);
  }
  const fov = Number(params.get('fov') || 35);
  const camera = new THREE.PerspectiveCamera(fov, 1, size / 1000, size * 100);
  const cam = (params.get('cam') || '').split(',').map(Number);
  let target = center;
  if (cam.length === 6 && cam.every(Number.isFinite)) {
    camera.position.set(cam[0], cam[1], cam[2]);
    target = new THREE.Vector3(cam[3], cam[4], cam[5]);
  } else {
    const dir = new THREE.Vector3(0.35, 0.45, 1).normalize();
    camera.position.copy(center).addScaledVector(dir, (0.7 * size) / Math.tan((fov * Math.PI) / 360));
  }
  camera.up.set(0, 1, 0);
  camera.lookAt(target);
  const controls = test ? null : new OrbitControls(camera, renderer.domElement);
  if (controls) controls.target.copy(target);
  const resize = () => {
    // Test mode: the size the URL gives (w, h), whatever the window's size.
    const w = test ? Number(params.get('w') || 800) : container.clientWidth;
    const h = test ? Number(params.get('h') || 600) : container.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  };
  resize();
  window.addEventListener('resize', resize);
  return { renderer, three, camera, controls, built: built0 };
}

function setUpPlot(results, frameOf) {
  const reqSel = $('request'), compSel = $('component');
  const requests = results ? results.requests : [];
  requests.forEach((r, i) => reqSel.add(new Option(r.name, String(i))));
  const fillComponents = () => {
    compSel.length = 0;
    const r = requests[Number(reqSel.value)];
    if (r) r.components.forEach((c, i) => compSel.add(new Option(c.name, String(i))));
    // The first component that changes over the run (a request's first is often a constant).
    const moving = r ? r.components.findIndex((c) => Math.min(...c.values) !== Math.max(...c.values)) : -1;
    if (moving > 0) compSel.value = String(moving);
  };
  const draw = () => {
    const canvas = $('plot');
    canvas.width = canvas.clientWidth;
    canvas.height = canvas.clientHeight;
    const r = requests[Number(reqSel.value)];
    const c = r && r.components[Number(compSel.value)];
    if (!c) return drawPlot(canvas, [], [], '', -1);
    const units = c.units ? ' [' + c.units + ']' : '';
    drawPlot(canvas, results.times, c.values, r.name + ': ' + c.name + units, frameOf());
  };
  reqSel.onchange = () => { fillComponents(); draw(); };
  compSel.onchange = draw;
  fillComponents();
  window.addEventListener('resize', draw);
  return draw;
}

async function main() {
  const { scene, results } = await load();
  $('title').textContent = scene.title;
  const view = setUpView(scene, results);
  const frames = results ? results.times.length : 1;
  let frame = Math.min(Math.max(0, Number(params.get('frame') || 0)), frames - 1);
  const slider = $('slider');
  slider.max = String(frames - 1);
  const drawPlotNow = setUpPlot(results, () => frame);
  const show = (k) => {
    frame = k;
    slider.value = String(k);
    const t = results ? results.times[k] : 0;
    $('time').textContent = 't = ' + t.toPrecision(6) + ' ' + (scene.units.time || '').toLowerCase();
    placeParts(view.built, results, k);
    view.renderer.render(view.three, view.camera);
    if (!test) drawPlotNow();
  };
  slider.oninput = () => show(Number(slider.value));
  $('triads').onchange = (e) => view.built.root.traverse((o) => {
    if (o.userData.triad) o.visible = e.target.checked;
  });
  let playing = false, startWall = 0, startTime = 0;
  $('play').onclick = () => {
    playing = !playing && frames > 1;
    $('play').textContent = playing ? 'Pause' : 'Play';
    startWall = performance.now();
    startTime = results ? results.times[frame] : 0;
  };
  const tick = () => {
    if (playing) {  // real-time playback, looping at the end
      const times = results.times, span = times[frames - 1] - times[0];
      let t = startTime + (performance.now() - startWall) / 1000;
      if (t > times[frames - 1]) { startWall = performance.now(); startTime = times[0]; t = times[0]; }
      let k = frame;
      while (k + 1 < frames && times[k + 1] <= t) ++k;
      if (t < times[k]) k = 0;
      if (span > 0 && k !== frame) show(k);
    }
    if (view.controls) { view.controls.update(); view.renderer.render(view.three, view.camera); }
    requestAnimationFrame(tick);
  };
  show(frame);
  if (test) {
    // The rendered picture as a PNG data URL in the page, where `chromium --dump-dom` reads
    // it: the exact pixels of the 3-D view, whatever the headless window's chrome.
    $('shot').textContent = view.renderer.domElement.toDataURL('image/png');
    $('shot').dataset.time = String(results ? results.times[frame] : 0);
    $('shot').dataset.frame = String(frame);
    document.title = 'ready';
  } else {
    requestAnimationFrame(tick);
  }
}

main().catch((e) => { $('error').textContent = String(e.stack || e); document.title = 'error: ' + e; });
