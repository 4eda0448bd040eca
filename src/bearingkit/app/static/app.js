// bearingkit serve: the page. Plain JavaScript, no framework, no build step, nothing fetched from elsewhere.
// Every number comes from the server's JSON (SI, units in keys); this file converts units for display and
// draws the plots as SVG. Text from the server or from files is always set as text, never as HTML.
"use strict";

const SVGNS = "http://www.w3.org/2000/svg";
const LOADS = ["F_x", "F_y", "F_z", "eccentricity", "M_x", "M_y"];
const VIRIDIS = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
const RPM = 60 / (2 * Math.PI);
const state = { source: null, opened: null, dirty: new Set(), seq: 0, shown: 0, last: null, timer: null, freeDofs: null };
// The other pages (catalogue.js, systems.js, study.js, duty.js) register their start here; each runs once
// the server's meta data is in (the scripts load in order, all before DOMContentLoaded).
const PAGES = {};

// ------------------------------------------------------------------------------------------ helpers
const $ = (id) => document.getElementById(id);

function el(tag, attrs, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (v !== null && v !== undefined) node.setAttribute(k, v);
  }
  for (const c of children.flat()) {
    if (c !== null && c !== undefined) node.append(c instanceof Node ? c : String(c));
  }
  return node;
}

function svg(tag, attrs, text) {
  const node = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  return node;
}

// Significant digits without exponent noise for everyday magnitudes; "—" for missing values.
function fmt(x, digits = 4) {
  if (x === null || x === undefined || Number.isNaN(x)) return "—";
  if (x === 0 || Math.abs(x) < 1e-300) return "0";
  const a = Math.abs(x);
  if (a >= 1e7 || a < 1e-4) {
    const [m, e] = x.toExponential(digits - 1).split("e");
    return `${parseFloat(m)}e${parseInt(e, 10)}`;
  }
  return String(parseFloat(x.toPrecision(digits)));
}

function viridis(t) {
  t = Math.min(1, Math.max(0, t)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(t));
  const f = t - i;
  const c = VIRIDIS[i].map((v, k) => Math.round(v + f * (VIRIDIS[i + 1][k] - v)));
  return `rgb(${c[0]},${c[1]},${c[2]})`;
}

function niceTicks(lo, hi, n = 5) {
  if (!(hi > lo)) return [lo];
  const step0 = (hi - lo) / n;
  const mag = 10 ** Math.floor(Math.log10(step0));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= step0);
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

// Ticks of a log axis (log10 values lo … hi): decades, and 2 and 5 times them when few decades show.
function logTicks(lo, hi) {
  const out = [];
  const mantissas = hi - lo > 4 ? [1] : hi - lo > 1.5 ? [1, 3] : [1, 2, 5];
  for (let d = Math.floor(lo); d <= Math.ceil(hi); d++) {
    for (const m of mantissas) {
      const v = d + Math.log10(m);
      if (v >= lo - 1e-9 && v <= hi + 1e-9) out.push(v);
    }
  }
  return out;
}

async function api(path, body) {
  const init = body === undefined ? {} : {
    method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body),
  };
  const response = await fetch(path, init);
  let data;
  try { data = await response.json(); } catch (e) { data = { error: `${response.status} ${response.statusText}` }; }
  if (!response.ok) {
    const err = new Error(data.error || `HTTP ${response.status}`);
    err.field = data.field || "source";
    throw err;
  }
  return data;
}

function setStatus(text, mode) {
  document.body.dataset.state = mode;
  $("status").textContent = text;
}

function clearErrors() {
  for (const e of document.querySelectorAll(".error[data-for]")) e.textContent = "";
  for (const i of document.querySelectorAll("input.invalid, select.invalid")) i.classList.remove("invalid");
}

function showError(err) {
  const field = err.field || "source";
  let target = document.querySelector(`.error[data-for="${CSS.escape(field)}"]`);
  if (!target) target = $("source-error");
  target.textContent = err.message;
  const input = document.querySelector(`[data-field="${CSS.escape(field)}"]`);
  if (input) input.classList.add("invalid");
  setStatus("bearing page: error, see the message next to the field", "error"); // the bar shows on every page
}

// ------------------------------------------------------------------------------------------ opening
async function openSource(source) {
  clearErrors();
  clearBearing(source); // nothing of the previous bearing stays on screen while this one opens
  setStatus("opening…", "busy");
  try {
    const opened = await api("/api/open", { source });
    state.source = source;
    state.opened = opened;
    state.dirty = new Set();
    fillForm(opened);
    await analyze();
  } catch (err) {
    showError({ message: err.message, field: "source" });
  }
}

// Forget the open bearing: its form values, results, plots, sweep and downloads. The three ways to open
// one show only the current source: the example list, the designation box and the upload field.
function clearBearing(source) {
  state.source = null;
  state.opened = null;
  state.last = null;
  state.sweep = null;
  state.freeDofs = null;
  state.seq += 1; // an answer still on its way belongs to the old bearing: it is not shown
  $("status").dataset.requested = String(state.seq);
  $("status").dataset.seq = String(state.seq);
  if (source.kind !== "example") $("example").value = "";
  if (source.kind !== "designation") $("designation").value = "";
  else $("designation").value = source.name;
  if (source.kind !== "upload") $("upload").value = "";
  $("bearing-title").textContent = "No bearing open";
  $("bearing-description").textContent = "";
  $("duty-hint").hidden = true;
  $("fixed-dofs").textContent = "—";
  for (const id of [...LOADS, "speed", "temperature", "contamination"]) $(id).value = "";
  $("friction-model").value = "auto";
  $("subsurface").checked = false;
  $("case").replaceChildren();
  $("clearances").replaceChildren();
  for (const input of document.querySelectorAll("[data-lube], [data-thermal]")) input.value = "";
  $("heat").checked = false;
  $("case-title").textContent = "";
  $("thermal").hidden = true;
  for (const id of ["summary", "warnings", "polar", "angles", "ratings", "limits", "friction", "stiffness", "pressure", "subsurface-out", "notes"]) {
    $(id).replaceChildren();
  }
  $("subsurface-card").hidden = true;
  renderStructure({}); // hides and empties the structure card
  $("references").textContent = "";
  $("sweep-plot").replaceChildren();
  $("sweep-status").textContent = "";
  $("sweep-error").textContent = "";
  for (const id of ["dl-toml", "dl-json", "dl-html"]) {
    $(id).classList.add("disabled");
    $(id).removeAttribute("href");
  }
}

