// The segslam map viewer: loads a run's description from /api/run, then its point clouds and
// trajectories, and draws them with three.js. window.segslamViewer is the hook the browser test
// uses to wait for the map and read what is drawn.
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { parsePly } from "./ply.js";
import { parseTum } from "./tum.js";

const COLOURS = {
  static: 0x9aa0aa, estimate: 0xff8c1a, ground_truth: 0x3ad17a, keyframes: 0x4aa3ff, dynamic: 0xff3b6b,
  occupied: 0xc9a227, floor_grid: 0x6fd3ff,
};
const LABEL_PALETTE = [0xe6194b, 0x3cb44b, 0xffe119, 0x4363d8, 0xf58231, 0x911eb4, 0x46f0f0,
  0xf032e6, 0xbcf60c, 0xfabebe, 0x008080, 0xe6beff, 0x9a6324, 0xaaffc3, 0x808000, 0xffd8b1];

const view = document.getElementById("view");
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x15171c);
const camera = new THREE.PerspectiveCamera(55, 1, 0.01, 500);
const controls = new OrbitControls(camera, renderer.domElement);
// Camera frames are x right, y down, z forward; turning the world half a turn about x shows the
// first camera's view upright and looking into the screen.
const world = new THREE.Group();
world.rotation.x = Math.PI;
scene.add(world);

const layers = new Map();   // name -> { object, points, checkbox }
const objects = new Map();  // id -> { label, cloud, box, points }
const state = { ready: false, error: null, run: null };

function render() {
  renderer.render(scene, camera);
}

function resize() {
  const { clientWidth: width, clientHeight: height } = view;
  renderer.setSize(width, height);
  camera.aspect = width / Math.max(height, 1);
  camera.updateProjectionMatrix();
  render();
}

async function fetchOk(url, kind) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return kind === "json" ? response.json() : kind === "text" ? response.text() : response.arrayBuffer();
}

function pointCloud(ply, size, tint) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(ply.positions, 3));
  const coloured = !tint && ply.colours;
  if (coloured) geometry.setAttribute("color", new THREE.BufferAttribute(ply.colours, 3));
  const material = new THREE.PointsMaterial({ size, sizeAttenuation: false, vertexColors: !!coloured });
  if (!coloured) material.color = new THREE.Color(tint ?? 0xcccccc);
  return new THREE.Points(geometry, material);
}

function trajectoryLine(poses, colour) {
  const positions = new Float32Array(poses.flatMap((pose) => pose.position));
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
  return new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: colour }));
}

function keyframeMarkers(poses) {
  const positions = new Float32Array(poses.flatMap((pose) => pose.position));
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
  return new THREE.Points(geometry, new THREE.PointsMaterial({ size: 7, sizeAttenuation: false, color: COLOURS.keyframes }));
}

// Labels get palette colours in alphabetical order, so a run's labels stay distinct.
const labelColours = new Map();

function labelColour(label) {
  return labelColours.get(label) ?? 0xcccccc;
}

function assignLabelColours(labels) {
  [...new Set(labels)].sort().forEach((label, index) => {
    labelColours.set(label, LABEL_PALETTE[index % LABEL_PALETTE.length]);
  });
}

function swatch(colour) {
  const span = document.createElement("span");
  span.className = "swatch";
  span.style.background = `#${colour.toString(16).padStart(6, "0")}`;
  return span;
}

function checkboxRow(text, colour, onChange, attributes = {}) {
  const label = document.createElement("label");
  const box = document.createElement("input");
  box.type = "checkbox";
  box.checked = true;
  for (const [key, value] of Object.entries(attributes)) box.dataset[key] = value;
  box.addEventListener("change", () => onChange(box.checked));
  label.append(box);
  if (colour !== null) label.append(swatch(colour));
  label.append(text);
  return { label, box };
}

function addLayer(name, text, object, points, colour) {
  world.add(object);
  const row = checkboxRow(text, colour, (on) => {
    object.visible = on;
    update();
  }, { layer: name });
  document.getElementById("layers").append(row.label);
  layers.set(name, { object, points, checkbox: row.box });
}

// Objects by label, the label of the largest object first, each label's objects largest first,
// with the share of the keyframes that saw the object which agreed on its label.
function objectsByLabel() {
  const byLabel = new Map();
  const largestFirst = [...objects].sort(([, a], [, b]) => b.points - a.points);
  for (const [id, entry] of largestFirst) {
    if (!byLabel.has(entry.label)) byLabel.set(entry.label, []);
    byLabel.get(entry.label).push(id);
  }
  return byLabel;
}

