// bearingkit serve: the catalogue page — browse and filter the standard bearings, select by life, compare up
// to four side by side at one operating point. Uses the helpers of app.js (el, api, fmt, table, num …).
"use strict";

const CMP = { list: [], max: 4 };

function catalogueRequest() {
  const bounds = {};
  for (const input of document.querySelectorAll("[data-bound]")) {
    if (input.value.trim()) bounds[input.dataset.bound] = input.value.trim();
  }
  return { kind: $("cat-kind").value, pattern: $("cat-pattern").value.trim(), bounds };
}

async function catalogueSearch() {
  clearPageErrors("catalogue");
  $("cat-count").textContent = "searching…";
  try {
    const out = await api("/api/catalogue/search", catalogueRequest());
    const rows = out.rows.map((r) => [
      el("button", { type: "button", class: "open", "data-designation": r.designation, title: "open it on the Bearing page" }, "Open"),
      { text: r.designation, cls: "designation" },
      r.family.replaceAll("_", " "),
      num(r.d_m, 1e3, 4), num(r.D_m, 1e3, 4), num(r.B_m, 1e3, 4),
      num(r.C_N, 1e-3, 4, { title: `${r.rating_source}: catalogue ${fmt(r.C_catalogue_N, 4)} N, estimate ${fmt(r.C_estimate_N, 4)} N` }),
      num(r.C0_N, 1e-3, 4), r.rating_source, num(r.mass_estimate_kg, 1, 3),
      el("input", { type: "checkbox", class: "compare", "data-designation": r.designation, title: "compare (up to four)", ...(CMP.list.includes(r.designation) ? { checked: "" } : {}) }),
    ]);
    table("cat-table", ["", "designation", "family", "d [mm]", "D [mm]", "B [mm]", "C [kN]", "C0 [kN]", "C from", "mass [kg] (est.)", "compare"], rows);
    $("cat-count").textContent = `${out.count} bearing${out.count === 1 ? "" : "s"} match${out.count > out.rows.length ? `; the first ${out.rows.length} shown` : ""}. C is the catalogue's where it prints one, else the ISO 281 estimate of the estimated geometry; masses are estimates.`;
  } catch (err) {
    $("cat-count").textContent = "";
    pageError("catalogue", err, "catalogue-error");
  }
}

// ------------------------------------------------------------------------------------------ selection
async function catalogueSelect() {
  clearPageErrors("catalogue");
  $("sel-status").textContent = "selecting: the catalogue method screens every row, the full analysis the lightest…";
  try {
    const out = await api("/api/catalogue/select", {
      radial: $("sel-radial").value.trim(), axial: $("sel-axial").value.trim(), speed: $("sel-speed").value.trim(),
      life: $("sel-life").value.trim(), kind: $("sel-kind").value, count: parseInt($("sel-count").value, 10) || 5,
    });
    const rows = [...out.candidates, ...out.rejected].map((c) => [
      el("button", { type: "button", class: "open", "data-designation": c.designation }, "Open"),
      c.designation, num(c.d_m, 1e3, 4), num(c.D_m, 1e3, 4), num(c.mass_estimate_kg, 1, 3),
      num(c.C_iso281_N, 1e-3, 4), num(c.C0_iso76_N, 1e-3, 4),
      num(c.L10h_iso281_h, 1, 4), num(c.L10h_iso16281_h, 1, 4), num(c.s0_iso76, 1, 3), num(c.static_safety, 1, 3),
      c.reason ? { text: c.reason, cls: "bad" } : "meets both lives and s0",
      el("button", { type: "button", class: "add-compare", "data-designation": c.designation }, "Compare"),
    ]);
    table("sel-table", ["", "designation", "d [mm]", "D [mm]", "mass [kg]", "C [kN]", "C0 [kN]", "L10h ISO 281 [h]", "L10h ISO/TS 16281 [h]", "s0 ISO 76 (C0/P0)", "s0 (p_max)", "verdict", ""], rows);
    $("sel-status").textContent = `${out.candidates.length} candidate(s), lightest first. ${out.notes.join(" · ")}`;
  } catch (err) {
    $("sel-status").textContent = "";
    pageError("catalogue", err, "select-error");
  }
}

