// The page that plays a tissu run (issue 20): the cloth of every recorded frame, orbit and zoom,
// a frame slider, play/pause, wireframe, strain colouring, pins and obstacles, and the stats.csv
// curves against time. Its data, frames.js, is a classic script of calls to window.tissu.* that a
// run appends to frame by frame (lib/viewer_frames.cpp), so that the page works from file:// and
// from a run still going or stopped. Bundled with three.js into one classic script by esbuild
// (viewer/CMakeLists.txt).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";

const run = { name: "", columns: [], frames: [] };

/// Decodes base64 into a typed array of `Type`.
function decode(text, Type) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  return new Type(bytes.buffer);
}

// Called by frames.js: tissu.run(name, columns) once, then tissu.frame({...}) per frame. A frame
// without triangles keeps the previous frame's (its particles did not change).
window.tissu = {
  run(name, columns) {
    run.name = name;
    run.columns = columns;
  },
  frame(f) {
    const previous = run.frames[run.frames.length - 1];
    run.frames.push({
      frame: f.frame,
      stats: f.stats,
      positions: decode(f.positions, Float32Array),
      triangles: f.triangles ? decode(f.triangles, Uint32Array) : previous.triangles,
      strain: decode(f.strain, Float32Array),
      level: f.triangles ? decode(f.level, Float32Array) : previous.level,
      pinned: f.pinned ?? previous.pinned,
      obstacles: (f.obstacles ?? []).map((o) => ({
        positions: decode(o.positions, Float32Array),
        triangles: decode(o.triangles, Uint32Array),
      })),
    });
  },
};

/// The PNG renderer's diverging map (lib/render/renderer.cpp): -10 % full blue, 0 white, +10 %
/// full red, clamped beyond.
function strainColour(strain, colour) {
  const s = Math.min(Math.max(strain / 0.1, -1), 1);
  const blue = new THREE.Color(0.23, 0.3, 0.75);
  const red = new THREE.Color(0.7, 0.02, 0.15);
  return colour.setRGB(0.93, 0.93, 0.93).lerp(s < 0 ? blue : red, Math.abs(s));
}

/// One colour per refinement level: 0 (the input mesh) light, each bisection darker and bluer.
const levelColours = [0xf2d3a0, 0xe8a060, 0xc8643c, 0x8c3c5a, 0x4a3c78, 0x1e3c64].map(
  (c) => new THREE.Color(c),
);
function levelColour(level, colour) {
  return colour.copy(
    levelColours[Math.min(Math.max(Math.round(level), 0), levelColours.length - 1)],
  );
}

function clothGeometry(f, colouring) {
  // one vertex per triangle corner, so that a triangle has one colour
  const count = f.triangles.length;
  const positions = new Float32Array(3 * count);
  const colours = new Float32Array(3 * count);
  const colour = new THREE.Color();
  for (let c = 0; c < count; ++c) {
    const v = f.triangles[c];
    positions.set(f.positions.subarray(3 * v, 3 * v + 3), 3 * c);
    const t = Math.floor(c / 3);
    if (colouring === "strain") strainColour(f.strain[t], colour);
    else if (colouring === "level") levelColour(f.level[t], colour);
    else colour.setRGB(0.85, 0.6, 0.35);
    colour.toArray(colours, 3 * c);
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute("color", new THREE.BufferAttribute(colours, 3));
  geometry.computeVertexNormals();
  return geometry;
}

function indexedGeometry(positions, triangles) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
  geometry.setIndex(new THREE.BufferAttribute(triangles, 1));
  geometry.computeVertexNormals();
  return geometry;
}

/// The stats.csv curves: one small plot per column, a cursor at the shown frame.
function drawPlots(canvas, shown) {
  const columns = ["particles", "kinetic_energy", "potential_energy", "tears"].filter((c) =>
    run.columns.includes(c),
  );
  const context = canvas.getContext("2d");
  const width = canvas.width;
  const height = canvas.height / columns.length;
  context.clearRect(0, 0, canvas.width, canvas.height);
  const time = run.frames.map((f) => f.stats.time);
  columns.forEach((column, k) => {
    const values = run.frames.map((f) => f.stats[column]);
    const [low, high] = [Math.min(...values), Math.max(...values)];
    const x = (t) =>
      40 + ((width - 50) * (t - time[0])) / Math.max(time[time.length - 1] - time[0], 1e-12);
    const y = (v) =>
      k * height + height - 18 - ((height - 34) * (v - low)) / Math.max(high - low, 1e-300);
    context.fillStyle = "#444";
    context.font = "12px sans-serif";
    const value = values[shown];
    context.fillText(
      `${column}  ${Number.isInteger(value) ? value : value.toPrecision(4)}`,
      40,
      k * height + 12,
    );
    context.strokeStyle = "#1f6fb4";
    context.lineWidth = 2;
    context.beginPath();
    values.forEach((v, i) =>
      i ? context.lineTo(x(time[i]), y(v)) : context.moveTo(x(time[i]), y(v)),
    );
    context.stroke();
    context.strokeStyle = "#d33";
    context.beginPath();
    context.moveTo(x(time[shown]), k * height + 16);
    context.lineTo(x(time[shown]), k * height + height - 14);
    context.stroke();
  });
}