function objectRow(id, onChange) {
  const { points, dynamic, confidence, keyframes } = objects.get(id);
  const row = checkboxRow(`${id}${dynamic ? " (dynamic)" : ""} `, null, onChange, { object: id });
  const count = document.createElement("span");
  count.className = "count";
  count.textContent = points.toLocaleString();
  row.label.append(count);
  if (confidence !== undefined) {
    const agreement = document.createElement("span");
    agreement.className = "confidence";
    agreement.textContent = ` ${Math.round(100 * confidence)} %`;
    agreement.title = `${Math.round(100 * confidence)} % of the ${keyframes} keyframes that saw it call it ${objects.get(id).label}`;
    row.label.append(agreement);
  }
  return row;
}

function addObjectControls() {
  const container = document.getElementById("objects");
  const byLabel = objectsByLabel();
  if (byLabel.size) container.replaceChildren();
  for (const [label, ids] of byLabel) {
    const instances = document.createElement("div");
    instances.className = "instances";
    const boxes = [];
    const group = checkboxRow(`${label} (${ids.length})`, labelColour(label), (on) => {
      for (const box of boxes) box.checked = on;
      for (const id of ids) setObjectVisible(id, on);
      update();
    }, { label });
    const syncGroup = () => {
      const shown = boxes.filter((box) => box.checked).length;
      group.box.checked = shown === boxes.length;
      group.box.indeterminate = shown > 0 && shown < boxes.length;
    };
    for (const id of ids) {
      const row = objectRow(id, (on) => {
        setObjectVisible(id, on);
        syncGroup();
        update();
      });
      boxes.push(row.box);
      instances.append(row.label);
    }
    container.append(group.label, instances);
  }
}

function setObjectVisible(id, on) {
  const entry = objects.get(id);
  entry.cloud.visible = on;
  entry.box.visible = on && boxesShown();
}

function boxesShown() {
  return !layers.has("boxes") || layers.get("boxes").object.visible;
}

function stats() {
  const visible = (name) => (layers.has(name) && layers.get(name).object.visible ? layers.get(name).points : 0);
  const labels = {};
  let objectPoints = 0;
  for (const entry of objects.values()) {
    const shown = entry.cloud.visible ? entry.points : 0;
    labels[entry.label] = (labels[entry.label] ?? 0) + shown;
    objectPoints += shown;
  }
  const result = { static: visible("static"), dynamic: visible("dynamic"), objects: objectPoints, labels };
  result.total = result.static + result.dynamic + result.objects;
  result.trajectories = {
    estimate: visible("estimate"), ground_truth: visible("ground_truth"), keyframes: visible("keyframes"),
  };
  result.occupancy = { voxels: visible("occupied"), grid_cells: visible("floor_grid") };
  return result;
}

function update() {
  for (const entry of objects.values()) entry.box.visible = entry.cloud.visible && boxesShown();
  const s = stats();
  const parts = [`${s.static.toLocaleString()} static`, `${s.dynamic.toLocaleString()} dynamic`,
    `${s.objects.toLocaleString()} on objects`];
  document.getElementById("status").textContent = state.run?.map
    ? `${s.total.toLocaleString()} points drawn (${parts.join(", ")})`
    : `${s.trajectories.estimate} poses, ${s.trajectories.keyframes} keyframes drawn`;
  render();
}

function fitCamera() {
  const box = new THREE.Box3().setFromObject(world);
  if (box.isEmpty()) return;
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 0.1);
  // From behind and above the first camera, close enough for the map to fill the view.
  camera.position.copy(centre).add(new THREE.Vector3(0.3, 0.7, 1.2).normalize().multiplyScalar(radius * 1.7));
  camera.near = radius / 100;
  camera.far = radius * 100;
  camera.updateProjectionMatrix();
  controls.target.copy(centre);
  controls.update();
}

async function loadTrajectories(trajectories) {
  const entries = [["estimate", "Estimated trajectory"], ["ground_truth", "Ground truth (aligned)"],
    ["keyframes", "Keyframes"]];
  for (const [name, text] of entries) {
    if (!trajectories[name]) continue;
    const poses = parseTum(await fetchOk(trajectories[name], "text"), trajectories[name]);
    const object = name === "keyframes" ? keyframeMarkers(poses) : trajectoryLine(poses, COLOURS[name]);
    addLayer(name, `${text} (${poses.length})`, object, poses.length, COLOURS[name]);
  }
}

