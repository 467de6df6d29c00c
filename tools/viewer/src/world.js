// The world's collision shapes as three.js objects: polygons (by source, with the backs of one-sided polygons in their
// own colour), cylinders and spheres; each colourable by cell id; objects grouped by id so a hit can light them up.
import {
  BackSide, BufferGeometry, Color, CylinderGeometry, DoubleSide, Float32BufferAttribute, FrontSide, Group,
  LineBasicMaterial, LineSegments, Mesh, MeshLambertMaterial, SphereGeometry, EdgesGeometry,
} from 'three';
import { BACK_FACE, HIT, NON_COLLIDING, SOURCES, cellColor } from './colors.js';

const OPACITY = { terrain: 1, cell: 0.45, building: 0.45, object: 0.6, portal: 0.3 };

function shapeColor(shape) {
  if (shape.source === 'object' && !shape.collides) return NON_COLLIDING;
  return SOURCES[shape.source].color;
}

function material(color, side, opacity) {
  return new MeshLambertMaterial({
    color, side, vertexColors: true, transparent: opacity < 1, opacity, depthWrite: opacity >= 1,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
  });
}

/** Polygons of one kind, gathered into one mesh (two for one-sided polygons: front and back). */
class PolygonBatch {
  constructor() { this.front = []; this.colorsBySource = []; this.colorsByCell = []; this.edges = []; }
  add(shape, v) {
    const n = v.length / 3;
    const a = new Color(shapeColor(shape));
    const b = new Color(cellColor(shape.cell));
    for (let i = 1; i + 1 < n; i++) {
      for (const k of [0, i, i + 1]) {
        this.front.push(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
        this.colorsBySource.push(a.r, a.g, a.b);
        this.colorsByCell.push(b.r, b.g, b.b);
      }
    }
    for (let k = 0; k < n; k++) {
      const j = (k + 1) % n;
      this.edges.push(v[3 * k], v[3 * k + 1], v[3 * k + 2], v[3 * j], v[3 * j + 1], v[3 * j + 2]);
    }
  }
  build(group, source, twoSided, byCell) {
    if (this.front.length === 0) return null;
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(this.front, 3));
    const bySource = new Float32BufferAttribute(this.colorsBySource, 3);
    const cells = new Float32BufferAttribute(this.colorsByCell, 3);
    geometry.setAttribute('color', byCell ? cells : bySource);
    geometry.computeVertexNormals();
    const opacity = OPACITY[source];
    const meshes = [];
    if (twoSided) {
      meshes.push(new Mesh(geometry, material('#ffffff', DoubleSide, opacity)));
    } else {
      meshes.push(new Mesh(geometry, material('#ffffff', FrontSide, opacity)));
      const back = material(BACK_FACE, BackSide, Math.min(opacity, 0.5));
      back.vertexColors = false;
      meshes.push(new Mesh(geometry, back));
    }
    for (const m of meshes) { m.userData.source = source; group.add(m); }
    const edges = new BufferGeometry();
    edges.setAttribute('position', new Float32BufferAttribute(this.edges, 3));
    const lines = new LineSegments(edges, new LineBasicMaterial({ color: source === 'terrain' ? '#a0b090' : '#333333', transparent: true, opacity: 0.6 }));
    group.add(lines);
    return { geometry, bySource, cells, meshes, lines };
  }
}

/** Builds the world group; returns it with the handles the page needs (cell colouring, hit highlight, cell outlines). */
export function buildWorld(data) {
  const group = new Group();
  const batches = new Map();
  const objectGroups = new Map();
  const cellEdges = new Map();
  const built = [];
  const batchOf = (key) => { if (!batches.has(key)) batches.set(key, new PolygonBatch()); return batches.get(key); };
  for (const shape of data.shapes) {
    if (shape.form === 'polygon') {
      const v = shape.vertices;
      if (shape.source === 'cell' || shape.source === 'portal') {
        let e = cellEdges.get(shape.cell);
        if (!e) { e = []; cellEdges.set(shape.cell, e); }
        const n = v.length / 3;
        for (let k = 0; k < n; k++) {
          const j = (k + 1) % n;
          e.push(v[3 * k], v[3 * k + 1], v[3 * k + 2], v[3 * j], v[3 * j + 1], v[3 * j + 2]);
        }
      }
      if (shape.source === 'object') {
        let og = objectGroups.get(shape.object);
        if (!og) { og = { batches: new Map(), meshes: [] }; objectGroups.set(shape.object, og); }
        const key = `${shape.collides}|${shape.sides === 'single'}`;
        if (!og.batches.has(key)) og.batches.set(key, { batch: new PolygonBatch(), shape });
        og.batches.get(key).batch.add(shape, v);
      } else {
        batchOf(`${shape.source}|${shape.sides === 'single'}`).add(shape, v);
      }
    } else {
      const color = shapeColor(shape);
      let geometry;
      if (shape.form === 'cylinder') {
        geometry = new CylinderGeometry(shape.radius, shape.radius, shape.height, 24, 1, false);
        geometry.rotateX(Math.PI / 2); // three's cylinders stand on Y; the world's on Z
        geometry.translate(shape.center[0], shape.center[1], shape.center[2] + shape.height / 2);
      } else {
        geometry = new SphereGeometry(shape.radius, 20, 14);
        geometry.translate(shape.center[0], shape.center[1], shape.center[2]);
      }
      const mesh = new Mesh(geometry, new MeshLambertMaterial({ color, transparent: true, opacity: shape.collides ? 0.55 : 0.3, depthWrite: false }));
      mesh.userData.baseColor = color;
      const edges = new LineSegments(new EdgesGeometry(geometry, 30), new LineBasicMaterial({ color: '#1f3f7f', transparent: true, opacity: 0.5 }));
      group.add(mesh, edges);
      let og = objectGroups.get(shape.object);
      if (!og) { og = { batches: new Map(), meshes: [] }; objectGroups.set(shape.object, og); }
      og.meshes.push(mesh);
    }
  }
  for (const [key, batch] of batches) {
    const [source, single] = key.split('|');
    const b = batch.build(group, source, single !== 'true', false);
    if (b) built.push(b);
  }
  for (const og of objectGroups.values())
    for (const { batch } of og.batches.values()) {
      const b = batch.build(group, 'object', false, false);
      if (b) { built.push(b); og.meshes.push(...b.meshes.filter((m) => m.material.vertexColors)); }
    }
  const hitMaterial = new MeshLambertMaterial({ color: HIT, emissive: HIT, emissiveIntensity: 0.4, side: DoubleSide });
  let lit = [];
  return {
    group,
    /** Colours the polygons by their cell id, or back by what they belong to. */
    colorByCell(on) {
      for (const b of built) b.geometry.setAttribute('color', on ? b.cells : b.bySource);
    },
    /** Lights up the shapes of the given object ids (the frame's hits). */
    highlight(ids) {
      for (const [mesh, m] of lit) mesh.material = m;
      lit = [];
      for (const id of ids) {
        const og = objectGroups.get(id);
        if (!og) continue;
        for (const mesh of og.meshes) { lit.push([mesh, mesh.material]); mesh.material = hitMaterial; }
      }
    },
    /** The edges of an indoor cell's polygons and portals, or null. */
    cellEdges(id) {
      const e = cellEdges.get(id);
      if (!e) return null;
      const geometry = new BufferGeometry();
      geometry.setAttribute('position', new Float32BufferAttribute(e, 3));
      return geometry;
    },
    cellIds: [...new Set(data.shapes.filter((s) => s.source === 'cell' || s.source === 'portal').map((s) => s.cell))].sort((a, b) => a - b),
  };
}
