// bearingkit serve: the shaft and drivetrain pages — a system file (an example, an upload or the editor's
// text) solved by the server as `bearingkit shaft` / `bearingkit system` do; every bearing's results, the
// system life, the shaft lines, and for a drivetrain the meshes and the power flow. Helpers from app.js.
"use strict";

const SYSTEM = { shaft: { data: null, source: null, seq: 0 }, drivetrain: { data: null, source: null, seq: 0 } };

function systemPageHtml(kind) {
  const k = (id) => `${kind}-${id}`;
  const left = el("section", { class: "card" },
    el("h2", {}, kind === "shaft" ? "Shaft file" : "Drivetrain file"),
    el("div", { class: "field" }, el("label", { for: k("example") }, "Example"),
      el("select", { id: k("example") }, el("option", { value: "" }, "— choose an example —"))),
    el("div", { class: "field" }, el("label", { for: k("upload") }, "Upload TOML"), el("input", { id: k("upload"), type: "file", accept: ".toml,text/plain" })),
    el("div", { class: "field" }, el("label", { for: k("text") }, "The file (edit it, then Analyse)"),
      el("textarea", { id: k("text"), class: "toml", spellcheck: "false", placeholder: `a ${kind} file: see docs/${kind === "shaft" ? "systems" : "drivetrains"}.md` })),
    el("p", { class: "error", id: k("error"), "data-for": "source" }),
    el("div", { class: "grid2" },
      el("div", { class: "field" }, el("label", { for: k("friction") }, "Friction model"), el("select", { id: k("friction") })),
      el("div", { class: "field" }, el("label", { for: k("contamination") }, "e_C (all bearings)"), el("input", { id: k("contamination"), placeholder: "the file's" }))),
    el("div", { class: "field" }, el("label", { for: k("heat") }, el("input", { type: "checkbox", id: k("heat") }), " find each bearing's temperature (heat balance; on when the file has [thermal])")),
    el("p", {}, el("button", { id: k("analyze"), type: "button", class: "primary" }, "Analyse")),
    el("p", { class: "muted small" }, "Bearing files named in the file are read from the example bearings by name; give your own bearings by designation (designation = \"6209\") or stiffness."));
  const right = el("section", {},
    el("div", { class: "card" },
      el("h2", {}, el("span", { id: k("title") }, "Results"), " ", el("span", { id: k("status"), class: "muted small", "data-state": "idle" })),
      el("div", { class: "field inline-case", id: k("case-field") }, el("label", { for: k("case") }, "Load case"), el("select", { id: k("case") })),
      el("div", { id: k("summary"), class: "summary" }),
      el("ul", { id: k("warnings"), class: "warnings" })),
    el("div", { class: "card" }, el("h2", {}, kind === "shaft" ? "Layout" : "Layout (end and side view)"), el("div", { id: k("layout"), class: "plots" })),
    el("div", { class: "card" }, el("h2", {}, "Bearings"), el("div", { class: "table-wrap" }, el("table", { id: k("bearings") }))),
    el("div", { class: "card", id: k("heat-card"), hidden: true }, el("h2", {}, "Heat balance of each bearing"), el("p", { class: "thermal", id: k("heat-note") }), el("div", { class: "table-wrap" }, el("table", { id: k("heat-table") }))),
    kind === "drivetrain" ? el("div", { class: "card" }, el("h2", {}, "Meshes"), el("div", { class: "table-wrap" }, el("table", { id: k("meshes") }))) : "",
    kind === "drivetrain" ? el("div", { class: "card" }, el("h2", {}, "Power flow"), el("div", { id: k("power") })) : "",
    el("div", { class: "card" }, el("h2", {}, "Deflection and bending moment"), el("div", { id: k("lines"), class: "plots" })),
    el("details", { class: "card" }, el("summary", {}, "The report's figure of this load case"), el("div", { id: k("figure"), class: "figures" })),
    el("div", { class: "card" }, el("h2", {}, "Notes"), el("ul", { id: k("notes"), class: "notes small" })));
  $(`page-${kind}`).replaceChildren(left, right);
}

