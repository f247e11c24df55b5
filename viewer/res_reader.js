// Reads an XRF results file (.res; docs/output-files.md and docs/viewer.md, "Reading the
// .res") in the browser with DOMParser. Returns the output times, each part's X Y Z PSI THETA
// PHI per frame and each request's components per frame.
//
// Frames are the <Step> elements of every <Data> block in document order, except the
// type="input" step (the model's input values, not a solution). The numbers of a step are in
// component-id order: the value of the component with id k is the k-th number (id 1 is TIME).

// The data-set id of a Part entity: the last integer of its entity name (PART_2, PART_2_XFORM
// give 2), else its objectId.
export function entityId(el) {
  const name = (el.getAttribute('entity') || el.getAttribute('name') || '').replace(/_XFORM$/, '');
  const m = name.match(/(\d+)$/);
  if (m) return Number(m[1]);
  const o = el.getAttribute('objectId');
  return o === null ? NaN : Number(o);
}

function components(el) {
  const out = [];
  for (const c of el.getElementsByTagName('Component'))
    out.push({ name: c.getAttribute('name'), id: Number(c.getAttribute('id')),
               units: c.getAttribute('unitsValue') || '' });
  return out;
}

export function parseRes(text) {
  const doc = new DOMParser().parseFromString(text, 'application/xml');
  if (doc.getElementsByTagName('parsererror').length)
    throw new Error('the results file is not well-formed XML');
  const parts = new Map();  // part id -> {X, Y, ..., PHI: component ids}
  const requests = [];
  for (const e of doc.getElementsByTagName('Entity')) {
    const type = e.getAttribute('entType');
    if (type === 'Part') {
      const ids = {};
      for (const c of components(e)) ids[c.name] = c.id;
      if (['X', 'Y', 'Z', 'PSI', 'THETA', 'PHI'].every((k) => k in ids)) parts.set(entityId(e), { ids });
    } else if (type === 'Request') {
      requests.push({ name: e.getAttribute('name'), id: entityId(e), components: components(e) });
    }
  }
  const steps = [];
  for (const s of doc.getElementsByTagName('Step')) {
    if (s.getAttribute('type') === 'input') continue;
    steps.push(s.textContent.trim().split(/\s+/).map(Number));
  }
  const value = (step, id) => step[id - 1];
  const times = steps.map((s) => s[0]);
  const poses = new Map();
  for (const [id, p] of parts) {
    const k = p.ids;
    poses.set(id, steps.map((s) => [value(s, k.X), value(s, k.Y), value(s, k.Z),
                                    value(s, k.PSI), value(s, k.THETA), value(s, k.PHI)]));
  }
  for (const r of requests)
    for (const c of r.components) c.values = steps.map((s) => value(s, c.id));
  return { times, poses, requests };
}