// Open a standard bearing on the bearing page (the catalogue's "Open").
function openDesignation(name) {
  showPage("bearing");
  $("designation").value = name;
  return openSource({ kind: "designation", name });
}

function fillForm(o) {
  $("bearing-title").textContent = `${o.bearing_name} (${o.bearing_type.replaceAll("_", " ")})`;
  $("bearing-description").textContent = o.description;
  $("fixed-dofs").textContent = "—"; // the DOFs the analysis solved with (render): the pipeline may fix the tilt
  $("duty-hint").hidden = !(o.duty_cycle && o.duty_cycle.length);
  const sel = $("case");
  sel.replaceChildren(...o.cases.map((c) => el("option", { value: c.name }, c.name)));
  $("case-field").hidden = o.cases.length < 2;
  fillCase(o.cases[0] || null);
  const box = $("clearances");
  box.replaceChildren(...Object.entries(o.clearances).map(([k, v]) => {
    const field = `geometry.${k}`;
    const input = el("input", { id: field, "data-field": field, "data-clearance": k, placeholder: "builder default" });
    input.value = v;
    input.addEventListener("change", () => { state.dirty.add(k); analyze(); });
    return el("div", { class: "field" }, el("label", { for: field }, k.replaceAll("_", " ")), input,
      el("span", { class: "error", "data-for": field }));
  }));
  const lube = $("lubricant");
  const own = o.lubricant ? `file: ${o.lubricant}` : "none (no κ, a_ISO)";
  lube.replaceChildren(el("option", { value: "" }, own), ...state.meta.lubricants.map((n) => el("option", { value: n }, n)));
  $("lube-base_oil").replaceChildren(el("option", { value: "" }, "(as chosen)"), ...(state.meta.base_oils || []).map((n) => el("option", { value: n }, n)));
  $("lube-thickener").replaceChildren(el("option", { value: "" }, "(oil)"), ...(state.meta.thickeners || []).map((n) => el("option", { value: n }, n)));
  for (const input of document.querySelectorAll("[data-lube], [data-thermal]")) input.value = "";
  $("heat").checked = Boolean(o.thermal);
  fillSweepFactors(o, o.free_dofs);
}

function fillCase(c) {
  for (const k of LOADS) $(k).value = c ? c[k] || "" : "";
  if (!c) $("F_x").value = "1 kN"; // a designation has no load case: start from a radial load to edit
  $("speed").value = c ? c.speed || "" : "";
  $("temperature").value = c ? c.temperature || "" : "";
}

// ------------------------------------------------------------------------------------------ analysing
function request() {
  const loads = {};
  for (const k of LOADS) loads[k] = $(k).value.trim();
  const geometry = {};
  for (const input of document.querySelectorAll("[data-clearance]")) {
    if (state.dirty.has(input.dataset.clearance)) geometry[input.dataset.clearance] = input.value.trim();
  }
  return {
    source: state.source,
    case: state.opened && state.opened.cases.length ? $("case").value : null,
    loads,
    speed: $("speed").value.trim(),
    temperature: $("temperature").value.trim(),
    geometry,
    lubricant: $("lubricant").value,
    lubricant_data: Object.fromEntries([...document.querySelectorAll("[data-lube]")].map((i) => [i.dataset.lube, i.value.trim()]).filter(([, v]) => v)),
    heat: $("heat").checked,
    thermal: Object.fromEntries([...document.querySelectorAll("[data-thermal]")].map((i) => [i.dataset.thermal, i.value.trim()]).filter(([, v]) => v)),
    contamination: $("contamination").value.trim(),
    friction_model: $("friction-model").value,
    subsurface: $("subsurface").checked,
  };
}

async function analyze() {
  delete $("status").dataset.pending;
  if (!state.source) return;
  const seq = ++state.seq;
  $("status").dataset.requested = String(seq); // the page is settled when data-seq reaches it
  clearErrors();
  setStatus("analysing the bearing…", "busy");
  const t0 = performance.now();
  try {
    const data = await api("/api/analyze", request());
    if (seq !== state.seq) return; // a newer request is on its way
    render(data);
    state.shown = seq;
    $("status").dataset.seq = String(seq);
    const total = performance.now() - t0;
    setStatus(`bearing analysed in ${fmt(data.elapsed_ms, 2)} ms (page ${fmt(total, 2)} ms)`, "ready");
  } catch (err) {
    if (seq !== state.seq) return;
    $("status").dataset.seq = String(seq);
    showError(err);
    for (const id of ["dl-toml", "dl-json", "dl-html"]) $(id).classList.add("disabled");
  }
}

function scheduleAnalyze() {
  clearTimeout(state.timer);
  $("status").dataset.pending = "1"; // an analysis is due: what is shown is about to change
  state.timer = setTimeout(analyze, 150);
}