// The edges of an object's oriented box (objects.json: centre, extent, axes as rows).
function orientedBox({ centre, extent, axes }, colour) {
  const edges = new THREE.EdgesGeometry(new THREE.BoxGeometry(...extent));
  const box = new THREE.LineSegments(edges, new THREE.LineBasicMaterial({ color: colour }));
  const [r0, r1, r2] = axes;
  box.matrixAutoUpdate = false;
  box.matrix.set(r0[0], r0[1], r0[2], centre[0], r1[0], r1[1], r1[2], centre[1], r2[0], r2[1], r2[2], centre[2], 0, 0, 0, 1);
  return box;
}

async function loadMap(map) {
  const size = 2;
  if (map.static) {
    const ply = parsePly(await fetchOk(map.static, "buffer"), map.static);
    addLayer("static", `Static map (${ply.count.toLocaleString()})`, pointCloud(ply, size), ply.count, COLOURS.static);
  }
  if (map.dynamic) {
    const ply = parsePly(await fetchOk(map.dynamic, "buffer"), map.dynamic);
    addLayer("dynamic", `Dynamic layer (${ply.count.toLocaleString()})`, pointCloud(ply, size + 1, COLOURS.dynamic),
      ply.count, COLOURS.dynamic);
  }
  const boxes = new THREE.Group();
  assignLabelColours(map.objects.map((object) => object.label));
  for (const object of map.objects) {
    const ply = parsePly(await fetchOk(object.url, "buffer"), object.url);
    const colour = labelColour(object.label);
    const cloud = pointCloud(ply, size + 1, colour);
    const box = object.oriented_box ? orientedBox(object.oriented_box, colour)
      : new THREE.Box3Helper(new THREE.Box3().setFromBufferAttribute(cloud.geometry.getAttribute("position")), colour);
    world.add(cloud);
    boxes.add(box);
    objects.set(object.id, {
      label: object.label, dynamic: object.dynamic, confidence: object.confidence, keyframes: object.keyframes,
      cloud, box, points: ply.count,
    });
  }
  if (map.objects.length) addLayer("boxes", "Object boxes", boxes, 0, null);
  addObjectControls();
  await loadOccupancy(map.occupancy);
}

// An 8-bit binary PGM (P5), as map_server reads the floor grid: { width, height, pixels }.
function parsePgm(buffer, url) {
  const bytes = new Uint8Array(buffer);
  const fields = [];
  let at = 0;
  while (fields.length < 4 && at < bytes.length) {
    while (at < bytes.length && /\s/.test(String.fromCharCode(bytes[at]))) at += 1;
    if (bytes[at] === 0x23) {  // a comment runs to the end of its line
      while (at < bytes.length && bytes[at] !== 0x0a) at += 1;
      continue;
    }
    let field = "";
    while (at < bytes.length && !/\s/.test(String.fromCharCode(bytes[at]))) field += String.fromCharCode(bytes[at++]);
    fields.push(field);
  }
  const [magic, width, height, maximum] = [fields[0], Number(fields[1]), Number(fields[2]), Number(fields[3])];
  if (magic !== "P5" || !(width > 0) || !(height > 0) || maximum > 255) throw new Error(`${url}: not an 8-bit binary PGM`);
  const pixels = bytes.subarray(at + 1, at + 1 + width * height);
  if (pixels.length !== width * height) throw new Error(`${url}: cut short`);
  return { width, height, pixels };
}

// Occupied voxels as cubes of the map's resolution, shaded by height along the floor's up.
function voxelCubes(ply, info) {
  const size = info.resolution_m;
  const mesh = new THREE.InstancedMesh(new THREE.BoxGeometry(size, size, size),
    new THREE.MeshBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.55 }), ply.count);
  const up = new THREE.Vector3(...info.grid.up);
  const heights = [];
  for (let i = 0; i < ply.count; ++i) heights.push(up.dot(new THREE.Vector3(...ply.positions.slice(3 * i, 3 * i + 3))));
  const low = Math.min(...heights);
  const span = Math.max(Math.max(...heights) - low, 1e-6);
  const matrix = new THREE.Matrix4();
  const colour = new THREE.Color();
  for (let i = 0; i < ply.count; ++i) {
    matrix.makeTranslation(ply.positions[3 * i], ply.positions[3 * i + 1], ply.positions[3 * i + 2]);
    mesh.setMatrixAt(i, matrix);
    mesh.setColorAt(i, colour.setHSL(0.12 - 0.12 * (heights[i] - low) / span, 0.75, 0.5));
  }
  return mesh;
}

