// Reading the page's data (written by the tool's ViewData; docs/viewer.md, "The page's data").

export const FLAG = { contact: 1, onWalkable: 2, contactPlaneValid: 4, collisionNormalValid: 8, slidingNormalValid: 16, succeeded: 32 };

export function hex(id) {
  return '0x' + (id >>> 0).toString(16).toUpperCase().padStart(8, '0');
}

/** The offset of a cell's landblock into the view's frame. */
export function blockOffset(data, cell) {
  const o = data.landblocks[String(cell >>> 16)];
  return o || [0, 0, 0];
}

/** A mover's frame position in the view's frame. */
export function drawPosition(data, mover, f) {
  const o = blockOffset(data, mover.cell[f]);
  const p = mover.position;
  return [p[3 * f] + o[0], p[3 * f + 1] + o[1], p[3 * f + 2] + o[2]];
}

export function vec(column, f) {
  return [column[3 * f], column[3 * f + 1], column[3 * f + 2]];
}

export function quat(column, f) {
  return [column[4 * f], column[4 * f + 1], column[4 * f + 2], column[4 * f + 3]];
}

/** A frame with a contact: a collision normal recorded or an object hit. */
export function isContact(mover, f) {
  return (mover.flags[f] & FLAG.collisionNormalValid) !== 0 || mover.collided[f].length > 0;
}

/** The compass heading of a [w, x, y, z] rotation: degrees clockwise from +Y of its forward (+Y) axis. */
export function heading(q) {
  const [w, x, y, z] = q;
  // forward = rotate (0, 1, 0)
  const fx = 2 * (x * y - w * z);
  const fy = 1 - 2 * (x * x + z * z);
  let d = Math.atan2(fx, fy) * 180 / Math.PI;
  if (d < 0) d += 360;
  return d;
}

/** Rotates v by the [w, x, y, z] quaternion q. */
export function rotate(q, v) {
  const [w, x, y, z] = q;
  const [vx, vy, vz] = v;
  const tx = 2 * (y * vz - z * vy), ty = 2 * (z * vx - x * vz), tz = 2 * (x * vy - y * vx);
  return [vx + w * tx + (y * tz - z * ty), vy + w * ty + (z * tx - x * tz), vz + w * tz + (x * ty - y * tx)];
}
