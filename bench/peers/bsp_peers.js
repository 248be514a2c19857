#!/usr/bin/env node
// SPDX-License-Identifier: LGPL-3.0-or-later
// Times the BSP trees of two JavaScript CSG libraries on exbsp's benchmark meshes.
//
//   node bsp_peers.js MESH.off [MESH.off ...] [--repeat N] [--cap SECONDS]
//
// Notation: a "triangle" is one input triangle after exbsp's loading rules (docs/contract.md §2:
// faces fan-triangulated from their first vertex, exactly collinear triangles skipped); a
// "piece" is one polygon stored in a node of the built tree (both libraries store convex
// polygons, split further as the tree grows); "pieces_triangulated" counts a stored k-gon as
// k-2 triangles, the unit exbsp stores, so it is the figure to set beside exbsp's fragments.
//
// Each (tool, mesh) pair runs in its own worker thread with a large stack (csg.js builds
// recursively) and a heap limit, so a stack overflow, an out-of-memory or a time-out becomes
// {"error": ...} for that pair instead of ending the run. Output: one JSON object per line.
'use strict';

const fs = require('fs');
const path = require('path');
const { Worker, isMainThread, parentPort, workerData } = require('worker_threads');

const STACK_MB = 512;      // thread stack of a worker: csg.js recurses once per tree level
const HEAP_MB = 8192;      // old-generation limit of a worker; beyond it the pair reports an error

// ---------------------------------------------------------------------------------------------
// OFF reader. Hand-written because no maintained npm package reads OFF with exbsp's rules
// (strict counts, line numbers in errors, fan triangulation, exact degeneracy test).

class InputError extends Error {}