// The floor grid as a textured plane at the floor's height: occupied cells dark red, free ones
// pale green, unknown ones left out.
function floorGridPlane(pgm, info) {
  const { rows, cols, resolution_m: cell, origin, u_axis: u, v_axis: v, up, floor_height_m: floor } = info.grid;
  const rgba = new Uint8Array(rows * cols * 4);
  let occupied = 0;
  for (let row = 0; row < rows; ++row) {
    for (let col = 0; col < cols; ++col) {
      const value = pgm.pixels[row * cols + col];
      // Texture rows run from the plane's bottom (low v) up; the image's from the top.
      const at = 4 * ((rows - 1 - row) * cols + col);
      if (value === 0) {
        rgba.set([200, 40, 40, 230], at);
        occupied += 1;
      } else if (value === 254) {
        rgba.set([120, 220, 140, 110], at);
      }
    }
  }
  const texture = new THREE.DataTexture(rgba, cols, rows, THREE.RGBAFormat);
  texture.magFilter = THREE.NearestFilter;
  texture.needsUpdate = true;
  const plane = new THREE.Mesh(new THREE.PlaneGeometry(cols * cell, rows * cell),
    new THREE.MeshBasicMaterial({ map: texture, transparent: true, side: THREE.DoubleSide, depthWrite: false }));
  // The plane's x, y, z axes are the grid's u, v and up; its centre the grid's centre.
  const basis = new THREE.Matrix4().makeBasis(new THREE.Vector3(...u), new THREE.Vector3(...v), new THREE.Vector3(...up));
  const centre = new THREE.Vector3(...u).multiplyScalar(origin[0] + cols * cell / 2)
    .add(new THREE.Vector3(...v).multiplyScalar(origin[1] + rows * cell / 2))
    .add(new THREE.Vector3(...up).multiplyScalar(floor));
  plane.applyMatrix4(basis.setPosition(centre));
  return { plane, occupied };
}

async function loadOccupancy(occupancy) {
  if (!occupancy) return;
  const info = await fetchOk(occupancy.info, "json");
  const ply = parsePly(await fetchOk(occupancy.voxels, "buffer"), occupancy.voxels);
  addLayer("occupied", `Occupied voxels (${ply.count.toLocaleString()}, ${info.resolution_m} m)`,
    voxelCubes(ply, info), ply.count, COLOURS.occupied);
  if (occupancy.grid) {
    const pgm = parsePgm(await fetchOk(occupancy.grid, "buffer"), occupancy.grid);
    const { plane, occupied } = floorGridPlane(pgm, info);
    addLayer("floor_grid", `Floor grid (${pgm.width} x ${pgm.height}, ${occupied.toLocaleString()} obstacle cells)`,
      plane, pgm.width * pgm.height, COLOURS.floor_grid);
  }
}

// A layer per session of a saved map (map_sessions/ of the run): the map points and keyframe
// centres each session made, in the session's colour (written by system::writeSessionLayers).
async function loadSessions(sessions) {
  for (const { session, points, keyframes } of sessions ?? []) {
    const cloud = parsePly(await fetchOk(points, "buffer"), points);
    const centres = parsePly(await fetchOk(keyframes, "buffer"), keyframes);
    const group = new THREE.Group();
    group.add(pointCloud(cloud, 3));
    group.add(pointCloud(centres, 8));
    const colour = centres.colours ? new THREE.Color(...centres.colours.slice(0, 3)).getHex()
      : cloud.colours ? new THREE.Color(...cloud.colours.slice(0, 3)).getHex() : null;
    addLayer(`session${session}`,
      `Session ${session}: ${cloud.count.toLocaleString()} points, ${centres.count} keyframes`,
      group, cloud.count, colour);
  }
}

async function load() {
  const run = await fetchOk("/api/run", "json");
  state.run = run;
  document.getElementById("run-name").textContent = run.name;
  document.title = `segslam: ${run.name}`;
  if (!run.map) document.getElementById("notice").textContent = "no map in this run (trajectories only)";
  await loadTrajectories(run.trajectories);
  if (run.map) await loadMap(run.map);
  await loadSessions(run.sessions);
  fitCamera();
  update();
}

window.segslamViewer = { state, stats };
window.addEventListener("resize", resize);
controls.addEventListener("change", render);
resize();
load()
  .catch((error) => {
    state.error = String(error.message ?? error);
    document.getElementById("status").textContent = `error: ${state.error}`;
  })
  .finally(() => {
    state.ready = true;
  });
