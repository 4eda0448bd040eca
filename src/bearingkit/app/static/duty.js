// bearingkit serve: the duty-cycle page — the bins of a load spectrum in a table (edit, add, remove), rated
// by the server in one batch on the bearing page's bearing and combined by Palmgren–Miner; each bin's life,
// static safety and damage share. Helpers from app.js.
"use strict";

const DUTY_FIELDS = ["F_x", "F_y", "F_z", "M_x", "M_y", "speed", "temperature"];
const DUTY = { source: null, result: null };

function dutyRow(b = {}) {
  const cell = (key, cls) => el("td", {}, el("input", { class: cls || "", "data-key": key, value: key === "name" ? b.name || "" : key === "fraction" ? b.fraction || "" : b[key] || "" }));
  const remove = el("button", { type: "button", class: "remove-bin", title: "remove the bin" }, "×");
  return el("tr", { class: "bin" }, cell("name", "name"), ...DUTY_FIELDS.map((k) => cell(k)), cell("fraction"),
    el("td", { class: "r-rev" }), el("td", { class: "r-l10-iso" }), el("td", { class: "r-lnm-iso" }), el("td", { class: "r-share-iso" }), el("td", { class: "r-l10" }), el("td", { class: "r-lnm" }), el("td", { class: "r-s0" }), el("td", { class: "r-share" }), el("td", {}, remove));
}

function dutyTable(bins) {
  const head = el("tr", {}, ...["bin", "F_x", "F_y", "F_z", "M_x", "M_y", "speed", "temperature", "share", "rev. share", "L10 ISO 281 [h]", "L_nm ISO 281 [h]", "damage share ISO 281", "L10r ISO/TS 16281 [h]", "L_nmr ISO/TS 16281 [h]", "s0", "damage share ISO/TS 16281", ""].map((h) => el("th", {}, h)));
  const t = $("duty-table");
  t.className = "data edit";
  t.replaceChildren(el("thead", {}, head), el("tbody", { id: "duty-bins" }, ...bins.map((b) => dutyRow(b))));
}

function dutyBins() {
  return [...document.querySelectorAll("#duty-bins tr.bin")].map((tr) => {
    const get = (k) => tr.querySelector(`[data-key="${k}"]`).value.trim();
    const values = {};
    for (const k of DUTY_FIELDS) if (get(k)) values[k] = get(k);
    return { name: get("name"), values, fraction: get("fraction") };
  });
}

function dutyFromFile() {
  const o = state.opened;
  if (!o) return;
  $("duty-fraction").value = o.duty_fraction || "time";
  dutyTable(o.duty_cycle && o.duty_cycle.length ? o.duty_cycle : [
    { name: "low", F_x: "2 kN", speed: "3000 rpm", temperature: "70 degC", fraction: "0.6" },
    { name: "high", F_x: "6 kN", speed: "1500 rpm", temperature: "80 degC", fraction: "0.4" },
  ]);
  DUTY.source = JSON.stringify(state.source);
  $("duty-summary").replaceChildren();
  $("duty-notes").replaceChildren();
  $("duty-status").textContent = o.duty_cycle && o.duty_cycle.length ? `the ${o.duty_cycle.length} bins of ${o.source}` : "the file has no duty cycle: two bins to start from";
}

function dutyCellError(err) {
  const m = /^duty\.(\d+)(?:\.(\w+))?$/.exec(err.field || "");
  const tr = m ? document.querySelectorAll("#duty-bins tr.bin")[+m[1]] : null;
  if (tr) {
    const input = tr.querySelector(`[data-key="${m[2] || "name"}"]`);
    if (input) input.classList.add("invalid");
  }
  pageError("duty", { message: err.message, field: "duty" }, "duty-error");
}