function systemRequest(kind) {
  const s = SYSTEM[kind];
  return {
    system: kind,
    source: { kind: "upload", name: s.source ? s.source.name : `${kind}.toml`, text: $(`${kind}-text`).value },
    friction_model: $(`${kind}-friction`).value,
    contamination: $(`${kind}-contamination`).value.trim(),
    heat: $(`${kind}-heat`).checked,
  };
}

function systemClear(kind) {
  SYSTEM[kind].data = null;
  for (const id of ["summary", "warnings", "layout", "bearings", "meshes", "power", "lines", "figure", "notes"]) {
    const node = $(`${kind}-${id}`);
    if (node) node.replaceChildren();
  }
  $(`${kind}-case`).replaceChildren();
  $(`${kind}-case-field`).hidden = true;
  $(`${kind}-title`).textContent = "Results";
}

async function systemOpen(kind, source) {
  clearPageErrors(kind);
  systemClear(kind);
  if (source.kind !== "example") $(`${kind}-example`).value = "";
  try {
    if (source.kind === "example") {
      const out = await api("/api/system/open", { system: kind, source });
      $(`${kind}-text`).value = out.text;
    } else {
      $(`${kind}-text`).value = source.text;
    }
    SYSTEM[kind].source = { name: source.name };
    await systemAnalyze(kind);
  } catch (err) {
    pageError(kind, err, `${kind}-error`);
  }
}

async function systemAnalyze(kind) {
  clearPageErrors(kind);
  const status = $(`${kind}-status`);
  if (!$(`${kind}-text`).value.trim()) {
    $(`${kind}-error`).textContent = `open an example, upload a ${kind} file or type one first`;
    return;
  }
  const seq = ++SYSTEM[kind].seq;
  status.textContent = "solving…";
  status.dataset.state = "busy";
  try {
    const out = await api("/api/system/analyze", systemRequest(kind));
    if (seq !== SYSTEM[kind].seq) return;
    SYSTEM[kind].data = out;
    const cases = out.analysis.cases;
    $(`${kind}-case`).replaceChildren(...cases.map((c, i) => el("option", { value: String(i) }, c.case)));
    $(`${kind}-case-field`).hidden = cases.length < 2;
    $(`${kind}-title`).textContent = kind === "shaft" ? out.analysis.shaft : out.analysis.drivetrain;
    systemRender(kind);
    status.textContent = `solved in ${fmt(out.elapsed_ms, 3)} ms`;
    status.dataset.state = "ready";
  } catch (err) {
    if (seq !== SYSTEM[kind].seq) return;
    systemClear(kind);
    status.textContent = "";
    status.dataset.state = "error";
    pageError(kind, err, `${kind}-error`);
  }
}

function systemRender(kind) {
  const out = SYSTEM[kind].data;
  if (!out) return;
  const i = parseInt($(`${kind}-case`).value || "0", 10);
  const a = out.analysis, c = a.cases[i];
  if (kind === "shaft") renderShaft(a, c); else renderDrivetrain(out, a, c);
  $(`${kind}-warnings`).replaceChildren(...(c.converged ? [] : [el("li", {}, `did not converge: ${c.reason || "no reason given"}`)]), ...c.warnings.map((w) => el("li", {}, w)));
  $(`${kind}-notes`).replaceChildren(...a.notes.map((n) => el("li", {}, n)));
  $(`${kind}-figure`).replaceChildren(el("img", { src: out.figures[i], alt: `${kind} figure of case ${c.case}`, id: `${kind}-figure-img` }));
}

