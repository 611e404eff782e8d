// ballrace subsurface-stress explorer: a canvas front end for one state of
// ballrace.teach.compute.compute (live: POST /api/compute; handout: the embedded grid).
"use strict";
(function () {
  const $ = (s) => document.querySelector(s);
  const $$ = (s) => Array.from(document.querySelectorAll(s));
  const EXPORT = DATA_B64.length > 0;
  let cur = null;          // {table, dimless, maxima}: the last valid state
  let pinned = null;       // the pinned state (compare)
  let seq = 0;             // request counter: stale answers are dropped
  let data = null;         // the handout's grid
  let view = { yaw: -0.6, pitch: 0.5 };

  // ------------------------------------------------------------------ helpers
  function unpack(d) {
    const bin = atob(d.data);
    const n = bin.length >> 1;
    const out = new Float32Array(n);
    const span = d.hi - d.lo;
    for (let i = 0; i < n; i++) {
      const q = bin.charCodeAt(2 * i) | (bin.charCodeAt(2 * i + 1) << 8);
      out[i] = d.lo + (q / 65535) * span;
    }
    return out;
  }
  function lin(r) { const a = []; for (let i = 0; i < r[2]; i++) a.push(r[0] + (r[1] - r[0]) * i / (r[2] - 1)); return a; }
  function fmt(v, scale) {
    if (v === null || v === undefined) return "–";
    const x = v * scale;
    return Math.abs(x) < 1e-12 ? "0" : x.toPrecision(4);
  }
  const VIR = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  const DIV = [[33, 102, 172], [146, 197, 222], [247, 247, 247], [244, 165, 130], [178, 24, 43]];
  function cmap(stops, t) {
    t = Math.min(1, Math.max(0, t)) * (stops.length - 1);
    const i = Math.min(stops.length - 2, Math.floor(t)), f = t - i;
    return stops[i].map((c, k) => Math.round(c + (stops[i + 1][k] - c) * f));
  }
  const ZERO = 1e-9;       // |field| / p0 below this everywhere: zero (round-off)
  function signed(name) { return name === "tau_xz" || name === "sigma_x" || name === "sigma_z"; }

  function prep(canvas) {
    const ctx = canvas.getContext("2d");
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.font = "11px system-ui, sans-serif"; ctx.fillStyle = "#222"; ctx.strokeStyle = "#222";
    return ctx;
  }
  function niceTicks(lo, hi, n) {
    const span = hi - lo; if (!(span > 0)) return [lo];
    const step0 = span / n, mag = Math.pow(10, Math.floor(Math.log10(step0)));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => span / s <= n) || 10 * mag;
    const t = []; for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) t.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    return t;
  }
  // a plot frame: data (x0..x1, y0..y1) -> pixels; y down when flip
  function frame(ctx, box, x0, x1, y0, y1, xl, yl, flip) {
    const [L, T, W, H] = box;
    const px = (x) => L + (x - x0) / (x1 - x0) * W;
    const py = flip ? (y) => T + (y - y0) / (y1 - y0) * H : (y) => T + H - (y - y0) / (y1 - y0) * H;
    ctx.strokeStyle = "#888"; ctx.lineWidth = 1; ctx.strokeRect(L, T, W, H);
    ctx.fillStyle = "#333"; ctx.textAlign = "center"; ctx.textBaseline = "top";
    for (const v of niceTicks(x0, x1, 6)) { ctx.fillText(+v.toPrecision(3), px(v), T + H + 2); }
    ctx.textAlign = "right"; ctx.textBaseline = "middle";
    for (const v of niceTicks(Math.min(y0, y1), Math.max(y0, y1), 5)) { ctx.fillText(+v.toPrecision(3), L - 3, py(v)); }
    ctx.textAlign = "center"; ctx.textBaseline = "bottom"; ctx.fillText(xl, L + W / 2, T + H + 28);
    ctx.save(); ctx.translate(12, T + H / 2); ctx.rotate(-Math.PI / 2); ctx.textBaseline = "middle"; ctx.fillText(yl, 0, 0); ctx.restore();
    return { px, py };
  }

  // ------------------------------------------------------------------ pressure ellipse
  function drawEllipse() {
    const cv = $("#c-ellipse"), ctx = prep(cv);
    const t = cur.table;
    const states = [cur].concat(pinned ? [pinned] : []);
    let R = 0; for (const s of states) R = Math.max(R, s.table.ax, s.table.ay);
    R *= 1.15e3;                                            // mm
    const box = [50, 10, cv.width - 70, cv.height - 50];
    const asp = box[2] / box[3];
    const f = frame(ctx, box, -R * asp, R * asp, -R, R, "x [mm] (rolling)", "y [mm]", false);
    const ax = t.ax * 1e3, ay = t.ay * 1e3;
    // pressure p/p0 as an image inside the ellipse
    const img = ctx.createImageData(box[2], box[3]);
    for (let j = 0; j < box[3]; j++) {
      const y = R - (j + 0.5) / box[3] * 2 * R;
      for (let i = 0; i < box[2]; i++) {
        const x = -R * asp + (i + 0.5) / box[2] * 2 * R * asp;
        const s = 1 - (x / ax) ** 2 - (y / ay) ** 2;
        const o = 4 * (j * box[2] + i);
        if (s > 0) { const c = cmap(VIR, Math.sqrt(s)); img.data[o] = c[0]; img.data[o + 1] = c[1]; img.data[o + 2] = c[2]; img.data[o + 3] = 255; }
      }
    }
    ctx.putImageData(img, box[0], box[1]);
    ctx.strokeStyle = "#000"; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.ellipse(f.px(0), f.py(0), f.px(ax) - f.px(0), f.py(0) - f.py(ay), 0, 0, 2 * Math.PI); ctx.stroke();
    if (pinned) {
      ctx.setLineDash([5, 4]); ctx.strokeStyle = "#c00";
      const px = pinned.table.ax * 1e3, py = pinned.table.ay * 1e3;
      ctx.beginPath(); ctx.ellipse(f.px(0), f.py(0), f.px(px) - f.px(0), f.py(0) - f.py(py), 0, 0, 2 * Math.PI); ctx.stroke();
      ctx.setLineDash([]);
    }
    ctx.fillStyle = "#000"; ctx.textAlign = "left"; ctx.textBaseline = "top";
    ctx.fillText(`p0 = ${fmt(t.p0, 1e-9)} GPa, a_x = ${fmt(t.ax, 1e3)} mm, a_y = ${fmt(t.ay, 1e3)} mm`, box[0] + 4, box[1] + 3);
    if (pinned) { ctx.fillStyle = "#c00"; ctx.fillText("pinned (dashed)", box[0] + 4, box[1] + 17); }
  }

  // ------------------------------------------------------------------ sections
  function marksFor(state, name, which) {
    // points (u, z in b units) and the depth line of the maximum of field `name`
    const d = state.dimless, m = state.maxima, sec = d[which];
    const out = { pts: [], depth: null, label: "" };
    const gm = sec.gridmax[name];
    let best = null;
    if (name === "tresca" && m) best = m.tresca_max;
    if (name === "von_mises" && m) best = m.vm_max;
    if (best) {
      const u = which === "sec_y0" ? best.x : best.y;
      const off = which === "sec_y0" ? Math.abs(best.y) : Math.abs(best.x);
      if (off < 1e-6) out.pts.push([u, best.z, "max"]);
      out.depth = best.z; out.label = `max ${best.v.toFixed(3)} p0 at z = ${fmt(best.z * state.table.b, 1e3)} mm`;
    } else if (name === "tau_xz" && m && m.lp && state.table.mu === 0) {
      out.depth = m.lp.z0; out.label = `max |tau_xz| = tau0 = ${m.lp.tau0.toFixed(3)} p0 at z0`;
    } else {
      out.depth = gm[1]; out.label = `grid max |${name}| ${Math.abs(gm[2]).toFixed(3)} p0 at z = ${fmt(gm[1] * state.table.b, 1e3)} mm`;
      out.pts.push([gm[0], gm[1], "grid max"]);
    }
    if (m && m.lp && which === "sec_y0") { out.pts.push([m.lp.x0, m.lp.z0, "LP"]); out.pts.push([-m.lp.x0, m.lp.z0, "LP"]); }
    if (m && m.lp) out.z0 = m.lp.z0;
    return out;
  }
  function drawSection(which, id, uname) {
    const cv = $(id), ctx = prep(cv);
    const name = $("#field").value;
    const sec = cur.dimless[which], b = cur.table.b * 1e3;
    const f = unpack(sec.fields[name]);
    const nu = sec.u[2], nz = sec.z[2];
    let lo = sec.fields[name].lo, hi = sec.fields[name].hi;
    // a field that is zero here (to round-off, in units of p0) has no scale: it is drawn in
    // the neutral colour, the centre of the diverging map, with no maximum marked
    const zero = Math.max(Math.abs(lo), Math.abs(hi)) < ZERO;
    const sg = signed(name) || zero;
    if (zero) { lo = -1; hi = 1; }
    else if (sg) { const a = Math.max(Math.abs(lo), Math.abs(hi)); lo = -a; hi = a; }
    const img = document.createElement("canvas"); img.width = nu; img.height = nz;
    const ic = img.getContext("2d"), id2 = ic.createImageData(nu, nz);
    for (let j = 0; j < nz; j++) for (let i = 0; i < nu; i++) {
      const v = zero ? 0 : f[j * nu + i], c = cmap(sg ? DIV : VIR, (v - lo) / (hi - lo || 1)), o = 4 * (j * nu + i);
      id2.data[o] = c[0]; id2.data[o + 1] = c[1]; id2.data[o + 2] = c[2]; id2.data[o + 3] = 255;
    }
    ic.putImageData(id2, 0, 0);
    const box = [50, 10, cv.width - 110, cv.height - 50];
    ctx.imageSmoothingEnabled = true;
    ctx.drawImage(img, box[0], box[1], box[2], box[3]);
    const u0 = sec.u[0] * b, u1 = sec.u[1] * b, z1 = sec.z[1] * b;
    const F = frame(ctx, box, u0, u1, 0, z1, `${uname} [mm]`, "depth z [mm]", true);
    // colour bar
    const cb = [box[0] + box[2] + 10, box[1], 12, box[3]];
    for (let j = 0; j < cb[3]; j++) { const c = cmap(sg ? DIV : VIR, zero ? 0.5 : 1 - j / cb[3]); ctx.fillStyle = `rgb(${c})`; ctx.fillRect(cb[0], cb[1] + j, cb[2], 1); }
    ctx.strokeStyle = "#bbb"; ctx.lineWidth = 1; ctx.strokeRect(cb[0], cb[1], cb[2], cb[3]);
    ctx.fillStyle = "#333"; ctx.textAlign = "left"; ctx.textBaseline = "middle";
    if (zero) ctx.fillText("0", cb[0] + 14, cb[1] + cb[3] / 2 - 14);
    else { ctx.fillText(hi.toFixed(3), cb[0] + 14, cb[1] + 4); ctx.fillText(lo.toFixed(3), cb[0] + 14, cb[1] + cb[3] - 4); }
    ctx.fillText("/ p0", cb[0] + 14, cb[1] + cb[3] / 2);
    cv.dataset.zero = zero ? "1" : "0";
    if (zero) {
      ctx.fillStyle = "#333"; ctx.textAlign = "center"; ctx.textBaseline = "middle";
      ctx.fillText(`${name} = 0 in this plane (symmetry)`, box[0] + box[2] / 2, box[1] + box[3] / 2);
    }
    // marks (none for a zero field: it has no maximum)
    const mk = zero ? { pts: [], depth: null, label: "" } : marksFor(cur, name, which);
    ctx.lineWidth = 1;
    if (mk.depth !== null) {
      const yl = F.py(mk.depth * b);
      ctx.strokeStyle = "#fff"; ctx.setLineDash([5, 3]);
      ctx.beginPath(); ctx.moveTo(box[0], yl); ctx.lineTo(box[0] + box[2], yl); ctx.stroke();
      ctx.setLineDash([]);
      // the label above its depth line, or below it (and below the marker's own label)
      // when the line is too near the top of the plot, as for a maximum at the surface:
      // it stays inside the plot, clear of the panel's title
      const above = yl - 16 >= box[1];
      const ty = above ? yl - 2 : Math.max(yl, box[1]) + 17;
      ctx.textAlign = "left"; ctx.textBaseline = above ? "bottom" : "top";
      const tw = ctx.measureText(mk.label).width;            // white on a dark band: legible on any colour
      ctx.fillStyle = "rgba(0, 0, 0, 0.6)"; ctx.fillRect(box[0] + 2, above ? ty - 13 : ty - 1, tw + 4, 14);
      ctx.fillStyle = "#fff"; ctx.fillText(mk.label, box[0] + 4, ty);
      cv.dataset.labelTop = String(above ? ty - 12 : ty);
    }
    for (const [u, z, lab] of mk.pts) {
      const x = F.px(u * b), y = F.py(z * b);
      ctx.strokeStyle = lab === "LP" ? "#ff0" : "#fff"; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(x - 6, y); ctx.lineTo(x + 6, y); ctx.moveTo(x, y - 6); ctx.lineTo(x, y + 6); ctx.stroke();
      ctx.fillStyle = ctx.strokeStyle; ctx.textAlign = "left"; ctx.textBaseline = "top"; ctx.fillText(lab, x + 4, y + 3);
    }
    if (pinned) {
      const pm = marksFor(pinned, name, which), pb = pinned.table.b * 1e3;
      ctx.strokeStyle = "#f0f"; ctx.lineWidth = 1.5;
      for (const [u, z] of pm.pts) { ctx.beginPath(); ctx.arc(F.px(u * pb), F.py(z * pb), 5, 0, 2 * Math.PI); ctx.stroke(); }
      if (pm.depth !== null) {
        ctx.setLineDash([2, 3]); ctx.beginPath(); ctx.moveTo(box[0], F.py(pm.depth * pb)); ctx.lineTo(box[0] + box[2], F.py(pm.depth * pb)); ctx.stroke(); ctx.setLineDash([]);
      }
    }
  }

  // ------------------------------------------------------------------ depth profiles
  const CURVES = [["sigma_x", "σx", "#1f77b4"], ["sigma_y", "σy", "#17becf"], ["sigma_z", "σz", "#2ca02c"],
    ["tresca", "Tresca", "#d62728"], ["von_mises", "von Mises", "#9467bd"], ["tau_xz_max", "max|τxz| over x", "#ff7f0e"]];
  function curves(state) {
    const a = state.dimless.axis, p = state.table.p0 * 1e-6, b = state.table.b * 1e3;
    const out = {};
    const z = lin(a.z).map((v) => v * b);
    for (const [k] of CURVES) {
      if (k === "tau_xz_max") out[k] = [lin(a.tau_xz_max.z).map((v) => v * b), a.tau_xz_max.v.map((v) => v * p)];
      else out[k] = [z, a.curves[k].map((v) => v * p)];
    }
    return out;
  }
  function drawProfiles() {
    const cv = $("#c-prof"), ctx = prep(cv);
    const states = [cur].concat(pinned ? [pinned] : []);
    const cs = states.map(curves);
    let lo = 0, hi = 0, zmax = 0;
    for (const c of cs) for (const k in c) { for (const v of c[k][1]) { lo = Math.min(lo, v); hi = Math.max(hi, v); } zmax = Math.max(zmax, c[k][0][c[k][0].length - 1]); }
    const box = [50, 10, cv.width - 60, cv.height - 50];
    const F = frame(ctx, box, lo, hi, 0, zmax, "stress [MPa]", "depth z [mm]", true);
    ctx.save(); ctx.beginPath(); ctx.rect(box[0], box[1], box[2], box[3]); ctx.clip();
    cs.forEach((c, si) => {
      ctx.setLineDash(si ? [5, 4] : []);
      for (const [k, , col] of CURVES) {
        const [z, v] = c[k]; ctx.strokeStyle = col; ctx.lineWidth = 1.5; ctx.beginPath();
        z.forEach((zz, i) => (i ? ctx.lineTo(F.px(v[i]), F.py(zz)) : ctx.moveTo(F.px(v[i]), F.py(zz)))); ctx.stroke();
      }
    });
    ctx.setLineDash([]);
    const t = cur.table;
    ctx.strokeStyle = "#555"; ctx.setLineDash([3, 3]);
    for (const [z, lab] of [[t.z0, "z0"], [t.tau_max_depth, "τmax"]]) {
      if (z === null || z === undefined) continue;
      ctx.beginPath(); ctx.moveTo(box[0], F.py(z * 1e3)); ctx.lineTo(box[0] + box[2], F.py(z * 1e3)); ctx.stroke();
      ctx.fillStyle = "#555"; ctx.textAlign = "right"; ctx.textBaseline = "bottom"; ctx.fillText(lab, box[0] + box[2] - 3, F.py(z * 1e3) - 1);
    }
    ctx.setLineDash([]); ctx.restore();
    ctx.textAlign = "left"; ctx.textBaseline = "top";
    CURVES.forEach(([, lab, col], i) => { ctx.fillStyle = col; ctx.fillText(lab, box[0] + 6 + (i % 3) * 95, box[1] + box[3] - 30 + Math.floor(i / 3) * 13); });
    if (pinned) { ctx.fillStyle = "#555"; ctx.fillText("dashed: pinned", box[0] + 6, box[1] + 4); }
  }

  // ------------------------------------------------------------------ 3-D iso-surface (marching tetrahedra)
  const TETS = [[0, 5, 1, 6], [0, 1, 2, 6], [0, 2, 3, 6], [0, 3, 7, 6], [0, 7, 4, 6], [0, 4, 5, 6]];
  const CORNER = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]];
  let meshCache = { key: null, tris: null };
  function isoMesh(state, level) {
    const key = state === cur ? `${seq}:${level}:${state.table.ax}:${state.table.load}:${state.table.mu}:${state.table.nu}` : null;
    if (key && meshCache.key === key) return meshCache.tris;
    const v = state.dimless.vol, f = unpack(v.vm), b = state.table.b * 1e3;
    const xs = lin(v.x).map((t) => t * b), ys = lin(v.y).map((t) => t * b), zs = lin(v.z).map((t) => t * b);
    const [nx, ny, nz] = [v.x[2], v.y[2], v.z[2]];
    const at = (i, j, k) => f[(i * ny + j) * nz + k];
    const tris = [];
    const P = new Array(8), V = new Array(8);
    for (let i = 0; i < nx - 1; i++) for (let j = 0; j < ny - 1; j++) for (let k = 0; k < nz - 1; k++) {
      let any = 0;
      for (let c = 0; c < 8; c++) {
        const [di, dj, dk] = CORNER[c];
        V[c] = at(i + di, j + dj, k + dk) - level; P[c] = [xs[i + di], ys[j + dj], zs[k + dk]]; any |= V[c] > 0 ? 1 : 2;
      }
      if (any !== 3) continue;
      for (const t of TETS) {
        const ins = t.filter((c) => V[c] > 0), out = t.filter((c) => V[c] <= 0);
        const cut = (a, c) => { const s = V[a] / (V[a] - V[c]); return [0, 1, 2].map((q) => P[a][q] + s * (P[c][q] - P[a][q])); };
        if (ins.length === 1 || ins.length === 3) {
          const [a, o] = ins.length === 1 ? [ins[0], out] : [out[0], ins];
          tris.push([cut(a, o[0]), cut(a, o[1]), cut(a, o[2])]);
        } else if (ins.length === 2) {
          const p1 = cut(ins[0], out[0]), p2 = cut(ins[0], out[1]), p3 = cut(ins[1], out[1]), p4 = cut(ins[1], out[0]);
          tris.push([p1, p2, p3]); tris.push([p1, p3, p4]);
        }
      }
    }
    if (key) meshCache = { key, tris };
    return tris;
  }
  function draw3d() {
    const cv = $("#c-3d"), ctx = prep(cv);
    const level = parseFloat($("#iso").value);
    const tris = isoMesh(cur, level);
    const t = cur.table, b = t.b * 1e3;
    const cy = Math.cos(view.yaw), sy = Math.sin(view.yaw), cp = Math.cos(view.pitch), sp = Math.sin(view.pitch);
    // z is depth: drawn downwards (world up = -z)
    const rot = (p) => { const x = cy * p[0] - sy * p[1], y = sy * p[0] + cy * p[1], z = -p[2]; return [x, cp * y - sp * z, sp * y + cp * z]; };
    const R = Math.max(t.ax, t.ay) * 1e3 * 1.4;
    const s = Math.min(cv.width, cv.height) / (2.2 * R), ox = cv.width / 2, oy = cv.height / 2 - 20;
    const proj = (q) => [ox + s * q[0], oy - s * q[2]];
    // the surface ellipse and the axes
    ctx.strokeStyle = "#444"; ctx.lineWidth = 1; ctx.beginPath();
    for (let i = 0; i <= 64; i++) { const a = 2 * Math.PI * i / 64; const q = proj(rot([t.ax * 1e3 * Math.cos(a), t.ay * 1e3 * Math.sin(a), 0])); i ? ctx.lineTo(q[0], q[1]) : ctx.moveTo(q[0], q[1]); }
    ctx.stroke();
    if (pinned) {
      ctx.strokeStyle = "#c00"; ctx.setLineDash([5, 4]); ctx.beginPath();
      for (let i = 0; i <= 64; i++) { const a = 2 * Math.PI * i / 64; const q = proj(rot([pinned.table.ax * 1e3 * Math.cos(a), pinned.table.ay * 1e3 * Math.sin(a), 0])); i ? ctx.lineTo(q[0], q[1]) : ctx.moveTo(q[0], q[1]); }
      ctx.stroke(); ctx.setLineDash([]);
    }
    for (const [p, lab] of [[[R * 0.8, 0, 0], "x"], [[0, R * 0.8, 0], "y"], [[0, 0, R * 0.8], "z (depth)"]]) {
      const a = proj(rot([0, 0, 0])), e = proj(rot(p));
      ctx.strokeStyle = "#999"; ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(e[0], e[1]); ctx.stroke();
      ctx.fillStyle = "#555"; ctx.fillText(lab, e[0] + 3, e[1]);
    }
    const L = [0.3, -0.5, 0.8], Ln = Math.hypot(...L);
    const faces = tris.map((tr) => {
      const q = tr.map(rot);
      const u = [0, 1, 2].map((i) => q[1][i] - q[0][i]), w = [0, 1, 2].map((i) => q[2][i] - q[0][i]);
      const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
      const nn = Math.hypot(...n) || 1;
      const shade = 0.35 + 0.65 * Math.abs((n[0] * L[0] + n[1] * L[1] + n[2] * L[2]) / (nn * Ln));
      return [q[0][1] + q[1][1] + q[2][1], q.map(proj), shade];
    });
    faces.sort((A, B) => B[0] - A[0]);
    for (const [, p, sh] of faces) {
      ctx.fillStyle = `rgb(${Math.round(120 * sh + 30)},${Math.round(90 * sh + 20)},${Math.round(220 * sh + 20)})`;
      ctx.beginPath(); ctx.moveTo(p[0][0], p[0][1]); ctx.lineTo(p[1][0], p[1][1]); ctx.lineTo(p[2][0], p[2][1]); ctx.closePath(); ctx.fill();
    }
    ctx.fillStyle = "#222"; ctx.textAlign = "left"; ctx.textBaseline = "top";
    const vmax = cur.maxima ? cur.maxima.vm_max.v : cur.dimless.vol.vm.hi;
    ctx.fillText(tris.length ? `σvm = ${level.toFixed(2)} p0 = ${fmt(level * t.p0, 1e-6)} MPa (${tris.length} triangles)`
      : `level ${level.toFixed(2)} p0 above the maximum ${vmax.toFixed(3)} p0`, 6, cv.height - 16);
    cv.dataset.triangles = String(tris.length);
  }
  function setupDrag() {
    const cv = $("#c-3d"); let last = null;
    cv.addEventListener("pointerdown", (e) => { last = [e.clientX, e.clientY]; cv.setPointerCapture(e.pointerId); });
    cv.addEventListener("pointermove", (e) => {
      if (!last || !cur || cur.kind === "roller") return;
      view.yaw += (e.clientX - last[0]) * 0.01; view.pitch = Math.max(-1.5, Math.min(1.5, view.pitch + (e.clientY - last[1]) * 0.01));
      last = [e.clientX, e.clientY]; draw3d();
    });
    cv.addEventListener("pointerup", () => { last = null; });
  }

  // ------------------------------------------------------------------ table
  const ROWS = [["Rx", "R_x [mm]", 1e3], ["Ry", "R_y [mm]", 1e3], ["k", "k = a/b [-]", 1], ["a", "a [mm]", 1e3], ["b", "b [mm]", 1e3],
    ["p0", "p0 [GPa]", 1e-9], ["delta", "δ approach [µm]", 1e6], ["tau0", "τ0 (LP) [MPa]", 1e-6], ["z0", "z0 (LP) [mm]", 1e3],
    ["tau_max", "τ_max Tresca [MPa]", 1e-6], ["tau_max_depth", "its depth [mm]", 1e3], ["tau_max_x", "its x [mm]", 1e3],
    ["vm_max", "σ_vm max [MPa]", 1e-6], ["vm_depth", "its depth [mm]", 1e3], ["load", "load Q [N]", 1], ["nu", "ν [-]", 1], ["mu", "traction q/p [-]", 1]];
  function drawTable(pending) {
    const tb = $("#table tbody"); tb.innerHTML = "";
    for (const [k, lab, sc] of ROWS) {
      const tr = document.createElement("tr");
      const pend = pending && cur.table[k] === null && /tau_max|vm_/.test(k);
      tr.innerHTML = `<td>${lab}</td><td data-key="${k}" class="${pend ? "pending" : ""}">${pend ? "computing…" : fmt(cur.table[k], sc)}</td>` +
        `<td class="pin" data-pin="${k}">${pinned ? fmt(pinned.table[k], sc) : ""}</td>`;
      tb.appendChild(tr);
    }
  }

  // ------------------------------------------------------------------ roller mode
  // text on a box of its own (legible over curves and colour maps)
  function boxedText(ctx, text, x, y, fg, bg) {
    const w = ctx.measureText(text).width, h = 13;
    const left = ctx.textAlign === "right" ? x - w : ctx.textAlign === "center" ? x - w / 2 : x;
    const top = ctx.textBaseline === "top" ? y : ctx.textBaseline === "bottom" ? y - h : y - h / 2;
    ctx.save(); ctx.fillStyle = bg; ctx.fillRect(left - 2, top - 1, w + 4, h + 1); ctx.restore();
    ctx.fillStyle = fg; ctx.fillText(text, x, y);
  }
  function drawRollerPressure() {
    const cv = $("#c-rpress"), ctx = prep(cv);
    const ln = cur.line, t = cur.table;
    const x = ln.x.map((v) => v * 1e3), p = ln.pressure.map((v) => v * 1e-9);
    const half = t.length * 1e3 / 2;
    const top = Math.max(t.p_max, t.p_hertz) * 1e-9 * 1.18;
    const box = [55, 12, cv.width - 125, cv.height - 52];
    const f = frame(ctx, box, -half, half, 0, top, "x along the roller [mm] (from its centre)", "pressure p [GPa]", false);
    // the profile's drop (seen once) on the right-hand axis, in µm (none for a straight roller)
    const drop = ln.drop.map((v) => v * 1e6);
    const dmax = Math.max(0, ...drop.filter((v) => isFinite(v)));
    if (dmax > 1e-6) {
      const dy = (v) => box[1] + (v / (dmax * 1.1)) * box[3];
      ctx.strokeStyle = "#999"; ctx.lineWidth = 1; ctx.setLineDash([2, 3]); ctx.beginPath();
      drop.forEach((v, i) => { if (isFinite(v)) { const X = f.px(x[i]), Y = dy(v); i ? ctx.lineTo(X, Y) : ctx.moveTo(X, Y); } });
      ctx.stroke(); ctx.setLineDash([]);
      ctx.fillStyle = "#888"; ctx.textAlign = "left"; ctx.textBaseline = "middle";
      for (const v of niceTicks(0, dmax * 1.1, 4)) ctx.fillText(+v.toPrecision(3), box[0] + box[2] + 4, dy(v));
      ctx.save(); ctx.translate(cv.width - 14, box[1] + box[3] / 2); ctx.rotate(Math.PI / 2); ctx.textAlign = "center";
      ctx.fillText("profile drop [µm] (dotted, downwards)", 0, 0); ctx.restore();
    }
    // the 2-D Hertz p0 at the mean load per length
    const ph = t.p_hertz * 1e-9;
    ctx.strokeStyle = "#c00"; ctx.setLineDash([6, 4]); ctx.beginPath(); ctx.moveTo(f.px(-half), f.py(ph)); ctx.lineTo(f.px(half), f.py(ph)); ctx.stroke(); ctx.setLineDash([]);
    ctx.textAlign = "right"; ctx.textBaseline = "top";
    boxedText(ctx, `2-D Hertz p0 at Q/L = ${fmt(t.p_hertz, 1e-9)} GPa`, box[0] + box[2] - 6, f.py(ph) + 3, "#c00", "rgba(255,255,255,0.85)");
    // the pressure of every slice
    ctx.strokeStyle = "#1f4e9c"; ctx.lineWidth = 2; ctx.beginPath();
    x.forEach((v, i) => { const X = f.px(v), Y = f.py(p[i]); i ? ctx.lineTo(X, Y) : ctx.moveTo(X, Y); });
    ctx.stroke(); ctx.lineWidth = 1;
    ctx.fillStyle = "#1f4e9c";
    x.forEach((v, i) => { ctx.beginPath(); ctx.arc(f.px(v), f.py(p[i]), 2.2, 0, 2 * Math.PI); ctx.fill(); });
    ctx.textAlign = "left"; ctx.textBaseline = "top";
    boxedText(ctx, `centre ${fmt(t.p_centre, 1e-9)} GPa, end of the contact ${fmt(t.p_edge, 1e-9)} GPa at x = ${fmt(t.x_edge, 1e3)} mm, ` +
      `max ${fmt(t.p_max, 1e-9)} GPa`, box[0] + 6, box[1] + 4, "#000", "rgba(255,255,255,0.85)");
    cv.dataset.points = String(x.length);
  }
  function drawRollerMap() {
    const cv = $("#c-rmap"), ctx = prep(cv);
    const m = cur.map, t = cur.table, vm = unpack(m.vm);
    const nx = m.x.length, nz = m.z.length;
    const w = (m.x[1] - m.x[0]) * 1e3, dz = (m.z[1] - m.z[0]) * 1e3;
    const x0 = m.x[0] * 1e3 - w / 2, x1 = m.x[nx - 1] * 1e3 + w / 2;
    const z0 = m.z[0] * 1e3 - dz / 2, z1 = m.z[nz - 1] * 1e3 + dz / 2;
    const box = [55, 12, cv.width - 135, cv.height - 52];
    const lo = 0, hi = m.vm.hi;
    for (let j = 0; j < nz; j++) for (let i = 0; i < nx; i++) {
      const c = cmap(VIR, (vm[j * nx + i] - lo) / (hi - lo || 1));
      ctx.fillStyle = `rgb(${c[0]},${c[1]},${c[2]})`;
      const X = box[0] + (i / nx) * box[2], Y = box[1] + (j / nz) * box[3];
      ctx.fillRect(Math.floor(X), Math.floor(Y), Math.ceil(box[2] / nx) + 1, Math.ceil(box[3] / nz) + 1);
    }
    const f = frame(ctx, box, x0, x1, z0, z1, "x along the roller [mm]", "depth z [mm]", true);
    // the depth of the maximum at every position (dotted)
    ctx.strokeStyle = "#fff"; ctx.setLineDash([2, 3]); ctx.beginPath();
    m.x.forEach((v, i) => { const X = f.px(v * 1e3), Y = f.py(m.vm_depth[i] * 1e3); i ? ctx.lineTo(X, Y) : ctx.moveTo(X, Y); });
    ctx.stroke(); ctx.setLineDash([]);
    // colour bar
    const cb = [box[0] + box[2] + 12, box[1], 14, box[3]];
    for (let k = 0; k < cb[3]; k++) { const c = cmap(VIR, 1 - k / cb[3]); ctx.fillStyle = `rgb(${c[0]},${c[1]},${c[2]})`; ctx.fillRect(cb[0], cb[1] + k, cb[2], 1); }
    ctx.strokeStyle = "#888"; ctx.strokeRect(...cb);
    ctx.fillStyle = "#333"; ctx.textAlign = "left"; ctx.textBaseline = "middle";
    for (const v of niceTicks(lo * 1e-6, hi * 1e-6, 5)) ctx.fillText(+v.toPrecision(3), cb[0] + cb[2] + 3, cb[1] + cb[3] - (v * 1e6 - lo) / (hi - lo || 1) * cb[3]);
    ctx.save(); ctx.translate(cv.width - 8, box[1] + box[3] / 2); ctx.rotate(Math.PI / 2); ctx.textAlign = "center"; ctx.fillText("σ_vm [MPa]", 0, 0); ctx.restore();
    // the maxima: centre and edge (and the largest, when elsewhere)
    const mark = (k, lab, col, dx) => {
      const [v, x, z] = cur.marks[k], X = f.px(x * 1e3), Y = f.py(z * 1e3);
      ctx.strokeStyle = col; ctx.lineWidth = 2; ctx.beginPath(); ctx.arc(X, Y, 6, 0, 2 * Math.PI); ctx.stroke(); ctx.lineWidth = 1;
      ctx.textBaseline = "middle"; ctx.textAlign = dx < 0 ? "right" : "left";
      boxedText(ctx, `${lab} ${fmt(v, 1e-6)} MPa at z = ${fmt(z, 1e3)} mm`, X + dx, Y + (k === "vm_edge" ? 16 : 0), col, "rgba(0,0,0,0.6)");
    };
    mark("vm_centre", "centre", "#fff", 10);
    const ex = cur.marks.vm_edge[1];
    mark("vm_edge", "edge", "#ff6", ex > 0 ? -10 : 10);
    const mx = cur.marks.vm_maximum;
    if (Math.abs(mx[1] - cur.marks.vm_centre[1]) > 1e-12 && Math.abs(mx[1] - ex) > 1e-12) mark("vm_maximum", "max", "#f80", 10);
    ctx.textAlign = "left"; ctx.textBaseline = "top";
    boxedText(ctx, `depths ${fmt(m.z[0], 1e3)}–${fmt(m.z[nz - 1], 1e3)} mm (0.2–2.5 b); dotted: depth of the maximum`, box[0] + 4, box[1] + box[3] - 16, "#fff", "rgba(0,0,0,0.6)");
    cv.dataset.cells = String(nx * nz);
  }
  const RROWS = [["load", "load Q [N]", 1], ["length", "roller length L [mm]", 1e3], ["R", "reduced radius R [mm]", 1e3],
    ["p_hertz", "2-D Hertz p0 at Q/L [GPa]", 1e-9], ["p_centre", "p at the centre [GPa]", 1e-9], ["p_edge", "p at the contact's end [GPa]", 1e-9],
    ["x_edge", "its x [mm]", 1e3], ["p_max", "p max [GPa]", 1e-9], ["b_centre", "half-width b at the centre [mm]", 1e3],
    ["approach", "approach δ [µm]", 1e6], ["contact_length", "length in contact [mm]", 1e3], ["edge_load", "load to reach the ends [N]", 1],
    ["vm_centre", "σ_vm max, centre [MPa]", 1e-6], ["vm_centre_depth", "its depth [mm]", 1e3],
    ["vm_edge", "σ_vm max, end [MPa]", 1e-6], ["vm_edge_x", "its x [mm]", 1e3], ["vm_edge_depth", "its depth [mm]", 1e3],
    ["vm_maximum", "σ_vm max, overall [MPa]", 1e-6], ["vm_maximum_x", "its x [mm]", 1e3], ["vm_maximum_depth", "its depth [mm]", 1e3],
    ["tr_centre", "τ_max (Tresca), centre [MPa]", 1e-6], ["tr_edge", "τ_max (Tresca), end [MPa]", 1e-6],
    ["tr_maximum", "τ_max (Tresca), overall [MPa]", 1e-6], ["tr_maximum_depth", "its depth [mm]", 1e3]];
  function drawRollerTable() {
    const tb = $("#rtable tbody"); tb.innerHTML = "";
    for (const [k, lab, sc] of RROWS) {
      const tr = document.createElement("tr");
      tr.innerHTML = `<td>${lab}</td><td data-rkey="${k}">${fmt(cur.table[k], sc)}</td>`;
      tb.appendChild(tr);
    }
  }
  function renderRoller() {
    drawRollerPressure(); drawRollerMap(); drawRollerTable();
  }

  function render(pending) {
    if (!cur) return;
    const t0 = performance.now();
    if (cur.kind === "roller") { renderRoller(); return performance.now() - t0; }
    drawEllipse(); drawSection("sec_y0", "#c-secy", "x"); drawSection("sec_x0", "#c-secx", "y");
    drawProfiles(); draw3d(); drawTable(pending);
    return performance.now() - t0;
  }

  // ------------------------------------------------------------------ live mode
  function params() {
    const p = {};
    for (const el of $$("[data-param]")) p[el.dataset.param] = el.value;
    return p;
  }
  function showError(field, msg) {
    for (const e of $$(".err")) e.textContent = "";
    for (const e of $$("input.bad")) e.classList.remove("bad");
    if (!field) return;
    const el = $(`.err[data-for="${field}"]`) || $(`.err[data-for="general"]`);
    el.textContent = msg;
    const inp = $(`[data-param="${field}"]`); if (inp) inp.classList.add("bad");
  }
  async function post(body) {
    const r = await fetch("/api/compute", { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
    return r.json();
  }
  async function update(extra) {
    const my = ++seq, t0 = performance.now();
    const p = Object.assign(params(), extra || {});
    let r;
    try { r = await post(Object.assign({ _maxima: false }, p)); } catch (e) { showError("general", "no answer from the server: " + e); return; }
    if (my !== seq) return;
    if (!r.ok) { showError(r.field, r.error); $("#status").textContent = "kept the last valid state"; return; }
    showError(null);
    for (const [k, v] of Object.entries(r.inputs || {})) { const el = $(`[data-param="${k}"]`); if (el) el.value = v; }
    cur = r; render(r.pending);
    const dt = performance.now() - t0;
    $("#status").textContent = `updated in ${dt.toFixed(0)} ms` + (r.pending ? "; maxima with traction follow" : "")
      + (r.note ? ` - note: ${r.note}` : "");
    $("#status").dataset.ms = dt.toFixed(1);
    document.body.dataset.state = String(my);
    if (r.pending) {
      delete p.set_ratio;
      await new Promise((ok) => setTimeout(ok, 250));      // only once the control rests
      if (my !== seq) return;
      const r2 = await post(Object.assign({ _maxima: true }, p));
      if (my !== seq || !r2.ok) return;
      cur = r2; render(false);
      $("#status").textContent = `updated in ${dt.toFixed(0)} ms; maxima after ${(performance.now() - t0).toFixed(0)} ms`;
    }
    document.body.dataset.ready = String(my);
  }
  function setupLive() {
    for (const [k, v] of Object.entries(DEFAULTS)) { const el = $(`[data-param="${k}"]`); if (el) el.value = v; }
    $("#case").value = DEFAULTS.case || "";
    // inputs from the address: ?mode=bearing&load=4000%20N&traction=0.2&field=von_mises
    for (const [k, v] of new URLSearchParams(location.search)) {
      const el = $(`[data-param="${k}"]`); if (el) el.value = v;
      if (k === "case") $("#case").value = v;
    }
    const syncSliders = () => {           // slider positions from the typed values
      const m = /^\s*([0-9.eE+-]+)\s*(k?N)\s*$/.exec($('[data-param="load"]').value);
      if (m) $("#load-slider").value = Math.log10(parseFloat(m[1]) * (m[2] === "kN" ? 1e3 : 1));
      const tm = /^\s*([0-9.eE+-]+)\s*mrad\s*$/.exec($('[data-param="tilt"]').value);
      if (tm) $("#tilt-slider").value = parseFloat(tm[1]);
      const t = parseFloat($('[data-param="traction"]').value);
      if (isFinite(t)) $("#traction-slider").value = t;
    };
    syncSliders();
    for (const k of ["load", "traction", "tilt"]) $(`[data-param="${k}"]`).addEventListener("change", syncSliders);
    const modeView = () => {
      const mode = $("#mode").value, r = mode === "roller";
      $("#bearing").hidden = mode !== "bearing"; $("#bodies").hidden = mode !== "bodies"; $("#roller").hidden = !r;
      $("#crown-inputs").hidden = $('[data-param="profile"]').value !== "crowned";
      for (const el of $$(".ball-only, .ball-view")) el.hidden = r;
      for (const el of $$(".roller-view")) el.hidden = !r;
      document.body.dataset.mode = mode;
      if (r && pinned) { pinned = null; $("#compare").checked = false; document.body.classList.remove("comparing"); }
    };
    modeView();
    $("#mode").addEventListener("change", () => { modeView(); update(); });
    $('[data-param="profile"]').addEventListener("change", modeView);
    $("#tilt-slider").addEventListener("input", (e) => { $('[data-param="tilt"]').value = `${(+e.target.value).toFixed(2)} mrad`; soon(() => update()); });
    for (const el of $$("[data-param]")) if (el.id !== "mode") el.addEventListener("change", () => update());
    let timer = null;
    const soon = (fn) => { clearTimeout(timer); timer = setTimeout(fn, 40); };
    $("#load-slider").addEventListener("input", (e) => {
      $('[data-param="load"]').value = `${(+Math.pow(10, +e.target.value).toPrecision(3))} N`; soon(() => update());
    });
    $("#traction-slider").addEventListener("input", (e) => { $('[data-param="traction"]').value = e.target.value; soon(() => update()); });
    $("#ratio").addEventListener("input", (e) => {
      const r = +Math.pow(10, +e.target.value).toPrecision(3); $("#ratio-out").textContent = r; soon(() => update({ set_ratio: String(r) }));
    });
    $("#case-load").addEventListener("click", async () => {
      const q = new URLSearchParams({ path: $("#case").value, race: $('[data-param="race"]').value });
      const r = await (await fetch("/api/case?" + q)).json();
      if (!r.ok) { showError("case", r.error); return; }
      for (const [k, v] of Object.entries(r.inputs)) { const el = $(`[data-param="${k}"]`); if (el) el.value = v; }
      modeView(); update();
    });
    update();
  }

  // ------------------------------------------------------------------ handout mode
  async function setupExport() {
    $("#live-controls").hidden = true; $("#export-controls").hidden = false;
    const t0 = performance.now();
    $("#status").textContent = `unpacking the precomputed grid (${(DATA_B64.length / 1e6).toFixed(1)} MB)…`;
    await new Promise((ok) => setTimeout(ok, 0));           // let the message show first
    const bin = Uint8Array.from(atob(DATA_B64), (c) => c.charCodeAt(0));
    const stream = new Blob([bin]).stream().pipeThrough(new DecompressionStream("gzip"));
    data = JSON.parse(await new Response(stream).text());
    $("#status").textContent = `${Object.keys(data.tables).length} states unpacked in ${((performance.now() - t0) / 1e3).toFixed(1)} s`;
    const g = data.grid;
    $("#geom").textContent = `r_x1 = ${data.geometry.rx1}, E = ${data.geometry.E}`;
    const sl = { ratio: "#s-ratio", load: "#s-load", nu: "#s-nu", mu: "#s-mu" };
    const init = { ratio: 0, load: g.load.indexOf(2000) >= 0 ? g.load.indexOf(2000) : 0, nu: g.nu.indexOf(0.3) >= 0 ? g.nu.indexOf(0.3) : 0, mu: 0 };
    for (const k in sl) { const el = $(sl[k]); el.max = g[k].length - 1; el.value = init[k]; el.addEventListener("input", pick); }
    pick();
    function pick() {
      const i = +$(sl.ratio).value, j = +$(sl.load).value, l = +$(sl.nu).value, m = +$(sl.mu).value;
      $("#g-ratio").textContent = g.ratio[i]; $("#g-load").textContent = `${g.load[j]} N`; $("#g-nu").textContent = g.nu[l]; $("#g-mu").textContent = g.mu[m];
      const dl = data.dimless[`${i},${l},${m}`];
      cur = { table: data.tables[`${i},${j},${l},${m}`], dimless: dl.fields, maxima: dl.maxima };
      seq++; render(false);
      document.body.dataset.ready = String(seq);
    }
  }

  // ------------------------------------------------------------------ common
  function setup() {
    for (const lab of $$("label.row")) {      // the label's text (with <sub>) as one flex item
      const span = document.createElement("span");
      for (const n of Array.from(lab.childNodes)) if (!(n.matches && n.matches("input,select,output"))) span.appendChild(n);
      lab.insertBefore(span, lab.firstChild);
    }
    const sel = $("#field");
    for (const [k, v] of Object.entries(FIELDS)) { const o = document.createElement("option"); o.value = k; o.textContent = v; sel.appendChild(o); }
    const q = new URLSearchParams(location.search);
    sel.value = FIELDS[q.get("field")] ? q.get("field") : "tau_xz";
    if (q.get("iso")) { $("#iso").value = q.get("iso"); $("#iso-out").textContent = (+$("#iso").value).toFixed(2); }
    sel.addEventListener("change", () => render(false));
    $("#iso").addEventListener("input", (e) => { $("#iso-out").textContent = (+e.target.value).toFixed(2); if (cur && cur.kind !== "roller") draw3d(); });
    $("#compare").addEventListener("change", (e) => {
      pinned = e.target.checked && cur ? cur : null;
      document.body.classList.toggle("comparing", !!pinned); render(false);
    });
    setupDrag();
    if (EXPORT) setupExport(); else setupLive();
  }
  setup();
})();
