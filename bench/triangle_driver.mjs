// triangle_driver.mjs — Shewchuk's Triangle (npm `triangle-wasm`, Triangle 1.6 compiled to WebAssembly by
// Emscripten, run by node) on the bench's PSLG: the regular 64-gon inscribed in the unit circle, its 64 sides as
// segments, quality switch -q<angle> (20.7° = asin(1/(2B)) for B = √2) and an area bound -a<area>.
//
//   node bench/triangle_driver.mjs NODE_MODULES_DIR calibrate TARGET_VERTICES [ANGLE]
//       prints {"area": A, "vertices": V}: A scaled (V ∝ 1/A) until V is within 1% of the target
//   node bench/triangle_driver.mjs NODE_MODULES_DIR run AREA REPEATS [ANGLE]
//       prints {"vertices", "seconds" (best CPU time of the triangulate() call), "wall", "minAngle", "meanMinAngle"}
//       or {"error": "..."} when the wasm module aborts (its heap is fixed at 16 MiB: about 45k vertices)
//
// Timed: the triangulate() call only (Triangle builds the constrained Delaunay triangulation of the PSLG and refines
// it), not the copies of the input into and of the output out of the wasm heap. CPU time is process.cpuUsage()
// (user + system of the node process). Angles are computed from the output after the timing.
// Bench only: bench/bench_refine_peers.sh installs the package into a bench folder; nothing here is a build or test
// dependency.
import { createRequire } from 'node:module';
import path from 'node:path';

const [nodeModules, mode, arg1, arg2, arg3] = process.argv.slice(2);
const require = createRequire(path.join(path.resolve(nodeModules), 'noop.js'));
const Triangle = require('triangle-wasm');

const kPolygon = 64;
const angle = Number((mode === 'calibrate' ? arg2 : arg3) ?? 20.7);

function polygon() {
  const pointlist = new Float64Array(2 * kPolygon);
  const segmentlist = new Int32Array(2 * kPolygon);
  for (let i = 0; i < kPolygon; ++i) {
    pointlist[2 * i] = Math.cos((2 * Math.PI * i) / kPolygon);
    pointlist[2 * i + 1] = Math.sin((2 * Math.PI * i) / kPolygon);
    segmentlist[2 * i] = i;
    segmentlist[2 * i + 1] = (i + 1) % kPolygon;
  }
  return { pointlist, segmentlist };
}

// Smallest angle and mean per-triangle smallest angle, degrees.
function quality(points, tris) {
  let minA = 180, sum = 0;
  const nt = tris.length / 3;
  for (let t = 0; t < nt; ++t) {
    let smallest = 180;
    for (let k = 0; k < 3; ++k) {
      const a = tris[3 * t + k], b = tris[3 * t + ((k + 1) % 3)], c = tris[3 * t + ((k + 2) % 3)];
      const ux = points[2 * b] - points[2 * a], uy = points[2 * b + 1] - points[2 * a + 1];
      const vx = points[2 * c] - points[2 * a], vy = points[2 * c + 1] - points[2 * a + 1];
      const ang = (Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180) / Math.PI;
      smallest = Math.min(smallest, ang);
    }
    minA = Math.min(minA, smallest);
    sum += smallest;
  }
  return { minAngle: minA, meanMinAngle: sum / nt };
}

// One triangulation; returns the outcome (quality only when asked, after the timing).
function runOnce(area, withQuality) {
  const input = Triangle.makeIO(polygon());
  const output = Triangle.makeIO();
  const switches = `pzQq${angle}a${area.toPrecision(17)}`;
  const c0 = process.cpuUsage();
  const w0 = process.hrtime.bigint();
  Triangle.triangulate(switches, input, output);
  const w1 = process.hrtime.bigint();
  const c1 = process.cpuUsage(c0);
  const out = {
    vertices: output.numberofpoints,
    seconds: (c1.user + c1.system) * 1e-6,
    wall: Number(w1 - w0) * 1e-9,
  };
  if (withQuality) Object.assign(out, quality(output.pointlist, output.trianglelist));
  Triangle.freeIO(input, true);
  Triangle.freeIO(output);
  return out;
}

function calibrate(target) {
  let area = Math.PI / (0.5 * target);  // ≈ 2 triangles per vertex
  let v = 0;
  for (let it = 0; it < 10; ++it) {
    v = runOnce(area, false).vertices;
    const ratio = v / target;
    if (Math.abs(ratio - 1) < 0.01) break;
    area *= ratio;
  }
  return { area, vertices: v };
}

function run(area, repeats) {
  let best = null;
  for (let i = 0; i < repeats; ++i) {
    const o = runOnce(area, i === 0);
    if (best === null) best = o;
    else if (o.seconds < best.seconds) Object.assign(best, { seconds: o.seconds, wall: o.wall });
  }
  return best;
}

// Node ≥ 18 has a global fetch(), which the 2020 Emscripten loader then tries on a file path and fails; without it
// the loader reads the .wasm from disk (fs.readFileSync).
globalThis.fetch = undefined;
await Triangle.init();
try {
  const result = mode === 'calibrate' ? calibrate(Number(arg1)) : run(Number(arg1), Number(arg2 ?? 5));
  console.log(JSON.stringify(result));
} catch (e) {
  console.log(JSON.stringify({ error: String(e && e.message ? e.message : e) }));
}