function lineCharts(z, u, zm, m, title) {
  const um = (v) => v * 1e6, mm = z.map((v) => v * 1e3), mmm = zm.map((v) => v * 1e3);
  const radial = u.x.map((v, j) => Math.hypot(v, u.y[j]));
  const mabs = m.x.map((v, j) => Math.hypot(v, m.y[j]));
  return [
    chart({ width: 520, height: 230, xlabel: "z [mm]", ylabel: "deflection [µm]", title: `${title}deflection of the axis`,
      series: [{ x: mm, y: u.x.map(um), label: "u_x" }, { x: mm, y: u.y.map(um), label: "u_y" }, { x: mm, y: radial.map(um), label: "|u|" }] }),
    chart({ width: 520, height: 230, xlabel: "z [mm]", ylabel: "bending moment [N·m]", title: `${title}bending moment`,
      series: [{ x: mmm, y: m.x, label: "M_x" }, { x: mmm, y: m.y, label: "M_y" }, { x: mmm, y: mabs, label: "|M|" }] }),
  ];
}

// The shaft's half outline, bearings (▲ locating, △ floating), gears and masses, from the file as read.
function shaftLayout(inputs, c) {
  const W = 640, H = 190, m = 30;
  const sections = inputs.sections, zmax = Math.max(...sections.map((s) => s.end_m)), zmin = Math.min(...sections.map((s) => s.start_m));
  const rmax = Math.max(...sections.map((s) => s.outer_diameter_m)) / 2;
  const gears = inputs.gears || [];
  const rshow = Math.max(rmax * 1.6, ...gears.map((g) => Math.min(g.pitch_diameter_m / 2, rmax * 3)));
  const px = (z) => m + ((z - zmin) / (zmax - zmin || 1)) * (W - 2 * m), py = (r) => H / 2 - (r / rshow) * (H / 2 - 22);
  const s = svg("svg", { width: W, height: H + 20, viewBox: `0 0 ${W} ${H + 20}`, role: "img", id: "shaft-layout-svg" });
  s.append(svg("title", {}, "shaft outline, bearings and gears"));
  for (const sec of sections) {
    for (const sign of [1, -1]) {
      const y1 = py(sign * sec.outer_diameter_m / 2), y2 = py(sign * sec.inner_diameter_m / 2);
      s.append(svg("rect", { x: px(sec.start_m), y: Math.min(y1, y2), width: px(sec.end_m) - px(sec.start_m), height: Math.abs(y2 - y1), fill: "#bdc3c7" }));
    }
  }
  for (const g of gears) {
    const r = Math.min(g.pitch_diameter_m / 2, rshow * 0.95);
    s.append(svg("line", { x1: px(g.position_m), x2: px(g.position_m), y1: py(r), y2: py(-r), stroke: "#8e44ad", "stroke-width": 4, opacity: 0.6 }));
    s.append(svg("text", { x: px(g.position_m), y: py(r) - 3, "text-anchor": "middle" }, g.name));
  }
  for (const b of inputs.bearings) {
    const x = px(b.position_m), y = py(-rmax) + 10;
    const tri = svg("path", { d: `M${x},${y} l-8,14 l16,0 Z`, fill: b.axial === "locating" ? "#2c3e50" : "#fff", stroke: "#2c3e50", class: "bearing-mark" });
    tri.append(svg("title", {}, `${b.name}: ${b.bearing}, ${b.axial}`));
    s.append(tri);
    s.append(svg("text", { x, y: y + 27, "text-anchor": "middle" }, b.name));
  }
  for (const f of (c && inputs.load_cases[c.index] ? inputs.load_cases[c.index].forces : []) || []) {
    s.append(svg("text", { x: px(f.position_m), y: 14, "text-anchor": "middle", fill: "#c0392b" }, `↓ ${f.name}`));
  }
  s.append(svg("text", { x: m, y: H + 14, class: "muted" }, `z from ${fmt(zmin * 1e3, 4)} to ${fmt(zmax * 1e3, 4)} mm; ▲ locating, △ floating bearing`));
  return s;
}

