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
  // The planes of the cell, building and object polygons, to find the polygon a collision normal came from.
  const planes = [];
  for (const shape of data.shapes) {
    if (shape.form !== 'polygon' || shape.source === 'portal' || shape.source === 'terrain') continue;
    const v = shape.vertices;
    const ax = v[3] - v[0], ay = v[4] - v[1], az = v[5] - v[2], bx = v[6] - v[0], by = v[7] - v[1], bz = v[8] - v[2];
    let nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    const len = Math.hypot(nx, ny, nz);
    if (!(len > 0)) continue;
    nx /= len; ny /= len; nz /= len;
    planes.push({ shape, n: [nx, ny, nz], d: -(nx * v[0] + ny * v[1] + nz * v[2]) });
  }
  const hitPolygon = new Mesh(new BufferGeometry(), hitMaterial);
  hitPolygon.visible = false;
  group.add(hitPolygon);
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
    /**
     * The polygons a collision normal most likely came from (a trajectory records the normal, not the polygon): those
     * facing along the normal (either way for a two-sided one) whose plane passes within a sphere's radius and 0.25 m of
     * one of the mover's sphere centres, with the centre over the polygon (its edges pushed out as far). Lit up; returns
     * how many.
     */
    inferHit(normal, centres, radius) {
      const found = [];
      for (const { shape, n, d } of planes) {
        const dot = n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2];
        if (!(dot > 0.999 || (shape.sides !== 'single' && dot < -0.999))) continue;
        const reach = radius + 0.25;
        const near = centres.some((c) => {
          const h = n[0] * c[0] + n[1] * c[1] + n[2] * c[2] + d;
          if (Math.abs(h) > reach) return false;
          const v = shape.vertices, k = v.length / 3;
          for (let i = 0; i < k; i++) {
            const j = (i + 1) % k;
            const ex = v[3 * j] - v[3 * i], ey = v[3 * j + 1] - v[3 * i + 1], ez = v[3 * j + 2] - v[3 * i + 2];
            // The edge's outward direction in the polygon's plane: edge × normal (counter-clockwise from the front).
            let ox = ey * n[2] - ez * n[1], oy = ez * n[0] - ex * n[2], oz = ex * n[1] - ey * n[0];
            const ol = Math.hypot(ox, oy, oz);
            if (!(ol > 0)) continue;
            ox /= ol; oy /= ol; oz /= ol;
            if ((c[0] - v[3 * i]) * ox + (c[1] - v[3 * i + 1]) * oy + (c[2] - v[3 * i + 2]) * oz > reach) return false;
          }
          return true;
        });
        if (near) found.push(shape);
      }
      const triangles = [];
      for (const shape of found) {
        const v = shape.vertices, k = v.length / 3;
        for (let i = 1; i + 1 < k; i++)
          for (const m of [0, i, i + 1]) triangles.push(v[3 * m], v[3 * m + 1], v[3 * m + 2]);
      }
      hitPolygon.geometry.dispose();
      hitPolygon.geometry = new BufferGeometry();
      hitPolygon.geometry.setAttribute('position', new Float32BufferAttribute(triangles, 3));
      hitPolygon.visible = triangles.length > 0;
      return found.length;
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
