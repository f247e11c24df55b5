// The request plot beside the 3-D view: one component of one request against time on a
// plain <canvas>, with a cursor at the frame shown.

function niceTicks(lo, hi, count) {
  if (!(hi > lo)) { hi = lo + 1; lo -= 1; }
  const raw = (hi - lo) / count, mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((f) => f * mag).find((s) => s >= raw);
  const ticks = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) ticks.push(v);
  return ticks;
}

export function drawPlot(canvas, times, values, label, cursor) {
  const ctx = canvas.getContext('2d');
  const w = canvas.width, h = canvas.height;
  const left = 64, right = 12, top = 24, bottom = 36;
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, w, h);
  if (!times.length) return;
  const finite = values.filter(Number.isFinite);
  let lo = Math.min(...finite), hi = Math.max(...finite);
  if (hi - lo < 1e-12 * Math.max(1, Math.abs(hi))) { lo -= 1; hi += 1; }
  const t0 = times[0], t1 = times[times.length - 1] > t0 ? times[times.length - 1] : t0 + 1;
  const x = (t) => left + ((t - t0) / (t1 - t0)) * (w - left - right);
  const y = (v) => top + (1 - (v - lo) / (hi - lo)) * (h - top - bottom);
  ctx.strokeStyle = '#ddd';
  ctx.fillStyle = '#333';
  ctx.font = '11px sans-serif';
  ctx.lineWidth = 1;
  for (const v of niceTicks(lo, hi, 5)) {
    ctx.beginPath(); ctx.moveTo(left, y(v)); ctx.lineTo(w - right, y(v)); ctx.stroke();
    ctx.textAlign = 'right'; ctx.fillText(Number(v.toPrecision(6)).toString(), left - 4, y(v) + 4);
  }
  for (const t of niceTicks(t0, t1, 5)) {
    ctx.beginPath(); ctx.moveTo(x(t), top); ctx.lineTo(x(t), h - bottom); ctx.stroke();
    ctx.textAlign = 'center'; ctx.fillText(Number(t.toPrecision(6)).toString(), x(t), h - bottom + 14);
  }
  ctx.textAlign = 'center';
  ctx.fillText('time', (left + w - right) / 2, h - 6);
  ctx.fillText(label, (left + w - right) / 2, 14);
  ctx.strokeStyle = '#1f6fb4';
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  values.forEach((v, i) => (i ? ctx.lineTo(x(times[i]), y(v)) : ctx.moveTo(x(times[i]), y(v))));
  ctx.stroke();
  if (cursor >= 0 && cursor < times.length) {
    ctx.strokeStyle = '#d33';
    ctx.beginPath(); ctx.moveTo(x(times[cursor]), top); ctx.lineTo(x(times[cursor]), h - bottom); ctx.stroke();
    ctx.fillStyle = '#d33';
    ctx.beginPath(); ctx.arc(x(times[cursor]), y(values[cursor]), 3, 0, 2 * Math.PI); ctx.fill();
  }
}