function renderShaft(a, c) {
  const rating = c.rating.system;
  // ISO 281 first (the bearings' catalogue lives, Weibull-combined), ISO/TS 16281 beside it
  const iso = [
    metric("shaft-system-l10-iso", "system L10h (ISO 281)", rating.L10h_iso281_h ?? null, 1, "h"),
    metric("shaft-system-lnm-iso", "system L_nmh (ISO 281)", rating.Lnm_iso281_h ?? null, 1, "h")];
  const ts = [
    metric("shaft-system-l10", "system L10h (ISO/TS 16281)", rating.L10h_h ?? null, 1, "h"),
    metric("shaft-system-lnm", "system L_nmh (ISO/TS 16281)", rating.Lnmr_h ?? null, 1, "h")];
  const isoFirst = !rating.headline || rating.headline.method === "ISO 281";
  const summary = [
    ...(isoFirst ? [...iso, ...ts] : [...ts, ...iso]),
    metric("shaft-deflection", "max radial deflection", c.shaft.max_radial_deflection_m, 1e6, "µm"),
    metric("shaft-moment", "max bending moment", c.shaft.max_bending_moment_Nm, 1, "N·m"),
    metric("shaft-power", "power loss (bearings)", c.power_loss_W ?? null, 1, "W"),
  ];
  if (rating.life_difference) summary.push(el("p", { class: "muted", id: "shaft-life-difference" }, `why they differ: ${rating.life_difference}`));
  $("shaft-summary").replaceChildren(...summary);
  $("shaft-layout").replaceChildren(shaftLayout(a.inputs, { index: parseInt($("shaft-case").value || "0", 10) }));
  const rows = c.bearings.map((b, j) => {
    const s = b.summary, r = s.reaction_on_shaft, iso = (c.rating.bearings || {})[b.name] || {};
    return [b.name, b.bearing, num(b.position_m, 1e3, 4),
      num(r.F_x_N, 1, 5, { id: `shaft-reaction-${j}-Fx` }), num(r.F_y_N, 1, 5, { id: `shaft-reaction-${j}-Fy` }), num(r.F_z_N, 1, 4, { id: `shaft-reaction-${j}-Fz` }),
      num(r.M_x_Nm, 1, 3), num(r.M_y_Nm, 1, 3), num(s.misalignment_rad, 1e3, 3), num(s.max_pressure_Pa, 1e-6, 4), num(s.static_safety, 1, 3, { cls: s.static_safety !== null && s.static_safety < 1 ? "bad" : null }),
      num(s.L10h_iso281_h ?? iso.L10h_iso281_h ?? null, 1, 4), num(s.Lnm_iso281_h ?? iso.Lnm_iso281_h ?? null, 1, 4), num(s.L10h_h, 1, 4), num(s.Lnmr_h, 1, 4), num(s.kappa_min, 1, 3), num(s.friction_torque_Nm, 1e3, 4), num(s.power_loss_W, 1, 3),
      num(s.temperature_C, 1, 4, { id: `shaft-temperature-${j}`, title: s.temperature_found ? "found by the heat balance" : "input" }), s.warnings];
  });
  table("shaft-bearings", ["bearing", "", "z [mm]", "F_x [N]", "F_y [N]", "F_z [N]", "M_x [N·m]", "M_y [N·m]", "tilt [mrad]", "p_max [MPa]", "s0", "L10h ISO 281 [h]", "L_nmh ISO 281 [h]", "L10rh TS [h]", "L_nmrh TS [h]", "κ", "M_f [N·mm]", "P [W]", "T [°C]", "warn."], rows);
  renderSystemHeat("shaft", c);
  const d = c.shaft.deflection, bm = c.shaft.bending_moment;
  $("shaft-lines").replaceChildren(...lineCharts(d.z_m, { x: d.u_x_m, y: d.u_y_m }, bm.z_m, { x: bm.M_x_Nm, y: bm.M_y_Nm }, ""));
}