// ------------------------------------------------------------------------------------------ comparison
function compareAdd(name) {
  name = name.trim().replace(/\s+/g, " ");
  if (!name || CMP.list.includes(name)) return;
  if (CMP.list.length >= CMP.max) {
    $("compare-error").textContent = `at most ${CMP.max} bearings side by side: remove one first`;
    return;
  }
  CMP.list.push(name);
  compareChips();
}

function compareRemove(name) {
  CMP.list = CMP.list.filter((n) => n !== name);
  compareChips();
}

function compareChips() {
  $("compare-error").textContent = "";
  $("cmp-list").replaceChildren(...(CMP.list.length ? CMP.list.map((n) => el("span", { class: "chip", "data-designation": n }, n,
    el("button", { type: "button", class: "remove", "data-designation": n, title: "remove" }, "×"))) : [el("span", { class: "muted" }, "none yet: tick rows above, or add one")]));
  for (const box of document.querySelectorAll("#cat-table input.compare")) box.checked = CMP.list.includes(box.dataset.designation);
}

// Comparison rows: [label, key, scale, digits, unit, better ("max"|"min"|null)].
const COMPARE_ROWS = [
  ["bearing", "bearing_name"], ["d × D × B [mm]", "dimensions"], ["mass [kg] (estimate)", "mass", 1, 3, "", "min"],
  ["C [kN]", "C", 1e-3, 4, "", "max"], ["C0 [kN]", "C0", 1e-3, 4, "", "max"],
  ["L10h ISO 281 [h]", "L10h_iso281_h", 1, 4, "", "max"], ["L_nmh ISO 281 [h]", "Lnm_iso281_h", 1, 4, "", "max"],
  ["L10h ISO/TS 16281 [h]", "L10h_iso16281_h", 1, 4, "", "max"], ["L_nmrh ISO/TS 16281 [h]", "Lnmr_h", 1, 4, "", "max"],
  ["static safety s0", "static_safety", 1, 3, "", "max"], ["Q_max [kN]", "max_load_N", 1e-3, 4, "", "min"],
  ["p_max [MPa]", "max_pressure_Pa", 1e-6, 4, "", "min"],
  ["friction torque [N·mm]", "friction_torque_Nm", 1e3, 4, "", "min"], ["power loss [W]", "power_loss_W", 1, 4, "", "min"],
  ["friction model", "friction_model"],
  ["radial stiffness [N/µm]", "k_radial_N_per_m", 1e-6, 4, "", "max"], ["axial stiffness [N/µm]", "k_axial_N_per_m", 1e-6, 4, "", "max"],
  ["tilt stiffness [N·m/mrad]", "k_tilt_Nm_per_rad", 1e-3, 4, "", "max"],
  ["limiting speed [r/min]", "limiting_speed_rad_s", 60 / (2 * Math.PI), 4, "", "max"],
  ["thermal reference speed [r/min]", "thermal_reference_speed_rad_s", 60 / (2 * Math.PI), 4, "", "max"],
  ["minimum load [N]", "minimum_load_N", 1, 4, "", null],
  ["converged", "converged"], ["warnings", "warning_count", 1, 3, "", "min"],
];

