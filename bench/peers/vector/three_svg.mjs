// SPDX-License-Identifier: LGPL-3.0-or-later
// three.js's SVGRenderer (in jsdom) drawing the scenes of bench/vector_peers.py.
//
//   node bench/peers/vector/three_svg.mjs JOBS.json
// JOBS.json: {"jobs": [{"out": "PATH.svg", "width": W, "height": H, "background": [r, g, b],
//   "camera": {"eye": [x, y, z], "look_at": [x, y, z], "up": [x, y, z], "fovy_deg", "near", "far"},
//   "faces": [{"polygon": [[x, y, z], ...], "color": [r, g, b]}, ...]}]}
// Each face is one Mesh (a fan of triangles from its first vertex, one MeshBasicMaterial in its
// colour, front side only: SVGRenderer's defaults, as a user would draw a coloured part), and
// the renderer keeps its defaults (sortElements: painter's order by the mean depth of each
// triangle; overdraw 0.5 px). Writes each SVG and, next to it, PATH.svg.json with the camera's
// matrices as three.js computed them ("clip_from_world", row-major), for the z-buffer reference.
import { readFileSync, writeFileSync } from 'node:fs';
import { JSDOM } from 'jsdom';

const { window } = new JSDOM('<!DOCTYPE html><html><body></body></html>');
globalThis.window = window;
globalThis.document = window.document;

const THREE = await import('three');
const { SVGRenderer } = await import('three/addons/renderers/SVGRenderer.js');

function colour(rgb) {
  return new THREE.Color().setRGB(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255, THREE.SRGBColorSpace);
}

function rowMajor(m) {
  const e = m.elements; // column-major
  const r = [];
  for (let i = 0; i < 4; ++i) for (let j = 0; j < 4; ++j) r.push(e[4 * j + i]);
  return r;
}

const doc = JSON.parse(readFileSync(process.argv[2], 'utf8'));
for (const job of doc.jobs) {
  const scene = new THREE.Scene();
  scene.background = colour(job.background);
  for (const face of job.faces) {
    const p = face.polygon;
    const positions = [];
    for (let i = 1; i + 1 < p.length; ++i) positions.push(...p[0], ...p[i], ...p[i + 1]);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    scene.add(new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color: colour(face.color) })));
  }
  const c = job.camera;
  const camera = new THREE.PerspectiveCamera(c.fovy_deg, job.width / job.height, c.near, c.far);
  camera.position.set(...c.eye);
  camera.up.set(...c.up);
  camera.lookAt(...c.look_at);
  camera.updateMatrixWorld();
  camera.updateProjectionMatrix();
  const renderer = new SVGRenderer();
  renderer.setSize(job.width, job.height);
  renderer.render(scene, camera);
  const svg = new window.XMLSerializer().serializeToString(renderer.domElement);
  writeFileSync(job.out, svg);
  const clip = new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
  writeFileSync(job.out + '.json', JSON.stringify({ clip_from_world: rowMajor(clip), faces: renderer.info.render.faces }));
}