// Each bearing's found temperature and its balance (the `thermal` block of each bearing's analysis).
function renderSystemHeat(kind, c) {
  const found = c.bearings.filter((b) => b.analysis && b.analysis.thermal);
  $(`${kind}-heat-card`).hidden = found.length === 0;
  if (!found.length) { $(`${kind}-heat-table`).replaceChildren(); $(`${kind}-heat-note`).textContent = ""; return; }
  $(`${kind}-heat-note`).textContent = "Operating temperatures FOUND by each bearing's heat balance (friction heat P(T) at the load the system puts on it = seats/housing H (T − T_amb) + circulating oil); κ, a_ISO, L_nm and friction above are at T.";
  const rows = found.map((b, j) => {
    const t = b.analysis.thermal;
    return [b.summary.name, num(t.temperature_C, 1, 4, { id: `${kind}-heat-${j}-T` }), num(t.friction_heat_W, 1, 5), num(t.conducted_heat_W, 1, 5), num(t.oil_heat_W, 1, 5),
      num(t.heat_dissipation_W_K, 1, 4), t.heat_dissipation_from, num(t.ambient_C, 1, 4), t.balance_residual_W.toExponential(1), t.balance_relative.toExponential(1), t.iterations, t.friction_model];
  });
  table(`${kind}-heat-table`, ["bearing", "T [°C]", "P(T) [W]", "seats/housing [W]", "oil [W]", "H [W/K]", "H from", "T_amb [°C]", "residual [W]", "residual / P", "iterations", "friction model"], rows);
}