/// Reads an ASCII OFF file into a Float64Array of triangles (9 doubles each, file order).
/// Throws InputError naming the file and line on any syntax error, NaN/Inf or bad index.
function read_off(file) {
  let text;
  try {
    text = fs.readFileSync(file, 'utf8');
  } catch (e) {
    throw new InputError(`${file}: cannot read: ${e.message}`);
  }
  const lines = text.split('\n');
  let li = 0;
  let tokens = [];
  let ti = 0;
  // next non-empty, comment-stripped line as tokens; returns false at end of file
  const next_line = () => {
    while (li < lines.length) {
      const s = lines[li++].replace(/#.*/, '').trim();
      if (s.length) { tokens = s.split(/\s+/); ti = 0; return true; }
    }
    return false;
  };
  const fail = (msg) => { throw new InputError(`${file}:${li}: ${msg}`); };
  const need_line = (what) => { if (!next_line()) fail(`unexpected end of file, expected ${what}`); };
  const int_tok = (tok, what) => {
    if (!/^[+]?\d+$/.test(tok)) fail(`expected a non-negative integer (${what}), got '${tok}'`);
    return Number(tok);
  };
  const num_tok = (tok) => {
    if (!/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(tok)) fail(`expected a number, got '${tok}'`);
    const v = Number(tok);   // nearest double to the decimal text (ECMAScript ToNumber)
    if (!Number.isFinite(v)) fail(`coordinate '${tok}' is not finite`);
    return v;
  };

  need_line('OFF header');
  if (tokens[0] !== 'OFF') fail(`expected 'OFF' header, got '${tokens[0]}'`);
  if (tokens.length > 1) ti = 1; else need_line('vertex, face and edge counts');
  const counts = tokens.slice(ti);
  if (counts.length !== 3) fail(`expected 3 counts (vertices faces edges), got ${counts.length}`);
  const nv = int_tok(counts[0], 'vertex count');
  const nf = int_tok(counts[1], 'face count');
  int_tok(counts[2], 'edge count');

  const xyz = new Float64Array(3 * nv);
  for (let i = 0; i < nv; i++) {
    need_line(`vertex ${i}`);
    if (tokens.length < 3) fail(`vertex ${i}: expected 3 coordinates, got ${tokens.length}`);
    for (let c = 0; c < 3; c++) xyz[3 * i + c] = num_tok(tokens[c]);
  }
  const tris = [];
  let degenerate = 0;
  for (let f = 0; f < nf; f++) {
    need_line(`face ${f}`);
    const k = int_tok(tokens[0], 'face size');
    if (k < 3) fail(`face ${f}: ${k} vertices, at least 3 needed`);
    if (tokens.length < 1 + k) fail(`face ${f}: expected ${k} vertex indices, got ${tokens.length - 1}`);
    const idx = [];
    for (let j = 0; j < k; j++) {
      const v = int_tok(tokens[1 + j], 'vertex index');
      if (v >= nv) fail(`face ${f}: vertex index ${v} out of range (${nv} vertices)`);
      idx.push(v);
    }
    for (let j = 1; j + 1 < k; j++) {           // fan from the first vertex (docs/contract.md §2)
      const t = [idx[0], idx[j], idx[j + 1]];
      const p = [];
      for (const v of t) p.push(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
      if (exactly_collinear(p)) { degenerate++; continue; }
      tris.push(...p);
    }
  }
  if (next_line()) fail(`unexpected content after ${nf} faces: '${tokens.join(' ')}'`);
  return { triangles: Float64Array.from(tris), degenerate };
}

// Exact collinearity of a triangle's three double points: a double filter, then integer
// arithmetic on BigInt (every double is an integer times 2^-1074). Neither library has an
// exact test; exbsp skips exactly degenerate triangles, so the input counts must agree.
function exactly_collinear(p) {
  const d = [p[3] - p[0], p[4] - p[1], p[5] - p[2], p[6] - p[0], p[7] - p[1], p[8] - p[2]];
  const cr = [d[1] * d[5] - d[2] * d[4], d[2] * d[3] - d[0] * d[5], d[0] * d[4] - d[1] * d[3]];
  const mag = [Math.abs(d[1] * d[5]) + Math.abs(d[2] * d[4]), Math.abs(d[2] * d[3]) + Math.abs(d[0] * d[5]),
    Math.abs(d[0] * d[4]) + Math.abs(d[1] * d[3])];
  // rounding of the 6 differences and 3 products and the subtraction: well under 8 ulp relative
  for (let i = 0; i < 3; i++) if (Math.abs(cr[i]) > 8 * Number.EPSILON * mag[i]) return false;
  const b = p.map(to_scaled_bigint);
  const e = [b[3] - b[0], b[4] - b[1], b[5] - b[2], b[6] - b[0], b[7] - b[1], b[8] - b[2]];
  return e[1] * e[5] === e[2] * e[4] && e[2] * e[3] === e[0] * e[5] && e[0] * e[4] === e[1] * e[3];
}

// x * 2^1074 as an exact BigInt (finite doubles only)
function to_scaled_bigint(x) {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const hi = view.getUint32(0), lo = view.getUint32(4);
  const sign = hi >>> 31 ? -1n : 1n;
  const exp = (hi >>> 20) & 0x7ff;
  let mant = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  if (exp !== 0) mant |= 1n << 52n;
  const shift = BigInt(exp === 0 ? 0 : exp - 1);   // value = mant * 2^(max(exp,1) - 1075)
  return sign * (mant << shift);
}

// ---------------------------------------------------------------------------------------------
// The two tools. Each: setup(triangles) builds the library's polygons (not timed, fresh for
// every repeat so no cache carries over), build(polys) is the timed tree build, count(tree)
// walks the tree iteratively and returns [pieces, pieces_triangulated].

const TOOLS = {
  'csg.js': {
    package: 'csg',
    setup(tri) {
      const CSG = require('csg');
      const polys = [];
      for (let i = 0; i < tri.length; i += 9) {
        polys.push(new CSG.Polygon([
          new CSG.Vertex([tri[i], tri[i + 1], tri[i + 2]], [0, 0, 0]),
          new CSG.Vertex([tri[i + 3], tri[i + 4], tri[i + 5]], [0, 0, 0]),
          new CSG.Vertex([tri[i + 6], tri[i + 7], tri[i + 8]], [0, 0, 0])]));  // computes the plane
      }
      return polys;
    },
    build(polys) {
      const CSG = require('csg');
      return new CSG.Node(polys);
    },
    count(root) {
      let pieces = 0, tris = 0;
      const stack = [root];
      while (stack.length) {
        const n = stack.pop();
        pieces += n.polygons.length;
        for (const p of n.polygons) tris += p.vertices.length - 2;
        if (n.front) stack.push(n.front);
        if (n.back) stack.push(n.back);
      }
      return [pieces, tris];
    },
  },
  jscad: {
    package: '@jscad/modeling',
    setup(tri) {
      const { poly3 } = require('@jscad/modeling').geometries;
      const polys = [];
      for (let i = 0; i < tri.length; i += 9) {
        const p = poly3.create([[tri[i], tri[i + 1], tri[i + 2]], [tri[i + 3], tri[i + 4], tri[i + 5]],
          [tri[i + 6], tri[i + 7], tri[i + 8]]]);
        poly3.plane(p);   // cached on the polygon, as csg.js computes its plane at construction
        polys.push(p);
      }
      return polys;
    },
    build(polys) {
      // JSCAD's booleans (unionGeom3Sub, subtractGeom3Sub, intersectGeom3Sub) build `new Tree(polygons)`
      const Tree = require('@jscad/modeling/src/operations/booleans/trees/Tree');
      return new Tree(polys);
    },
    count(tree) {
      // pieces live in BSP nodes (Node.polygontreenodes); cross-check against the leaves of the
      // polygon tree, which records every split
      let pieces = 0, tris = 0;
      const stack = [tree.rootnode];
      while (stack.length) {
        const n = stack.pop();
        for (const t of n.polygontreenodes) {
          if (t.isRemoved()) continue;
          pieces++;
          tris += t.getPolygon().vertices.length - 2;
        }
        if (n.front) stack.push(n.front);
        if (n.back) stack.push(n.back);
      }
      let leaves = 0;
      const q = [tree.polygonTree];
      while (q.length) {
        const t = q.pop();
        if (t.children.length) q.push(...t.children); else if (t.polygon && t.parent) leaves++;
      }
      if (leaves !== pieces) throw new Error(`jscad: ${pieces} pieces in BSP nodes but ${leaves} polygon-tree leaves`);
      return [pieces, tris];
    },
  },
};

function version_of(pkg) {
  return require(`${pkg}/package.json`).version;
}

// ---------------------------------------------------------------------------------------------
// Worker: one (tool, mesh) pair.

// The same protocol as exbsp's side of the comparison (bench/run.py: one counted build, then
// the median of the timed rounds): one untimed warm-up build, which also lets V8 compile the
// hot code, then `repeat` timed builds; the medians are reported, the best wall time beside.
function run_pair({ tool, triangles, repeat }) {
  const t = TOOLS[tool];
  const median = (xs) => {
    const s = [...xs].sort((a, b) => a - b);
    const h = s.length >> 1;
    return s.length % 2 ? s[h] : (s[h - 1] + s[h]) / 2;
  };
  const walls = [], cpus = [];
  let tree = t.build(t.setup(triangles));  // warm-up, untimed
  for (let r = 0; r < repeat; r++) {
    const polys = t.setup(triangles);
    tree = null;
    const c0 = process.cpuUsage();
    const t0 = process.hrtime.bigint();
    tree = t.build(polys);
    const t1 = process.hrtime.bigint();
    const c1 = process.cpuUsage(c0);
    walls.push(Number(t1 - t0) / 1e9);
    cpus.push((c1.user + c1.system) / 1e6);
  }
  const [pieces, pieces_triangulated] = t.count(tree);
  return { build_seconds: median(walls), build_cpu_seconds: median(cpus),
    build_seconds_best: Math.min(...walls), pieces, pieces_triangulated };
}

if (!isMainThread) {
  try {
    parentPort.postMessage({ ok: run_pair(workerData) });
  } catch (e) {
    parentPort.postMessage({ error: `${e.name}: ${e.message}` });
  }
  return;
}

// ---------------------------------------------------------------------------------------------
// Main thread.

function usage(msg) {
  process.stderr.write(`bsp_peers: error: ${msg}\n` +
    'usage: node bsp_peers.js MESH.off [MESH.off ...] [--repeat N] [--cap SECONDS]\n');
  process.exit(2);
}

function parse_args(argv) {
  const opts = { meshes: [], repeat: 3, cap: 300 };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--repeat' || a === '--cap') {
      const v = argv[++i];
      if (v === undefined || !/^\d+$/.test(v) || Number(v) < 1) usage(`${a} needs a positive integer`);
      opts[a.slice(2)] = Number(v);
    } else if (a.startsWith('--')) {
      usage(`unknown option ${a}`);
    } else {
      opts.meshes.push(a);
    }
  }
  if (!opts.meshes.length) usage('no mesh given');
  return opts;
}

