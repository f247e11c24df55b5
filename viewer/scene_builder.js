// Builds the three.js objects of a scene.json (docs/viewer.md, "scene.json"): one group per
// part, holding its graphics and marker triads in part (body-frame) coordinates, so that
// placing the group at the part's pose from the .res places everything on it.
import * as THREE from 'three';

// A rotation matrix given row by row (9 numbers) and a position, as a Matrix4.
export function frameMatrix(position, rows) {
  const r = rows;
  return new THREE.Matrix4().set(r[0], r[1], r[2], position[0], r[3], r[4], r[5], position[1],
                                 r[6], r[7], r[8], position[2], 0, 0, 0, 1);
}

// The pose of a part from X Y Z PSI THETA PHI: body-fixed 3-1-3 angles, A = Rz(psi) Rx(theta)
// Rz(phi) (docs/theory.md, the part coordinates).
export function poseMatrix(p) {
  const rz = (a) => new THREE.Matrix4().makeRotationZ(a);
  const m = new THREE.Matrix4().makeTranslation(p[0], p[1], p[2]);
  return m.multiply(rz(p[3])).multiply(new THREE.Matrix4().makeRotationX(p[4])).multiply(rz(p[5]));
}

// CYLINDER and FRUSTUM: three's cylinder lies along y about its middle; ADAMS's grows from the
// CM marker along z (to -z for a negative LENGTH), its angle measured from the marker x axis.
function roundGeometry(g, top, bottom) {
  const len = Math.abs(g.length), sign = g.length < 0 ? -1 : 1;  // LENGTH 0: a disc
  const geo = new THREE.CylinderGeometry(top, bottom, len, Math.max(3, g.sides), 1,
                                         g.rangle < 2 * Math.PI - 1e-9, Math.PI / 2, g.rangle);
  geo.rotateX(sign * Math.PI / 2);
  geo.translate(0, 0, g.length / 2);
  return geo;
}

function curvePoints(g) {
  const n = Math.max(3, g.sides), pts = [];
  const closed = g.kind === 'CIRCLE';
  for (let i = 0; i <= n; ++i) {
    if (closed && i === n) break;
    const a = (g.rangle * i) / n;
    pts.push(new THREE.Vector3(g.radius * Math.cos(a), g.radius * Math.sin(a), 0));
  }
  return pts;
}

// The three.js object of one graphic, in its reference marker's frame (or, for OUTLINE, in
// part coordinates); null for an OUTLINE spanning parts (scene.moving lines redraw those).
function graphicObject(g, material, lineMaterial) {
  let obj;
  switch (g.kind) {
    case 'CYLINDER': obj = new THREE.Mesh(roundGeometry(g, g.radius, g.radius), material); break;
    case 'FRUSTUM': obj = new THREE.Mesh(roundGeometry(g, g.top, g.bottom), material); break;
    case 'BOX': {
      const e = g.extents;
      const geo = new THREE.BoxGeometry(Math.abs(e[0]), Math.abs(e[1]), Math.abs(e[2]));
      geo.translate(e[0] / 2, e[1] / 2, e[2] / 2);
      obj = new THREE.Mesh(geo, material);
      break;
    }
    case 'ELLIPSOID': {
      const geo = new THREE.SphereGeometry(0.5, 32, 16);
      geo.scale(g.diameters[0], g.diameters[1], g.diameters[2]);
      obj = new THREE.Mesh(geo, material);
      break;
    }
    case 'ARC':
    case 'CIRCLE': {
      const geo = new THREE.BufferGeometry().setFromPoints(curvePoints(g));
      obj = g.kind === 'CIRCLE' ? new THREE.LineLoop(geo, lineMaterial) : new THREE.Line(geo, lineMaterial);
      break;
    }
    case 'OUTLINE': {
      if (g.points.some((p) => p.part !== g.part)) return null;
      const pts = g.points.map((p) => new THREE.Vector3(...p.position));
      return new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), lineMaterial);
    }
    default: return null;
  }
  obj.matrixAutoUpdate = false;
  obj.matrix.copy(frameMatrix(g.position, g.orientation));
  return obj;
}

// opts: colorOf(partId) -> THREE.Color, flat (unlit materials), triadSize (0: none),
// hideGround. Returns {root, groups: Map part id -> Group, outlines: [{line, points}]}.
export function buildScene(scene, opts) {
  const root = new THREE.Group();
  const groups = new Map();
  for (const p of scene.parts) {
    const group = new THREE.Group();
    group.matrixAutoUpdate = false;
    group.matrix.copy(frameMatrix(p.position, p.orientation));
    group.userData.initial = group.matrix.clone();
    group.visible = !(p.ground && opts.hideGround);
    groups.set(p.id, group);
    root.add(group);
  }
  const materials = new Map();
  const ground = new Set(scene.parts.filter((p) => p.ground).map((p) => p.id));
  const materialOf = (partId) => {
    if (!materials.has(partId)) {
      const color = opts.colorOf(partId);
      // Ground graphics (housings, cylinders) are see-through in the normal view, so the
      // parts moving inside them stay visible.
      const glass = !opts.flat && ground.has(partId);
      const mesh = opts.flat ? new THREE.MeshBasicMaterial({ color })
                             : new THREE.MeshStandardMaterial({ color, metalness: 0.1, roughness: 0.6,
                                                                side: THREE.DoubleSide, transparent: glass,
                                                                opacity: glass ? 0.3 : 1,
                                                                depthWrite: !glass });
      materials.set(partId, { mesh, line: new THREE.LineBasicMaterial({ color }) });
    }
    return materials.get(partId);
  };
  const outlines = [];
  for (const g of scene.graphics) {
    const m = materialOf(g.part);
    const obj = graphicObject(g, m.mesh, m.line);
    if (obj) {
      obj.userData.graphic = g.id;
      groups.get(g.part)?.add(obj);
    } else if (g.kind === 'OUTLINE') {
      const geo = new THREE.BufferGeometry().setFromPoints(g.points.map(() => new THREE.Vector3()));
      const line = new THREE.Line(geo, m.line);
      root.add(line);
      outlines.push({ line, points: g.points });
    }
  }
  if (opts.triadSize > 0) {
    for (const mk of scene.markers) {
      const axes = new THREE.AxesHelper(opts.triadSize);
      axes.matrixAutoUpdate = false;
      axes.matrix.copy(frameMatrix(mk.position, mk.orientation));
      axes.userData.triad = true;
      groups.get(mk.part)?.add(axes);
    }
  }
  return { root, groups, outlines };
}

// Places every part at frame `k` of the results (parts the results do not list keep their
// initial pose) and redraws the OUTLINEs that span parts.
export function placeParts(built, results, k) {
  for (const [id, group] of built.groups) {
    const poses = results && results.poses.get(id);
    group.matrix.copy(poses ? poseMatrix(poses[k]) : group.userData.initial);
    group.matrixWorldNeedsUpdate = true;
  }
  for (const o of built.outlines) {
    const pos = o.line.geometry.attributes.position;
    o.points.forEach((p, i) => {
      const v = new THREE.Vector3(...p.position).applyMatrix4(built.groups.get(p.part).matrix);
      pos.setXYZ(i, v.x, v.y, v.z);
    });
    pos.needsUpdate = true;
  }
}