function start() {
  const status = document.getElementById("status");
  if (run.frames.length === 0) {
    status.textContent = "no frame recorded yet (frames.js is empty)";
    return;
  }
  document.title = `tissu: ${run.name}`;
  const view = document.getElementById("view");
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  view.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf2f2f2);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(2, -3, 4);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  camera.up.set(0, 0, 1); // tissu's world is z-up
  const controls = new OrbitControls(camera, renderer.domElement);

  const clothMaterial = new THREE.MeshStandardMaterial({
    vertexColors: true,
    side: THREE.DoubleSide,
    roughness: 0.9,
  });
  const cloth = new THREE.Mesh(new THREE.BufferGeometry(), clothMaterial);
  const pins = new THREE.Points(
    new THREE.BufferGeometry(),
    new THREE.PointsMaterial({ color: 0xcc2222, size: 8, sizeAttenuation: false }),
  );
  const obstacles = new THREE.Group();
  scene.add(cloth, pins, obstacles);
  const obstacleMaterial = new THREE.MeshStandardMaterial({ color: 0x8899aa, roughness: 0.6 });

  // the camera frames the first frame's cloth, from the front (-y) and a little above
  const box = new THREE.Box3().setFromBufferAttribute(
    new THREE.BufferAttribute(run.frames[0].positions, 3),
  );
  const centre = box.getCenter(new THREE.Vector3());
  const size = Math.max(box.getSize(new THREE.Vector3()).length(), 0.1);
  camera.position.copy(centre).add(new THREE.Vector3(0.3 * size, -1.6 * size, 0.5 * size));
  controls.target.copy(centre);
  controls.update();

  const slider = document.getElementById("frame");
  const colouring = document.getElementById("colouring");
  const wireframe = document.getElementById("wireframe");
  const play = document.getElementById("play");
  const plots = document.getElementById("plots");
  slider.max = run.frames.length - 1;

  function show(index) {
    const f = run.frames[index];
    cloth.geometry.dispose();
    cloth.geometry = clothGeometry(f, colouring.value);
    clothMaterial.wireframe = wireframe.checked;
    const pinned = new Float32Array(3 * f.pinned.length);
    f.pinned.forEach((v, k) => pinned.set(f.positions.subarray(3 * v, 3 * v + 3), 3 * k));
    pins.geometry.dispose();
    pins.geometry = new THREE.BufferGeometry().setAttribute(
      "position",
      new THREE.BufferAttribute(pinned, 3),
    );
    obstacles.children.forEach((o) => o.geometry.dispose());
    obstacles.clear();
    f.obstacles.forEach((o) =>
      obstacles.add(new THREE.Mesh(indexedGeometry(o.positions, o.triangles), obstacleMaterial)),
    );
    const time = f.stats.time.toFixed(3);
    status.textContent =
      `frame ${f.frame} (${index + 1} of ${run.frames.length}), ` +
      `t = ${time} s, ${f.stats.particles} particles`;
    status.dataset.frame = f.frame;
    drawPlots(plots, index);
  }
  const current = () => Number(slider.value);
  slider.oninput = () => show(current());
  colouring.onchange = wireframe.onchange = () => show(current());
  let playing = null;
  play.onclick = () => {
    if (playing) {
      clearInterval(playing);
      playing = null;
      play.textContent = "play";
      return;
    }
    play.textContent = "pause";
    const frameRate =
      run.frames.length > 1
        ? (run.frames.length - 1) /
          (run.frames[run.frames.length - 1].stats.time - run.frames[0].stats.time)
        : 30;
    playing = setInterval(
      () => {
        slider.value = (current() + 1) % run.frames.length;
        show(current());
      },
      1000 / Math.min(frameRate, 60),
    );
  };

  function resize() {
    const width = view.clientWidth;
    const height = view.clientHeight;
    renderer.setSize(width, height);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
  }
  window.addEventListener("resize", resize);
  resize();

  // #frame=N (a frame number, or "last") and #colouring=strain select what is shown first
  const options = new URLSearchParams(window.location.hash.slice(1));
  if (options.get("colouring")) colouring.value = options.get("colouring");
  const asked = options.get("frame");
  const index =
    asked === "last"
      ? run.frames.length - 1
      : run.frames.findIndex((f) => String(f.frame) === asked);
  slider.value = Math.max(index, 0);
  show(current());
  renderer.setAnimationLoop(() => renderer.render(scene, camera));
}

window.addEventListener("load", start);
