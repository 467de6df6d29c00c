// The viewer's colours and what they mean (docs/viewer.md lists the same; keep the two together).

/** Outcome colours, in the order of the tool's ViewOutcome (the plot's colours, the step split up and down). */
export const OUTCOMES = [
  { name: 'moved', color: '#2ca02c' },
  { name: 'slid', color: '#ff7f0e' },
  { name: 'stepped up', color: '#9467bd' },
  { name: 'stepped down', color: '#8c564b' },
  { name: 'refused', color: '#d62728' },
  { name: 'airborne', color: '#17becf' },
];

/** World shapes by what they belong to. */
export const SOURCES = {
  terrain: { name: 'terrain', color: '#c9d8b6' },
  cell: { name: 'indoor cell polygon', color: '#8a8a8a' },
  building: { name: 'building shell', color: '#b08050' },
  object: { name: 'object shape', color: '#4f7fcf' },
  portal: { name: 'portal (not collided)', color: '#f2d24b' },
};

export const BACK_FACE = '#e377c2';      // the back of a one-sided polygon
export const NON_COLLIDING = '#9fb6dd';  // an object shape its dispatch rung never tests (dashed in the plot)
export const HIT = '#ffd000';            // the object(s) the frame collided with
export const MOVER = '#1f3fbf';          // the selected mover's spheres
export const OTHER_MOVER = '#7f7f7f';    // the other movers' spheres
export const CONTACT_PLANE = '#17becf';  // the contact plane under the mover
export const COLLISION_NORMAL = '#d62728';
export const SLIDING_NORMAL = '#ff7f0e';
export const HEADING = '#000000';
export const TARGET = '#000000';
export const REPORT = '#e377c2';         // a reported (interpolateTo) position
export const CELL_OUTLINE = '#ff00ff';   // the frame's cell
export const PATH_AHEAD = '#cccccc';     // the path still to come
export const BACKGROUND = '#ffffff';

/** A stable colour for a cell id (cells coloured by id): the id hashed to a hue. */
export function cellColor(id) {
  let h = id >>> 0;
  h = Math.imul(h ^ (h >>> 16), 0x45d9f3b) >>> 0;
  h = Math.imul(h ^ (h >>> 16), 0x45d9f3b) >>> 0;
  const hue = (h % 360);
  return `hsl(${hue}, 65%, 55%)`;
}