// runs one pair in a worker; resolves to the result fields or {error}
function in_worker(tool, triangles, repeat, cap) {
  return new Promise((resolve) => {
    const w = new Worker(__filename, {
      workerData: { tool, triangles, repeat },
      resourceLimits: { stackSizeMb: STACK_MB, maxOldGenerationSizeMb: HEAP_MB },
    });
    let done = false;
    const finish = (r) => { if (!done) { done = true; clearTimeout(timer); resolve(r); } };
    const timer = setTimeout(() => {
      finish({ error: `time cap: over ${cap} s for ${repeat} build(s)` });
      w.terminate();
    }, cap * 1000);
    w.on('message', (m) => finish(m.ok ? m.ok : { error: m.error }));
    w.on('error', (e) => finish({ error: `${e.code || e.name}: ${e.message}` }));
    w.on('exit', (code) => finish({ error: `worker exited with code ${code}` }));
  });
}

async function main() {
  const opts = parse_args(process.argv.slice(2));
  const versions = {};
  for (const [name, t] of Object.entries(TOOLS)) versions[name] = version_of(t.package);
  for (const file of opts.meshes) {
    let mesh;
    try {
      mesh = read_off(file);
    } catch (e) {
      if (!(e instanceof InputError)) throw e;
      process.stderr.write(`bsp_peers: error: ${e.message}\n`);
      process.exit(2);
    }
    const input_triangles = mesh.triangles.length / 9;
    for (const tool of Object.keys(TOOLS)) {
      const r = await in_worker(tool, mesh.triangles, opts.repeat, opts.cap);
      const row = { tool, version: versions[tool], mesh: path.basename(file), input_triangles,
        degenerate_skipped: mesh.degenerate, repeats: opts.repeat, ...r };
      process.stdout.write(JSON.stringify(row) + '\n');
    }
  }
}

main();