async function dutyRun() {
  clearPageErrors("duty");
  if (!state.source) {
    $("duty-error").textContent = "open a bearing on the Bearing page first";
    return;
  }
  $("duty-status").textContent = "rating every bin in one batch…";
  try {
    const out = await api("/api/duty", { base: request(), bins: dutyBins(), fraction: $("duty-fraction").value });
    const d = out.duty_cycle;
    DUTY.result = d;
    const rows = document.querySelectorAll("#duty-bins tr.bin");
    const top = Math.max(...d.bins.map((b) => b.damage_share || 0), 1e-30);
    d.bins.forEach((b, i) => {
      const tr = rows[i];
      if (!tr) return;
      const speed = b.speed_rad_s ? Math.abs(b.speed_rad_s) / (2 * Math.PI) : null;
      const hours = (rev) => (rev === null || speed === null ? null : rev / speed / 3600);
      const put = (cls, value, text, bad) => {
        const td = tr.querySelector(`.${cls}`);
        td.replaceChildren(text);
        td.dataset.value = value === null || value === undefined ? "" : String(value);
        td.className = `${cls}${bad ? " bad" : ""}`;
      };
      put("r-rev", b.revolution_fraction, fmt(b.revolution_fraction, 4));
      put("r-l10-iso", b.L10_iso281_rev, fmt(hours(b.L10_iso281_rev), 4));
      put("r-lnm-iso", b.Lnm_iso281_rev, fmt(hours(b.Lnm_iso281_rev), 4));
      put("r-share-iso", b.damage_share_iso281, b.damage_share_iso281 === null ? "—" : `${fmt(b.damage_share_iso281 * 100, 3)} %`);
      put("r-l10", b.L10r_rev, fmt(hours(b.L10r_rev), 4));
      put("r-lnm", b.Lnmr_rev, fmt(hours(b.Lnmr_rev), 4));
      put("r-s0", b.static_safety, fmt(b.static_safety, 3), b.static_safety !== null && b.static_safety < 1);
      const share = b.damage_share;
      const td = tr.querySelector(".r-share");
      td.dataset.value = share === null ? "" : String(share);
      td.replaceChildren(el("span", { class: "bar", style: null }), share === null ? "—" : `${fmt(share * 100, 3)} %`);
      td.firstChild.style.width = `${share === null ? 0 : Math.round((60 * share) / top)}px`;
    });
    // ISO 281 first (the catalogue method), ISO/TS 16281 beside it; headline.method says which leads
    const iso = [
      metric("duty-l10-iso", "L10 ISO 281, Palmgren–Miner", d.L10h_iso281_h, 1, "h"),
      metric("duty-lnm-iso", "L_nm ISO 281, Palmgren–Miner", d.Lnm_iso281_h, 1, "h")];
    const ts = [
      metric("duty-l10", "L10r ISO/TS 16281, Palmgren–Miner", d.L10r_h, 1, "h"),
      metric("duty-l10-rev", "L10r ISO/TS 16281", d.L10r_rev, 1e-6, "10⁶ rev"),
      metric("duty-lnm", "L_nmr ISO/TS 16281, Palmgren–Miner", d.Lnmr_h, 1, "h")];
    const isoFirst = !d.headline || d.headline.method === "ISO 281";
    $("duty-summary").replaceChildren(...(isoFirst ? [...iso, ...ts] : [...ts, ...iso]));
    const warnings = d.bins.flatMap((b) => b.warnings.map((w) => el("li", { class: "bad" }, `${b.bin}: ${w}`)));
    const why = d.life_difference ? [el("li", {}, `why they differ: ${d.life_difference}`)] : [];
    $("duty-notes").replaceChildren(el("li", {}, d.rule), ...why, ...d.notes.map((n) => el("li", {}, n)), ...warnings);
    $("duty-status").textContent = `${d.bins.length} bins rated in one batch, ${fmt(out.elapsed_ms, 3)} ms; shares of the ${d.fraction_kind}`;
  } catch (err) {
    $("duty-status").textContent = "";
    dutyCellError(err);
  }
}

PAGES.duty = {
  start() {
    dutyTable([]);
    $("duty-add").addEventListener("click", () => $("duty-bins").append(dutyRow({ name: `bin_${$("duty-bins").children.length + 1}` })));
    $("duty-from-file").addEventListener("click", dutyFromFile);
    $("duty-run").addEventListener("click", dutyRun);
    $("duty-table").addEventListener("click", (e) => e.target.matches("button.remove-bin") && e.target.closest("tr").remove());
  },
  shown() {
    $("duty-bearing").textContent = state.last ? state.last.analysis.bearing_name : "— (open a bearing on the Bearing page)";
    if (state.source && DUTY.source !== JSON.stringify(state.source)) dutyFromFile();
    if (!state.source) { dutyTable([]); DUTY.source = null; $("duty-summary").replaceChildren(); $("duty-notes").replaceChildren(); }
  },
};