// ------------------------------------------------------------------------------------------ rendering
function render(data) {
  const a = data.analysis;
  const c = a.cases[0];
  state.last = data;
  $("case-title").textContent = `case ${c.case}${c.converged ? "" : " (NOT converged)"}`;
  renderSummary(c);
  renderThermal(c);
  const warn = $("warnings");
  warn.replaceChildren(...c.warnings.map((w) => el("li", {}, w)));
  renderPolar(c);
  renderAngles(c);
  renderStructure(c); // structure.js: a [structure]'s rigid → flexible rings
  renderFriction(c);
  renderPressure(data, c);
  renderStiffness(c.stiffness_SI);
  renderRatings(c);
  renderLimits(c.limits);
  renderSubsurface(c, a.subsurface);
  const dofs = ["u_x", "u_y", "u_z", "theta_x", "theta_y"];
  $("fixed-dofs").textContent = dofs.filter((d) => !a.free_dofs.includes(d)).join(", ") || "none";
  if (String(state.freeDofs) !== String(a.free_dofs)) {
    state.freeDofs = a.free_dofs;
    if (state.opened) fillSweepFactors(state.opened, a.free_dofs);
  }
  $("notes").replaceChildren(...a.notes.map((n) => el("li", {}, n)));
  $("references").textContent = a.references.length ? `References: ${a.references.join(", ")}` : "";
  for (const [ext, href] of Object.entries(data.downloads)) {
    const link = $(`dl-${ext}`);
    link.href = href;
    link.classList.remove("disabled");
  }
}

// The first value of a key matching `pattern` anywhere in `obj` (κ sits where the pipeline puts it).
function findKey(obj, pattern) {
  if (obj === null || typeof obj !== "object") return undefined;
  for (const [k, v] of Object.entries(obj)) {
    if (pattern.test(k) && (typeof v === "number" || v === null)) return v;
  }
  for (const v of Object.values(obj)) {
    const found = findKey(v, pattern);
    if (found !== undefined) return found;
  }
  return undefined;
}

function metric(id, name, value, scale, unit, digits = 4, bad = false) {
  const shown = value === null || value === undefined ? "—" : fmt(value * scale, digits);
  return el("div", { class: bad ? "metric bad" : "metric" },
    el("div", { class: "name" }, name),
    el("span", { class: "value", id, "data-value": value === null || value === undefined ? "" : String(value) }, shown),
    el("span", { class: "unit" }, unit));
}

function renderThermal(c) {
  const box = $("thermal"), t = c.thermal;
  box.hidden = !t;
  if (!t) return;
  const oil = t.oil_flow_m3_s > 0 ? ` + oil ${fmt(t.oil_heat_W, 4)} W` : "";
  box.textContent = `Operating temperature FOUND by the heat balance: ${fmt(t.temperature_C, 4)} °C — friction heat ${fmt(t.friction_heat_W, 4)} W = seats/housing ${fmt(t.conducted_heat_W, 4)} W (${fmt(t.heat_dissipation_W_K, 3)} W/K to ${fmt(t.ambient_C, 3)} °C)${oil}; closed to ${t.balance_relative.toExponential(1)} in ${t.iterations} iterations (${t.friction_model} friction). κ, a_ISO, friction and clearance are at this temperature.`;
}

function renderSummary(c) {
  const rows = c.rows;
  const qmax = Math.max(...rows.map((r) => r.max_load_N));
  const pmax = Math.max(...rows.map((r) => r.max_pressure_Pa));
  const sys = c.rating ? c.rating.system : {};
  const fr = c.friction || {};
  const d = c.displacement;
  const kappa = findKey(c, /^kappa/);
  const s0 = sys.static_safety;
  $("summary").replaceChildren(
    metric("max-load", "max element load Q_max", qmax, 1e-3, "kN"),
    metric("max-pressure", "max contact pressure", pmax, 1e-6, "MPa"),
    // the headline life first: ISO 281 where it rates the bearing (system.headline), the TS's beside it
    ...(sys.headline && sys.headline.method === "ISO 281"
      ? [metric("l10-iso281", "L10h (ISO 281)", sys.L10h_iso281_h ?? null, 1, "h"),
         metric("lnm-iso281", "L_nmh (ISO 281, a_ISO)", sys.Lnm_iso281_h ?? null, 1, "h")]
      : []),
    metric("l10", "L10r (ISO/TS 16281)", sys.L10r_rev ?? null, 1e-6, "10⁶ rev"),
    metric("l10h", "L10rh (ISO/TS 16281)", sys.L10h_h ?? null, 1, "h"),
    metric("lnm", "Lnmr (ISO/TS 16281, a_ISO)", sys.Lnmr_h ?? null, 1, "h"),
    metric("s0", "static safety s0", s0 ?? null, 1, "", 3, s0 !== undefined && s0 !== null && s0 < 1),
    // ISO 76's s0 = C0/P0 with the bearing's C0 (the catalogue's for a designation), where ISO 76 gives P0
    ...(sys.C0_iso76_N !== undefined && sys.C0_iso76_N !== null
      ? [metric("c0-iso76", `C0 (ISO 76, ${sys.C0_source})`, sys.C0_iso76_N, 1e-3, "kN"),
         metric("s0-iso76", "s0 = C0/P0 (ISO 76)", sys.s0_iso76 ?? null, 1, "", 3,
           sys.s0_iso76 !== undefined && sys.s0_iso76 !== null && sys.s0_iso76 < 1)]
      : []),
    metric("kappa", "viscosity ratio κ", kappa ?? null, 1, "", 3),
    metric("torque", "friction torque", fr.total_Nm ?? null, 1e3, "N·mm"),
    metric("power", "power loss", fr.power_loss_W ?? null, 1, "W"),
    metric("u-radial", "radial displacement", Math.hypot(d.u_x_m, d.u_y_m), 1e6, "µm"),
    metric("u-axial", "axial displacement", d.u_z_m, 1e6, "µm"),
  );
}