async function compareRun() {
  clearPageErrors("catalogue");
  if (!CMP.list.length) {
    $("compare-error").textContent = "choose bearings to compare first: tick rows of the catalogue, or add a designation";
    return;
  }
  const loads = {};
  for (const input of document.querySelectorAll("[data-load]")) if (input.value.trim()) loads[input.dataset.load] = input.value.trim();
  const point = {
    loads, speed: $("cmp-speed").value.trim(), temperature: $("cmp-temperature").value.trim(),
    lubricant: $("cmp-lubricant").value, contamination: $("cmp-contamination").value.trim(), friction_model: $("cmp-friction").value,
  };
  $("cmp-status").textContent = `analysing ${CMP.list.length} bearing(s) at the same operating point…`;
  try {
    const out = await api("/api/catalogue/compare", { designations: CMP.list, point });
    const cols = out.bearings.map((b) => ({
      ...b,
      dimensions: b.catalogue.d_m ? `${fmt(b.catalogue.d_m * 1e3, 4)} × ${fmt(b.catalogue.D_m * 1e3, 4)} × ${fmt(b.catalogue.B_m * 1e3, 4)}` : "—",
      mass: b.catalogue.mass_estimate_kg ?? null, C: b.catalogue.C_N ?? null, C0: b.catalogue.C0_N ?? null,
      converged: b.converged ? "yes" : "NO", warning_count: b.warnings.length,
    }));
    const rows = COMPARE_ROWS.map(([label, key, scale, digits, , better]) => {
      const values = cols.map((c) => c[key]);
      const nums = values.filter((v) => typeof v === "number" && Number.isFinite(v));
      const differ = nums.length > 1 && Math.max(...nums) > Math.min(...nums);
      const best = better && differ ? (better === "max" ? Math.max(...nums) : Math.min(...nums)) : null;
      return [label, ...cols.map((c, i) => {
        const v = values[i];
        const id = `cmp-${i}-${key}`;
        if (typeof v === "number") return num(v, scale || 1, digits || 4, { id, cls: v === best ? "best" : null });
        return { text: v === null || v === undefined ? "—" : String(v), id, cls: key === "converged" && v !== "yes" ? "bad" : null };
      })];
    });
    const head = ["", ...cols.map((c, i) => el("span", {}, c.designation, " ",
      el("button", { type: "button", class: "open", "data-designation": c.designation, id: `cmp-open-${i}` }, "Open")))];
    table("cmp-table", head, rows);
    $("cmp-warnings").replaceChildren(...cols.flatMap((c) => c.warnings.map((w) => el("li", {}, `${c.designation}: ${w}`))),
      ...cols.filter((c) => c.life_difference).map((c) => el("li", { class: "muted" }, `${c.designation}: why the two lives differ — ${c.life_difference}`)));
    $("cmp-status").textContent = `${cols.length} bearings at F = ${Object.entries(loads).map(([k, v]) => `${k} ${v}`).join(", ") || "no load"}, ${point.speed || "at rest"}, ${point.lubricant || "no lubricant"}; ${fmt(out.elapsed_ms, 3)} ms. Green: the best of the row. ISO 281 is the catalogue calculation, ISO/TS 16281 follows the computed load distribution of the estimated geometry.`;
  } catch (err) {
    $("cmp-status").textContent = "";
    const m = /^compare\.(\d+)$/.exec(err.field || "");
    pageError("catalogue", m ? { message: `${CMP.list[+m[1]]}: ${err.message}`, field: "compare" } : err, "compare-error");
  }
}

PAGES.catalogue = {
  start(meta) {
    const kinds = ["", ...(meta.catalogue_kinds || [])];
    for (const id of ["cat-kind", "sel-kind"]) {
      $(id).replaceChildren(...kinds.map((k) => el("option", { value: k }, k ? k.replaceAll("_", " ") : "all kinds")));
    }
    $("sel-kind").value = "deep_groove";
    $("cmp-lubricant").replaceChildren(el("option", { value: "" }, "none"), ...meta.lubricants.map((n) => el("option", { value: n }, n)));
    $("cmp-lubricant").value = meta.lubricants.includes("ISO_VG68") ? "ISO_VG68" : "";
    $("cmp-friction").replaceChildren(...meta.friction_models.map((n) => el("option", { value: n }, n)));
    $("cat-search").addEventListener("click", catalogueSearch);
    for (const input of document.querySelectorAll("#page-catalogue .filters input[data-bound], #cat-pattern")) {
      input.addEventListener("keydown", (e) => e.key === "Enter" && catalogueSearch());
    }
    $("cat-kind").addEventListener("change", catalogueSearch);
    $("sel-run").addEventListener("click", catalogueSelect);
    $("cmp-run").addEventListener("click", compareRun);
    $("cmp-add-button").addEventListener("click", () => { compareAdd($("cmp-add").value); $("cmp-add").value = ""; });
    $("cmp-add").addEventListener("keydown", (e) => { if (e.key === "Enter") { compareAdd($("cmp-add").value); $("cmp-add").value = ""; } });
    $("page-catalogue").addEventListener("click", (e) => {
      const t = e.target;
      if (t.matches("button.open")) openDesignation(t.dataset.designation);
      else if (t.matches("button.add-compare")) compareAdd(t.dataset.designation);
      else if (t.matches("button.remove")) compareRemove(t.dataset.designation);
    });
    $("page-catalogue").addEventListener("change", (e) => {
      const t = e.target;
      if (!t.matches("input.compare")) return;
      if (t.checked) compareAdd(t.dataset.designation); else compareRemove(t.dataset.designation);
      t.checked = CMP.list.includes(t.dataset.designation);
    });
    compareChips();
  },
  shown() {
    if (!$("cat-table").children.length) catalogueSearch();
  },
};
