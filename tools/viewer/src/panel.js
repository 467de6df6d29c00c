// The side panel: one frame's state, the numbers exactly as the trajectory holds them (each number is the shortest
// text of the recorded float, as the trajectory file writes it; JavaScript prints that same text back).
import { OUTCOMES } from './colors.js';
import { FLAG, heading, hex, quat, vec } from './data.js';

function esc(text) {
  return String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));
}

function row(field, label, value, numeric = true) {
  return `<tr><td>${esc(label)}</td><td data-field="${field}"${numeric ? ' class="num"' : ''}>${esc(value)}</td></tr>`;
}

const v3 = (v) => v.map(String).join(' ');
const yes = (b) => (b ? 'yes' : 'no');

/** The panel's HTML for frame f of mover m. */
export function panelHtml(data, m, f, breakJump, inferred) {
  const mover = data.movers[m];
  const flags = mover.flags[f];
  const rows = [];
  rows.push(row('mover', 'mover', `${mover.name} (${mover.kind})`, false));
  rows.push(row('frame', 'frame', `${f} of ${mover.frames - 1}`, false));
  rows.push(row('outcome', 'outcome', OUTCOMES[mover.outcome[f]].name, false));
  if (breakJump !== null) rows.push(row('break', 'path break', `jumped ${breakJump.toFixed(2)} m (blip or teleport)`, false));
  rows.push(row('position', 'position', v3(vec(mover.position, f))));
  rows.push(row('cell', 'cell', hex(mover.cell[f])));
  if (mover.targetOrigin) {
    rows.push(row('targetOrigin', 'target', v3(vec(mover.targetOrigin, f))));
    rows.push(row('targetCell', 'target cell', hex(mover.targetCell[f])));
  }
  if (mover.velocity) {
    rows.push(row('velocity', 'velocity', v3(vec(mover.velocity, f))));
    rows.push(row('dt', 'elapsed (s)', String(mover.dt[f])));
    rows.push(row('desiredVelocity', 'desired velocity', v3(vec(mover.desiredVelocity, f))));
    rows.push(row('jump', 'jump', String(mover.jump[f])));
    rows.push(row('quanta', 'quanta', String(mover.quanta[f])));
  }
  rows.push(row('contact', 'contact', yes(flags & FLAG.contact), false));
  rows.push(row('onWalkable', 'walkable', yes(flags & FLAG.onWalkable), false));
  rows.push(row('succeeded', 'move accepted', yes(flags & FLAG.succeeded), false));
  rows.push(row('contactPlaneValid', 'contact plane', yes(flags & FLAG.contactPlaneValid), false));
  rows.push(row('contactNormal', '  normal', v3(vec(mover.contactNormal, f))));
  rows.push(row('contactD', '  d', String(mover.contactD[f])));
  rows.push(row('contactCell', '  cell', hex(mover.contactCell[f])));
  rows.push(row('collisionNormalValid', 'collision normal', yes(flags & FLAG.collisionNormalValid), false));
  rows.push(row('collisionNormal', '  vector', v3(vec(mover.collisionNormal, f))));
  rows.push(row('slidingNormalValid', 'sliding', yes(flags & FLAG.slidingNormalValid), false));
  rows.push(row('slidingNormal', '  normal', v3(vec(mover.slidingNormal, f))));
  rows.push(row('collided', 'hit objects', mover.collided[f].length ? mover.collided[f].map(hex).join(' ') : '-'));
  if (inferred > 0) rows.push(row('inferredHit', 'hit polygon', `${inferred} lit (inferred from the normal)`, false));
  if (mover.rotation) {
    const name = (id, speed) => (id === 0 ? '-' : `${data.commandNames[String(id)] ?? hex(id)} x${speed}`);
    rows.push(row('heading', 'heading (deg)', heading(quat(mover.rotation, f)).toFixed(1)));
    rows.push(row('rotation', 'rotation w x y z', quat(mover.rotation, f).map(String).join(' ')));
    rows.push(row('style', 'style', data.commandNames[String(mover.style[f])] ?? hex(mover.style[f]), false));
    rows.push(row('forward', 'forward', name(mover.forward[f], mover.forwardSpeed[f]), false));
    rows.push(row('sideStep', 'side step', name(mover.sideStep[f], mover.sideStepSpeed[f]), false));
    rows.push(row('turn', 'turn', name(mover.turn[f], mover.turnSpeed[f]), false));
  }
  for (const hit of mover.missileHits)
    if (hit.frame === f) rows.push(row('missileHit', 'missile hit', `${hit.kind} ${hex(hit.object)} (quantum ${hit.quantum})`, false));
  return `<h2>${esc(data.scene)}</h2><table>${rows.join('')}</table>`;
}