function renderPolar(c) {
  const size = 300, cx = size / 2, cy = size / 2 + 24, R = 108;
  const panels = c.rows.map((row) => {
    const q = row.loads_N, psi = row.azimuth_rad;
    const qmax = Math.max(0, ...q);
    const scale = qmax > 0 ? qmax : 1;
    const s = svg("svg", { width: size, height: size + 34, viewBox: `0 0 ${size} ${size + 34}`, role: "img" });
    s.append(svg("title", {}, `${row.name}: element loads at their azimuth`));
    for (const f of [1 / 3, 2 / 3, 1]) {
      s.append(svg("circle", { cx, cy, r: R * f, class: "grid" }));
      s.append(svg("text", { x: cx + 3, y: cy - R * f - 2, "font-size": 9, fill: "#5d6b7a" }, `${fmt(scale * f / 1e3, 3)} kN`));
    }
    for (let deg = 0; deg < 360; deg += 45) {
      const t = (deg * Math.PI) / 180;
      s.append(svg("line", { x1: cx, y1: cy, x2: cx + R * Math.cos(t), y2: cy - R * Math.sin(t), class: "grid" }));
      const lx = cx + (R + 14) * Math.cos(t), ly = cy - (R + 14) * Math.sin(t) + 4;
      s.append(svg("text", { x: lx, y: ly, "text-anchor": "middle", "font-size": 10 }, `${deg}°`));
    }
    const half = Math.min(0.4 * (2 * Math.PI) / Math.max(q.length, 1), 0.35);
    q.forEach((load, j) => {
      const p = ((psi[j] % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
      if (!(load > 0)) {
        s.append(svg("circle", { cx: cx + 5 * Math.cos(p), cy: cy - 5 * Math.sin(p), r: 1.6, fill: "#7f8c8d" }));
        return;
      }
      const r = (R * load) / scale;
      const a1 = p - half, a2 = p + half;
      const d = `M${cx},${cy} L${cx + r * Math.cos(a1)},${cy - r * Math.sin(a1)} A${r},${r} 0 0 0 ${cx + r * Math.cos(a2)},${cy - r * Math.sin(a2)} Z`;
      const wedge = svg("path", { d, fill: viridis(load / scale), stroke: "none" });
      wedge.append(svg("title", {}, `ψ = ${fmt((p * 180) / Math.PI, 4)}°, Q = ${fmt(load, 5)} N`));
      s.append(wedge);
    });
    const loaded = q.filter((v) => v > 0).length;
    s.append(svg("text", { x: 4, y: 13, class: "title" }, `${row.name} (${row.kind})`));
    s.append(svg("text", { x: 4, y: 27, "font-size": 11 }, `${loaded}/${q.length} loaded, Q_max ${fmt(qmax / 1e3, 4)} kN`));
    s.append(svg("text", { x: 4, y: size + 30, "font-size": 9, fill: "#5d6b7a" }, "ψ from +x (right) towards +y (up)"));
    return s;
  });
  $("polar").replaceChildren(...panels);
}

// A small x–y chart: series [{x: [...], y: [...], label}], with axes, ticks and optional log y.
function chart({ width = 460, height = 230, series, xlabel, ylabel, title, logy = false, bad = [] }) {
  const m = { l: 58, r: 24, t: 22, b: 38 };
  const s = svg("svg", { width, height, viewBox: `0 0 ${width} ${height}`, role: "img" });
  const xs = series.flatMap((se) => se.x), ys0 = series.flatMap((se) => se.y).filter((v) => v !== null && Number.isFinite(v) && (!logy || v > 0));
  if (!xs.length || !ys0.length) {
    s.append(svg("text", { x: width / 2, y: height / 2, "text-anchor": "middle" }, "nothing to plot"));
    return s;
  }
  const tf = logy ? (v) => Math.log10(v) : (v) => v;
  const ys = ys0.map(tf);
  let [x0, x1] = [Math.min(...xs), Math.max(...xs)];
  let [y0, y1] = [Math.min(...ys), Math.max(...ys)];
  if (x1 === x0) { x0 -= 1; x1 += 1; }
  if (y1 - y0 < 1e-12 * Math.max(1, Math.abs(y1))) { const pad = Math.abs(y0) * 0.1 || 1; y0 -= pad; y1 += pad; }
  if (!logy && y0 > 0 && y0 < 0.5 * y1) y0 = 0;
  const px = (x) => m.l + ((x - x0) / (x1 - x0)) * (width - m.l - m.r);
  const py = (y) => height - m.b - ((y - y0) / (y1 - y0)) * (height - m.t - m.b);
  const yt = logy ? logTicks(y0, y1) : niceTicks(y0, y1, 5);
  for (const v of yt) {
    s.append(svg("line", { x1: m.l, x2: width - m.r, y1: py(v), y2: py(v), class: "grid" }));
    s.append(svg("text", { x: m.l - 4, y: py(v) + 4, "text-anchor": "end" }, logy ? fmt(10 ** v, 3) : fmt(v, 4)));
  }
  for (const v of niceTicks(x0, x1, 6)) {
    s.append(svg("line", { x1: px(v), x2: px(v), y1: height - m.b, y2: height - m.b + 4, class: "axis" }));
    s.append(svg("text", { x: px(v), y: height - m.b + 15, "text-anchor": "middle" }, fmt(v, 4)));
  }
  s.append(svg("rect", { x: m.l, y: m.t, width: width - m.l - m.r, height: height - m.t - m.b, class: "axis" }));
  const colours = ["#1f5f99", "#c0392b", "#239b56", "#8e44ad"];
  series.forEach((se, k) => {
    const pts = se.x.map((x, i) => [x, se.y[i]]).filter(([, y]) => y !== null && Number.isFinite(y) && (!logy || y > 0));
    if (pts.length > 1) {
      s.append(svg("polyline", { points: pts.map(([x, y]) => `${px(x)},${py(tf(y))}`).join(" "), fill: "none", stroke: colours[k % 4], "stroke-width": 1.8 }));
    }
    const dots = se.x.length <= 60 || bad.some(Boolean); // a dense line (a shaft's) needs no dots
    se.x.forEach((x, i) => {
      const y = se.y[i];
      if (!dots || y === null || !Number.isFinite(y) || (logy && y <= 0)) return;
      const dot = svg("circle", { cx: px(x), cy: py(tf(y)), r: bad[i] ? 4 : 2.6, fill: bad[i] ? "#c0392b" : colours[k % 4] });
      dot.append(svg("title", {}, `${fmt(x, 5)}: ${fmt(y, 5)}`));
      s.append(dot);
    });
  });
  // a legend of the labelled series, right-aligned at the top of the plot area, on a white backdrop
  const labelled = series.filter((se) => se.label);
  if (labelled.length) {
    const widths = labelled.map((se) => 24 + 6.2 * String(se.label).length);
    const total = widths.reduce((a, b) => a + b, 0);
    let x = width - m.r - total - 4;
    s.append(svg("rect", { x: x - 2, y: m.t + 2, width: total + 4, height: 15, fill: "#fff", opacity: 0.85 }));
    labelled.forEach((se, k) => {
      s.append(svg("line", { x1: x, x2: x + 14, y1: m.t + 10, y2: m.t + 10, stroke: colours[series.indexOf(se) % 4], "stroke-width": 2 }));
      s.append(svg("text", { x: x + 17, y: m.t + 14 }, se.label));
      x += widths[k];
    });
  }
  s.append(svg("text", { x: (m.l + width - m.r) / 2, y: height - 6, "text-anchor": "middle" }, xlabel));
  s.append(svg("text", { x: 12, y: (m.t + height - m.b) / 2, "text-anchor": "middle", transform: `rotate(-90 12 ${(m.t + height - m.b) / 2})` }, ylabel));
  if (title) s.append(svg("text", { x: m.l, y: 14, class: "title" }, title));
  return s;
}

function renderAngles(c) {
  const charts = c.rows.map((row) => {
    const x = row.azimuth_rad.map((p) => ((((p * 180) / Math.PI) % 360) + 360) % 360);
    const order = x.map((v, i) => i).sort((i, j) => x[i] - x[j]);
    const loaded = row.loads_N.map((q) => !(q > 0));
    return chart({
      width: 420, height: 210,
      series: [{ x: order.map((i) => x[i]), y: order.map((i) => (row.contact_angle_rad[i] * 180) / Math.PI) }],
      bad: order.map((i) => loaded[i]),
      xlabel: "azimuth ψ [°]", ylabel: "contact angle α [°]",
      title: `${row.name}: α per element (red: unloaded)`,
    });
  });
  $("angles").replaceChildren(...charts);
}

function bars(items, unit, title) {
  const width = 420, rowH = 18, left = 150;
  const height = 26 + rowH * items.length;
  const s = svg("svg", { width, height, viewBox: `0 0 ${width} ${height}`, role: "img" });
  s.append(svg("text", { x: 0, y: 13, class: "title" }, title));
  const top = Math.max(...items.map(([, v]) => Math.abs(v)), 1e-30);
  items.forEach(([name, v], i) => {
    const y = 22 + i * rowH;
    const w = ((width - left - 95) * Math.abs(v)) / top;
    s.append(svg("text", { x: left - 6, y: y + 12, "text-anchor": "end" }, name.replaceAll("_", " ")));
    s.append(svg("rect", { x: left, y: y + 2, width: Math.max(w, v ? 1 : 0), height: rowH - 5, fill: "#2e86c1" }));
    s.append(svg("text", { x: left + w + 4, y: y + 12 }, `${fmt(v, 4)} ${unit}`));
  });
  return s;
}

function renderFriction(c) {
  const box = $("friction");
  const f = c.friction;
  if (!f) {
    box.replaceChildren(el("p", { class: "muted" }, "Not computed (the notes below say why: friction needs a speed and a lubricant)."));
    return;
  }
  const comp = Object.entries(f.components_Nm || {}).map(([k, v]) => [k, v * 1e3]);
  const rows = Object.entries(f.rows_Nm || {}).map(([k, v]) => [k, v * 1e3]);
  const why = f.model_why ? ` — ${f.model_why}` : "";
  box.replaceChildren(
    el("p", {}, `M = ${fmt(f.total_Nm * 1e3, 5)} N·mm, power loss ${fmt(f.power_loss_W, 4)} W`),
    el("p", { class: "muted" }, `model: ${f.model || "components"}${why}`),
    bars(comp, "N·mm", "by component"),
    rows.length ? bars(rows, "N·mm", "by row") : "",
  );
}

function renderPressure(data, c) {
  const box = $("pressure");
  if (data.pressure_map) {
    box.replaceChildren(el("img", { src: `/api/figure/${data.id}/pressure.svg`, alt: "slice pressure map", id: "pressure-map" }));
  } else {
    const p = c.rows.map((r) => `${r.name}: p_max ${fmt(r.max_pressure_Pa / 1e6, 4)} MPa`).join("; ");
    box.replaceChildren(el("p", { class: "muted" }, `No roller row with slices in this bearing (${p}).`));
  }
}

function renderStiffness(K) {
  const rowsN = ["F_x", "F_y", "F_z", "M_x", "M_y"], colsN = ["u_x", "u_y", "u_z", "θ_x", "θ_y"];
  // translations in µm, tilts in mrad; forces in N, moments in N·m
  const scale = (i, j) => (j < 3 ? 1e-6 : 1e-3);
  const unit = (i, j) => `${i < 3 ? "N" : "N·m"}/${j < 3 ? "µm" : "mrad"}`;
  const diag = Math.max(...K.map((r, i) => Math.abs(r[i] * scale(i, i))), 1e-30);
  const head = el("tr", {}, el("th", {}, "K"), ...colsN.map((n) => el("th", {}, `∂/∂${n}`)));
  const body = K.map((r, i) => el("tr", {}, el("th", {}, rowsN[i]), ...r.map((v, j) => {
    const shown = Math.abs(v * scale(i, j)) < 1e-9 * diag ? 0 : v * scale(i, j);
    return el("td", { title: `${fmt(v, 6)} SI` }, `${fmt(shown, 4)}`);
  })));
  const units = el("p", { class: "muted small" }, "Units: ", rowsN.map((n, i) => `${n} row ${unit(i, 0)} | ${unit(i, 3)}`).filter((_, i) => i === 0 || i === 3).join("; "),
    ". Fixed DOFs give the stiffness of the constrained bearing; zero rows/columns are unloaded mechanisms.");
  $("stiffness").replaceChildren(el("div", { class: "table-wrap" }, el("table", { id: "stiffness-table" }, head, ...body)), units);
}

function renderRatings(c) {
  const box = $("ratings");
  if (!c.rating) {
    box.replaceChildren(el("p", { class: "muted" }, "Not rated (the notes below say why)."));
    return;
  }
  const cols = [["C", "C_N", 1e-3, "kN"], ["C0", "C0_N", 1e-3, "kN"], ["P_ref", "P_ref_N", 1e-3, "kN"],
    ["L10r", "L10r_rev", 1e-6, "10⁶ rev"], ["L10r", "L10r_h", 1, "h"], ["a_ISO", "a_ISO", 1, ""],
    ["Lnmr", "Lnmr_h", 1, "h"], ["s0", "static_safety", 1, ""], ["p_max", "max_pressure_Pa", 1e-6, "MPa"]];
  const head = el("tr", {}, el("th", {}, "row"), ...cols.map(([n, , , u]) => el("th", {}, u ? `${n} [${u}]` : n)));
  const body = c.rating.rows.map((r) => el("tr", {}, el("td", {}, r.name),
    ...cols.map(([, k, s]) => el("td", {}, r[k] === null || r[k] === undefined ? "—" : fmt(r[k] * s, 4)))));
  const sys = c.rating.system;
  const total = el("tr", {}, el("td", {}, el("b", {}, "bearing")), el("td", {}), el("td", {}), el("td", {}),
    el("td", {}, fmt((sys.L10r_rev ?? null) === null ? null : sys.L10r_rev * 1e-6, 4)), el("td", {}, fmt(sys.L10h_h ?? null, 4)),
    el("td", {}), el("td", {}, fmt(sys.Lnmr_h ?? null, 4)), el("td", {}, fmt(sys.static_safety ?? null, 3)), el("td", {}));
  const lines = [];
  if (sys.headline) lines.push(el("p", { class: "small", id: "life-headline" }, `${sys.headline.method} first: ${sys.headline.why}.`));
  if (sys.life_difference) lines.push(el("p", { class: "small", id: "life-difference" }, `Why they differ: ${sys.life_difference}.`));
  box.replaceChildren(el("div", { class: "table-wrap" }, el("table", {}, head, ...body, total)), ...lines,
    el("p", { class: "muted small" }, `reliability ${c.rating.reliability}, a1 = ${c.rating.a1}; lives in hours need a speed; a_ISO and Lnmr need a lubricant, a temperature and e_C.`));
}

function renderLimits(lim) {
  const box = $("limits");
  if (!lim) {
    box.replaceChildren(el("p", { class: "muted" }, "No catalogue rule covers this bearing (seed composites, slewing rings, models built in code): no limiting speed or minimum load."));
    return;
  }
  const f = lim.flags || {};
  const rpm = (w) => (w === null || w === undefined ? null : w * RPM);
  const line = (name, value, unit, note, bad, id) => el("tr", {},
    el("td", {}, name),
    el("td", { class: bad ? "bad" : "", id, "data-value": value === null || value === undefined ? "" : String(value) }, value === null || value === undefined ? "—" : `${fmt(value, 4)} ${unit}`),
    el("td", { class: "muted small wrap" }, note || ""));
  const rows = [
    line("limiting speed", rpm(lim.limiting_speed_rad_s), "r/min", lim.limiting_speed_source, f.above_limiting_speed, "limit-speed"),
    line("n·d_m", lim.n_dm_mm_rpm, "mm·r/min", `lubrication: ${lim.lubrication || "—"}`, false),
    line("thermal reference speed", rpm(lim.thermal_reference_speed_rad_s), "r/min", lim.thermal_reference_speed_note, f.above_reference_speed, "limit-reference"),
    line("minimum load", lim.minimum_load_N, "N", lim.minimum_load_rule ? `${lim.minimum_load_rule}; load compared ${fmt(lim.load_compared_N, 4)} N` : "", f.below_minimum_load, "limit-minimum-load"),
  ];
  if (lim.seal) rows.push(line(`seal lip speed (${lim.seal})`, lim.seal_lip_speed_m_s, "m/s", lim.seal_lip_speed_limit_m_s ? `limit ${fmt(lim.seal_lip_speed_limit_m_s, 3)} m/s` : "", f.seal_lip_speed_exceeded));
  box.replaceChildren(el("table", { id: "limits-table" }, el("tr", {}, el("th", {}, "limit"), el("th", {}, "value"), el("th", {}, "source / rule")), ...rows),
    ...(lim.notes || []).map((n) => el("p", { class: "muted small" }, n)));
}

function renderSubsurface(c, settings) {
  const rows = c.rows.filter((r) => r.subsurface && r.subsurface.max_von_mises_Pa);
  $("subsurface-card").hidden = !rows.length;
  if (!rows.length) { $("subsurface-out").replaceChildren(); return; }
  const at = (v, z) => (v === null || v === undefined ? "—" : `${fmt(v / 1e6, 4)} @ ${fmt(z * 1e3, 3)}`);
  const head = el("tr", {}, ...["row", "raceway", "p₀ [MPa]", "σ_vM max [MPa @ mm]", "σ_vM/p₀", "τ_max [MPa @ mm]", "τ₀ [MPa @ mm]", "case safety [@ mm]", "case depth needed [mm]"].map((h) => el("th", {}, h)));
  const body = rows.map((r) => {
    const s = r.subsurface;
    const safety = s.case_safety === null ? "through-hardened" : `${fmt(s.case_safety, 3)} @ ${fmt(s.depth_case_safety_m * 1e3, 3)}${s.case_safety_zone ? ` (${s.case_safety_zone})` : ""}`;
    const need = s.required_case_depth_m === null ? "—" : fmt(s.required_case_depth_m * 1e3, 3);
    return el("tr", {}, el("td", {}, r.name), el("td", {}, `${s.raceway || "—"}${s.edge_slice ? " (edge slice)" : ""}`),
      el("td", {}, fmt(s.max_pressure_Pa / 1e6, 4)), el("td", { id: `sub-vm-${r.name}`, "data-value": String(s.max_von_mises_Pa) }, at(s.max_von_mises_Pa, s.depth_max_von_mises_m)),
      el("td", {}, fmt(s.von_mises_over_pressure, 3)), el("td", {}, at(s.max_tresca_Pa, s.depth_max_tresca_m)),
      el("td", {}, at(s.max_orthogonal_shear_Pa, s.depth_max_orthogonal_shear_m)),
      el("td", { class: s.case_safety !== null && s.case_safety < 1 ? "bad" : "" }, safety), el("td", {}, need));
  });
  const charts = rows.map((r) => {
    const s = r.subsurface, z = s.depth_m.map((v) => v * 1e3);
    const mpa = (k) => s[k].map((v) => (v === null ? null : v / 1e6));
    return chart({
      width: 460, height: 240, xlabel: "depth below the surface [mm]", ylabel: "stress [MPa]",
      title: `${r.name}: ${s.raceway} raceway, p₀ = ${fmt(s.max_pressure_Pa / 1e6, 4)} MPa`,
      series: [{ x: z, y: mpa("von_mises_Pa"), label: "von Mises" }, { x: z, y: mpa("tresca_Pa"), label: "Tresca" },
        { x: z, y: mpa("orthogonal_shear_Pa"), label: "τ₀" }, { x: z, y: mpa("strength_Pa"), label: "strength" }],
    });
  });
  const profile = settings ? `${settings.hardness_profile}${settings.case_depth_m ? `; effective case depth ${fmt(settings.case_depth_m * 1e3, 3)} mm` : ""}` : "";
  $("subsurface-out").replaceChildren(el("p", { class: "small" }, profile),
    el("div", { class: "table-wrap" }, el("table", { id: "subsurface-table" }, head, ...body)), el("div", { class: "plots" }, ...charts));
}

// ------------------------------------------------------------------------------------------ pages
function showPage(name) {
  if (!$(`page-${name}`)) name = "bearing";
  for (const page of document.querySelectorAll("main.page")) page.hidden = page.id !== `page-${name}`;
  for (const a of document.querySelectorAll("#tabs a")) a.classList.toggle("active", a.dataset.page === name);
  if (location.hash !== `#${name}`) history.replaceState(null, "", `#${name}`);
  if (PAGES[name] && PAGES[name].shown) PAGES[name].shown();
}

// An error of a workbench page: under the field it names (data-for), else in the page's own error line.
function pageError(page, err, fallback) {
  const box = $(`page-${page}`);
  let target = box.querySelector(`.error[data-for="${CSS.escape(err.field || "")}"]`);
  if (!target) target = $(fallback);
  target.textContent = err.message;
  const input = box.querySelector(`[data-field="${CSS.escape(err.field || "")}"]`);
  if (input) input.classList.add("invalid");
}

function clearPageErrors(page) {
  const box = $(`page-${page}`);
  for (const e of box.querySelectorAll(".error")) e.textContent = "";
  for (const i of box.querySelectorAll(".invalid")) i.classList.remove("invalid");
}

// A table of rows of cells; a cell is text, a Node, or {text, value, cls, id} (value: the exact SI number).
function table(id, head, rows, cls = "data") {
  const cell = (c, tag = "td") => {
    if (c instanceof Node) return el(tag, {}, c);
    if (c !== null && typeof c === "object") {
      return el(tag, { class: c.cls || null, id: c.id || null, title: c.title || null, "data-value": c.value === undefined || c.value === null ? null : String(c.value) }, c.text);
    }
    return el(tag, {}, c === null || c === undefined ? "—" : String(c));
  };
  const t = $(id);
  t.className = cls;
  t.replaceChildren(el("thead", {}, el("tr", {}, ...head.map((h) => cell(h, "th")))), el("tbody", {}, ...rows.map((r) => el("tr", {}, ...r.map((c) => cell(c))))));
  return t;
}

// A number cell: shown in display units, the exact SI value kept in data-value.
function num(value, scale = 1, digits = 4, extra = {}) {
  const v = value === null || value === undefined || Number.isNaN(value) ? null : value;
  return { text: v === null ? "—" : fmt(v * scale, digits), value: v, ...extra };
}

// ------------------------------------------------------------------------------------------ sweep
const SWEEP_OUTPUTS = {
  max_load_N: ["max element load [kN]", 1e-3, false],
  max_pressure_Pa: ["max contact pressure [MPa]", 1e-6, false],
  L10r_rev: ["L10r [10⁶ rev]", 1e-6, true],
  L10h_h: ["L10h [h]", 1, true],
  Lnmr_h: ["Lnmr [h]", 1, true],
  static_safety: ["static safety s0", 1, true],
  friction_torque_Nm: ["friction torque [N·mm]", 1e3, false],
  power_loss_W: ["power loss [W]", 1, false],
};
// factor → [default from, default to, display scale of SI, display unit]
const SWEEP_DEFAULTS = {
  F_x: ["1 kN", "10 kN", 1e-3, "kN"], F_y: ["1 kN", "10 kN", 1e-3, "kN"], F_z: ["0.5 kN", "5 kN", 1e-3, "kN"],
  M_x: ["0 N*m", "100 N*m", 1, "N·m"], M_y: ["0 N*m", "100 N*m", 1, "N·m"],
  speed: ["500 rpm", "6000 rpm", RPM, "rpm"], temperature: ["20 degC", "100 degC", 1, "°C"],
};

function fillSweepFactors(o, free) {
  const fixed = { F_x: "u_x", F_y: "u_y", F_z: "u_z", M_x: "theta_x", M_y: "theta_y" };
  const factors = Object.keys(SWEEP_DEFAULTS).filter((f) => !fixed[f] || free.includes(fixed[f]));
  const options = [...factors.map((f) => el("option", { value: f }, f)),
    ...Object.keys(o.clearances).map((k) => el("option", { value: `geometry.${k}` }, k))];
  const sel = $("sweep-factor");
  const before = sel.value;
  sel.replaceChildren(...options);
  if ([...sel.options].some((op) => op.value === before)) sel.value = before;
  else sweepDefaults();
}

function sweepDefaults() {
  const f = $("sweep-factor").value;
  const d = SWEEP_DEFAULTS[f] || ["0 um", "40 um"];
  $("sweep-from").value = d[0];
  $("sweep-to").value = d[1];
}

async function runSweep() {
  if (!state.source) return;
  $("sweep-error").textContent = "";
  $("sweep-status").textContent = "running…";
  try {
    const n = parseInt($("sweep-n").value, 10);
    const out = await api("/api/sweep", {
      base: request(), factor: $("sweep-factor").value, start: $("sweep-from").value, stop: $("sweep-to").value, n,
    });
    state.sweep = out;
    drawSweep();
    const bad = out.outputs.filter((o) => !o.converged).length;
    $("sweep-status").textContent = `${out.values.length} values in ${out.analyses} analysis${out.analyses > 1 ? "es" : ""}, ${fmt(out.elapsed_ms, 3)} ms${bad ? `; ${bad} did not converge (red)` : ""}`;
  } catch (err) {
    $("sweep-error").textContent = err.message;
    $("sweep-status").textContent = "";
  }
}

function drawSweep() {
  const out = state.sweep;
  if (!out) return;
  const [label, scale, logy] = SWEEP_OUTPUTS[$("sweep-output").value];
  const d = SWEEP_DEFAULTS[out.factor];
  const xs = d ? d[2] : 1e6, xu = d ? d[3] : "µm";
  const key = $("sweep-output").value;
  $("sweep-plot").replaceChildren(chart({
    width: 720, height: 280, logy,
    series: [{ x: out.values.map((v) => v * xs), y: out.outputs.map((o) => (o[key] === null ? null : o[key] * scale)) }],
    bad: out.outputs.map((o) => !o.converged),
    xlabel: `${out.factor.replace("geometry.", "")} [${xu}]`, ylabel: label, title: `${label} vs ${out.factor.replace("geometry.", "")}`,
  }));
}

// ------------------------------------------------------------------------------------------ start
async function start() {
  try {
    state.meta = await api("/api/meta");
  } catch (err) {
    setStatus(`cannot reach the server: ${err.message}`, "error");
    return;
  }
  $("version").textContent = `${state.meta.version} · local`;
  $("example").append(...state.meta.examples.map((n) => el("option", { value: n }, n)));
  $("friction-model").replaceChildren(...state.meta.friction_models.map((n) => el("option", { value: n }, n)));
  $("sweep-output").replaceChildren(...Object.entries(SWEEP_OUTPUTS).map(([k, [l]]) => el("option", { value: k }, l)));
  $("example").addEventListener("change", (e) => e.target.value && openSource({ kind: "example", name: e.target.value }));
  const openDesignation = () => $("designation").value.trim() && openSource({ kind: "designation", name: $("designation").value.trim() });
  $("open-designation").addEventListener("click", openDesignation);
  $("designation").addEventListener("keydown", (e) => e.key === "Enter" && openDesignation());
  $("upload").addEventListener("change", async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    if (file.size > state.meta.max_file_bytes) {
      showError({ message: `${file.name}: file too large (${file.size} bytes); at most ${state.meta.max_file_bytes}`, field: "source" });
      return;
    }
    openSource({ kind: "upload", name: file.name, text: await file.text() });
    e.target.value = "";
  });
  $("case").addEventListener("change", () => {
    fillCase(state.opened.cases.find((c) => c.name === $("case").value));
    analyze();
  });
  for (const id of [...LOADS, "speed", "temperature", "contamination"]) {
    $(id).addEventListener("change", scheduleAnalyze);
    $(id).addEventListener("keydown", (e) => e.key === "Enter" && scheduleAnalyze());
  }
  for (const id of ["lubricant", "friction-model", "heat", "lube-base_oil", "lube-thickener"]) $(id).addEventListener("change", scheduleAnalyze);
  for (const input of document.querySelectorAll("[data-lube], [data-thermal]")) input.addEventListener("change", scheduleAnalyze);
  $("analyze").addEventListener("click", analyze);
  $("sweep-factor").addEventListener("change", sweepDefaults);
  $("sweep-run").addEventListener("click", runSweep);
  $("sweep-output").addEventListener("change", drawSweep);
  $("subsurface").addEventListener("change", scheduleAnalyze);
  for (const name of Object.keys(PAGES)) {
    try { PAGES[name].start(state.meta); } catch (err) { console.error(name, err); }
  }
  window.addEventListener("hashchange", () => showPage(location.hash.slice(1)));
  showPage(location.hash.slice(1) || "bearing");
  setStatus("choose an example, type a designation or upload a file", "ready");
}

document.addEventListener("DOMContentLoaded", start);