function renderDrivetrain(out, a, c) {
  const p = c.power;
  $("drivetrain-summary").replaceChildren(
    metric("dt-system-l10-iso", "system L10h (ISO 281)", c.system.L10h_iso281_h ?? null, 1, "h"),
    metric("dt-system-l10", "system L10h (ISO/TS 16281)", c.system.L10h_h ?? null, 1, "h"),
    metric("dt-efficiency", "efficiency", p ? p.efficiency : null, 100, "%", 5),
    metric("dt-loss", "power loss", p ? p.loss_W : null, 1, "W"),
    metric("dt-held", "held torque", c.held_torque_Nm, 1, "N·m"),
    ...(c.system.life_difference ? [el("p", { class: "muted", id: "dt-life-difference" }, `why they differ: ${c.system.life_difference}`)] : []));
  $("drivetrain-layout").replaceChildren(el("img", { src: out.layout, alt: "drivetrain layout", id: "drivetrain-layout-img" }));
  table("drivetrain-bearings", ["bearing", "on", "F_r [N]", "F_a [N]", "tilt [mrad]", "p_max [MPa]", "s0", "L10h ISO 281 [h]", "L10rh TS [h]", "L_nmrh TS [h]", "M_f [N·mm]", "P [W]", "T [°C]", "warn."],
    c.bearings.map((b, j) => {
      const s = b.summary;
      return [s.name, `${s.inner}/${s.outer}`, num(s.radial_load_N, 1, 5, { id: `dt-bearing-${j}-Fr` }), num(s.axial_load_N, 1, 4), num(s.misalignment_rad, 1e3, 3),
        num(s.max_pressure_Pa, 1e-6, 4), num(s.static_safety, 1, 3), num(s.L10h_iso281_h, 1, 4), num(s.L10h_h, 1, 4), num(s.Lnmr_h, 1, 4),
        num(s.friction_torque_Nm, 1e3, 4), num(s.power_loss_W, 1, 3), num(s.temperature_C, 1, 4, { title: s.temperature_found ? "found by the heat balance" : "input" }), s.warnings];
    }));
  renderSystemHeat("drivetrain", c);
  table("drivetrain-meshes", ["mesh", "gears", "F_n [N]", "F_t [N]", "F_r [N]", "F_a [N]", "T_a [N·m]", "T_b [N·m]", "k [N/µm]", "ε_α", "ratio"],
    c.meshes.map((m) => [m.name, m.gears.map((g) => g.join(".")).join(" – "), num(m.normal_force_N, 1, 5), num(m.on_a.tangential_N, 1, 5), num(m.on_a.radial_N, 1, 5),
      num(m.on_a.axial_N, 1, 5), num(m.on_a.torque_Nm, 1, 5), num(m.on_b.torque_Nm, 1, 5), num(m.stiffness_N_per_m, 1e-6, 4), num(m.contact_ratio, 1, 4), num(m.ratio, 1, 5)]));
  const box = $("drivetrain-power");
  if (!p) {
    box.replaceChildren(el("p", { class: "muted" }, "No power flow: the load case has no speed."));
  } else {
    const rpm = 60 / (2 * Math.PI);
    const losses = [...Object.entries(p.bearing_loss_W).map(([k, v]) => [`bearing ${k}`, v]), ...Object.entries(p.mesh).map(([k, v]) => [`mesh ${k}`, v.loss_W])];
    box.replaceChildren(
      el("p", {}, `in ${fmt(p.input_W, 5)} W → out ${fmt(p.output_W, 5)} W; losses ${fmt(p.loss_W, 4)} W; efficiency `, el("b", { id: "dt-efficiency-text", "data-value": String(p.efficiency) }, `${fmt(p.efficiency * 100, 5)} %`)),
      el("p", { class: "small" }, `speeds [r/min]: ${Object.entries(p.speeds_rad_s).map(([k, v]) => `${k} ${fmt(v * rpm, 5)}`).join(", ")}`),
      bars(losses, "W", "losses by part"));
  }
  const shafts = Object.entries(c.shafts);
  const deflection = chart({ width: 520, height: 230, xlabel: "z [mm]", ylabel: "|u| [µm]", title: "radial deflection of every shaft",
    series: shafts.map(([name, s]) => ({ x: s.deflection.z_m.map((v) => v * 1e3), y: s.deflection.u_x_m.map((v, j) => Math.hypot(v, s.deflection.u_y_m[j]) * 1e6), label: name })) });
  const moment = chart({ width: 520, height: 230, xlabel: "z [mm]", ylabel: "|M| [N·m]", title: "bending moment of every shaft",
    series: shafts.map(([name, s]) => ({ x: s.bending_moment.z_m.map((v) => v * 1e3), y: s.bending_moment.M_x_Nm.map((v, j) => Math.hypot(v, s.bending_moment.M_y_Nm[j])), label: name })) });
  $("drivetrain-lines").replaceChildren(deflection, moment);
}

function systemStart(kind, meta) {
  systemPageHtml(kind);
  const names = (meta.systems || {})[kind] || [];
  $(`${kind}-example`).append(...names.map((n) => el("option", { value: n }, n)));
  const models = kind === "drivetrain" ? meta.friction_models.filter((n) => n !== "auto") : meta.friction_models;
  $(`${kind}-friction`).replaceChildren(...models.map((n) => el("option", { value: n }, n)));
  $(`${kind}-example`).addEventListener("change", (e) => e.target.value && systemOpen(kind, { kind: "example", name: e.target.value }));
  $(`${kind}-upload`).addEventListener("change", async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    if (file.size > meta.max_file_bytes) {
      $(`${kind}-error`).textContent = `${file.name}: file too large (${file.size} bytes); at most ${meta.max_file_bytes}`;
      return;
    }
    await systemOpen(kind, { kind: "upload", name: file.name, text: await file.text() });
    e.target.value = "";
  });
  $(`${kind}-analyze`).addEventListener("click", () => systemAnalyze(kind));
  $(`${kind}-case`).addEventListener("change", () => systemRender(kind));
  $(`${kind}-case-field`).hidden = true;
}

PAGES.shaft = { start: (meta) => systemStart("shaft", meta) };
PAGES.drivetrain = { start: (meta) => systemStart("drivetrain", meta) };
