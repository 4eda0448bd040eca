// bearingkit serve: the studies page — factors and outputs on the current bearing, shaft or drivetrain, run
// by the server in the background (`bearingkit study` in a child process) with its progress, stop and
// resume; the study's own plots and tables, and its folder as a zip. Helpers from app.js.
"use strict";

const STUDY = { paths: [], outputs: [], job: null, timer: null, subjectKey: null };

// The subject's request: the page that holds it, as that page would send it.
function studySubject() {
  const subject = $("study-subject").value;
  if (subject === "bearing") return { subject, bearing: state.source ? request() : null };
  const s = SYSTEM[subject];
  return { subject, system: s && s.data ? systemRequest(subject) : null };
}

function subjectName(subject) {
  if (subject === "bearing") return state.last ? state.last.analysis.bearing_name : null;
  const s = SYSTEM[subject];
  return s && s.data ? `${s.data.name} (${subject === "shaft" ? s.data.analysis.shaft : s.data.analysis.drivetrain})` : null;
}

async function studyLoadPaths() {
  clearPageErrors("study");
  const body = studySubject();
  const name = subjectName(body.subject);
  $("study-subject-name").textContent = name || `no ${body.subject} open: open one on its page first`;
  $("study-run").disabled = !name;
  if (!name) {
    STUDY.paths = [];
    STUDY.outputs = [];
    studyFactorRows([]);
    $("study-outputs").replaceChildren();
    return;
  }
  try {
    const out = await api("/api/study/paths", body);
    STUDY.paths = out.paths;
    STUDY.outputs = out.outputs;
    STUDY.subjectKey = JSON.stringify(body);
    $("study-outputs").replaceChildren(...out.outputs.map((o) => el("option", { value: o.name, title: o.description }, `${o.name} [${o.unit}]`)));
    for (const id of ["study-obj1", "study-obj2"]) $(id).replaceChildren(...out.outputs.map((o) => el("option", { value: o.name }, o.name)));
    studyDefaults(body.subject);
  } catch (err) {
    pageError("study", err, "study-error");
  }
}

// A starting study for the subject: two factors and three outputs the user edits.
function studyDefaults(subject) {
  const has = (p) => STUDY.paths.some((x) => x.path === p);
  let rows = [];
  let outputs = [];
  if (subject === "bearing") {
    const clearance = STUDY.paths.find((p) => p.path.startsWith("geometry.clearance"));
    if (clearance) rows.push({ path: clearance.path, start: "0 um", stop: "40 um", n: 5 });
    if (has("load_cases.page.F_x")) rows.push({ path: "load_cases.page.F_x", start: "1 kN", stop: "10 kN", n: 10 });
    outputs = ["L10_iso281_rev", "L10r_rev", "max_load_N", "s0"]; // lives in hours need a speed, the page may have none
  } else {
    rows.push({ path: "load_scale", start: "0.5", stop: "1.5", n: 5 });
    // ISO 281 first (the life the single bearing shows first), ISO/TS 16281 beside it
    outputs = subject === "shaft" ? ["system_L10h_iso281_h", "system_L10h_h", "max_pressure_Pa", "max_radial_deflection_m"] : ["system_L10h_iso281_h", "system_L10h_h", "efficiency", "max_pressure_Pa"];
    if (subject === "drivetrain") rows[0].path = "torque_scale";
  }
  studyFactorRows(rows);
  for (const op of $("study-outputs").options) op.selected = outputs.includes(op.value);
  studyResponses();
  $("study-obj1").value = subject === "bearing" ? "L10r_rev" : "system_L10h_h";
  $("study-obj2").value = subject === "bearing" ? (STUDY.outputs.some((o) => o.name === "friction_torque_Nm") ? "friction_torque_Nm" : "max_load_N") : "max_pressure_Pa";
  studyCount();
}

function studyFactorRows(rows) {
  $("study-factors").replaceChildren(...rows.map((r) => studyFactorRow(r)));
  studyCount();
}

function studyFactorRow(r = {}) {
  const i = () => [...$("study-factors").children].indexOf(row);
  const path = el("select", { class: "f-path" }, ...STUDY.paths.map((p) => el("option", { value: p.path }, `${p.path} [${p.unit}]`)));
  if (r.path) path.value = r.path;
  const start = el("input", { class: "f-start", value: r.start || "", placeholder: "from / low / mean" });
  const stop = el("input", { class: "f-stop", value: r.stop || "", placeholder: "to / high / std" });
  const n = el("input", { class: "f-n", type: "number", min: 1, max: 50, value: r.n || 3 });
  const levels = el("input", { class: "f-levels", value: r.levels || "", placeholder: "or levels: a, b, c" });
  const remove = el("button", { type: "button", title: "remove" }, "×");
  const row = el("div", { class: "factor-row" },
    el("div", { class: "field path" }, el("label", {}, "factor"), path),
    el("div", { class: "field" }, el("label", {}, "from"), start),
    el("div", { class: "field" }, el("label", {}, "to"), stop),
    el("div", { class: "field" }, el("label", {}, "n"), n),
    el("div", { class: "field" }, el("label", {}, "levels"), levels),
    remove);
  const err = el("span", { class: "error factor-error" });
  const wrap = el("div", { class: "factor" }, row, err);
  remove.addEventListener("click", () => { wrap.remove(); studyCount(); });
  for (const input of [path, start, stop, n, levels]) input.addEventListener("change", studyCount);
  Object.defineProperty(wrap, "index", { get: i });
  return wrap;
}

function studyFactors() {
  return [...$("study-factors").children].map((w) => {
    const levels = w.querySelector(".f-levels").value.split(",").map((v) => v.trim()).filter(Boolean);
    return {
      path: w.querySelector(".f-path").value,
      start: w.querySelector(".f-start").value.trim(),
      stop: w.querySelector(".f-stop").value.trim(),
      n: parseInt(w.querySelector(".f-n").value, 10) || 1,
      levels,
      distribution: "uniform",
    };
  });
}

function studyResponses() {
  const chosen = [...$("study-outputs").selectedOptions].map((o) => o.value);
  const before = $("study-response").value;
  $("study-response").replaceChildren(...chosen.map((o) => el("option", { value: o }, o)));
  if (chosen.includes(before)) $("study-response").value = before;
}

function studyCount() {
  const design = $("study-design").value;
  $("study-mc").hidden = design !== "monte_carlo";
  $("study-opt").hidden = design !== "optimize";
  $("study-response-field").hidden = design !== "factorial";
  const factors = studyFactors();
  let n = 1;
  if (design === "factorial") for (const f of factors) n *= f.levels.length || f.n;
  else if (design === "monte_carlo") n = parseInt($("study-samples").value, 10) || 0;
  else n = (parseInt($("study-pop").value, 10) || 0) * (parseInt($("study-gen").value, 10) || 0);
  $("study-count").textContent = `${n} case${n === 1 ? "" : "s"} (the app runs up to ${state.meta.max_study_cases} for a bearing, 200 for a shaft or drivetrain; the command line more)`;
  $("study-count").dataset.cases = String(n);
}

function studyBody() {
  const design = $("study-design").value;
  return {
    ...studySubject(),
    design,
    factors: studyFactors(),
    outputs: [...$("study-outputs").selectedOptions].map((o) => o.value),
    response: design === "factorial" ? $("study-response").value : "",
    objectives: design === "optimize" ? [
      { output: $("study-obj1").value, sense: $("study-obj1-sense").value },
      { output: $("study-obj2").value, sense: $("study-obj2-sense").value },
    ] : [],
    samples: parseInt($("study-samples").value, 10) || 64,
    seed: parseInt($("study-seed").value, 10) || 0,
    population: parseInt($("study-pop").value, 10) || 20,
    generations: parseInt($("study-gen").value, 10) || 10,
  };
}

function studyError(err) {
  const m = /^study\.factor\.(\d+)$/.exec(err.field || "");
  if (m) {
    const w = $("study-factors").children[+m[1]];
    if (w) { w.querySelector(".factor-error").textContent = err.message; return; }
  }
  pageError("study", err, "study-error");
}

async function studyRun() {
  clearPageErrors("study");
  studyClearResults();
  try {
    const job = await api("/api/study", studyBody());
    studyShow(job);
    studyPoll();
  } catch (err) {
    studyError(err);
  }
}

function studyClearResults() {
  $("study-figures").replaceChildren();
  $("study-tables").replaceChildren();
  $("study-table").replaceChildren();
  $("study-rows").textContent = "";
  const dl = $("study-download");
  dl.classList.add("disabled");
  dl.removeAttribute("href");
}

function studyShow(job) {
  STUDY.job = job;
  const bar = $("study-progress");
  bar.value = job.fraction;
  bar.dataset.state = job.state;
  const status = $("study-status");
  status.dataset.state = job.state;
  const what = `${job.cases_done} of ${job.cases} cases (chunk ${job.chunks_done} of ${job.chunks || "?"}), ${fmt(job.elapsed_s, 3)} s`;
  const words = { running: job.fraction >= 1 ? "writing the results and plots…" : "running", done: "done", failed: "failed", stopped: "stopped", queued: "queued" };
  status.textContent = `${words[job.state] || job.state}: ${what}${job.message ? ` — ${job.message}` : ""}`;
  $("study-stop").disabled = job.state !== "running";
  $("study-resume").disabled = !["stopped", "failed"].includes(job.state);
  $("study-run").disabled = job.state === "running";
  const dl = $("study-download");
  if (job.state !== "running") {
    dl.href = `/api/study/${job.id}.zip`;
    dl.classList.remove("disabled");
  }
}

function studyPoll() {
  clearTimeout(STUDY.timer);
  STUDY.timer = setTimeout(async () => {
    if (!STUDY.job) return;
    try {
      const job = await api(`/api/study/${STUDY.job.id}`);
      studyShow(job);
      if (job.state === "running" || job.state === "queued") studyPoll();
      else if (job.state === "done") studyResults(job.id);
    } catch (err) {
      pageError("study", err, "study-error");
    }
  }, 400);
}

async function studyResults(id) {
  try {
    const out = await api(`/api/study/${id}/results`);
    $("study-figures").replaceChildren(...out.figures.map((f) => el("img", { src: `/api/study/${id}/figure/${f}`, alt: f, title: f, "data-name": f })));
    const cols = out.columns.filter((c) => c !== "error" || out.rows.some((r) => r[out.columns.indexOf("error")]));
    const idx = cols.map((c) => out.columns.indexOf(c));
    table("study-table", cols, out.rows.map((r, k) => idx.map((j) => {
      const v = r[j];
      if (typeof v === "number") return { text: fmt(v, 5), value: v, id: `study-cell-${k}-${out.columns[j]}` };
      return { text: v === null ? "—" : String(v), id: `study-cell-${k}-${out.columns[j]}` };
    })));
    $("study-rows").textContent = `${out.total_rows} cases${out.total_rows > out.rows.length ? `, the first ${out.rows.length} shown (the zip has them all)` : ""}`;
    const tables = Object.entries(out.tables).map(([name, t]) => {
      const node = el("table", { class: "data", id: `study-${name}` });
      const wrap = el("div", { class: "table-wrap" }, el("h3", {}, name.replaceAll("_", " ")), node);
      node.append(el("tr", {}, ...t.columns.map((c) => el("th", {}, c))), ...t.rows.slice(0, 30).map((r) => el("tr", {}, ...r.map((v) => el("td", {}, typeof v === "number" ? fmt(v, 4) : v === null ? "—" : String(v))))));
      return wrap;
    });
    $("study-tables").replaceChildren(...tables);
  } catch (err) {
    pageError("study", err, "study-error");
  }
}

async function studyAction(action) {
  if (!STUDY.job) return;
  clearPageErrors("study");
  try {
    const job = await api(`/api/study/${STUDY.job.id}/${action}`, {});
    studyShow(job);
    if (action === "resume") { studyClearResults(); studyPoll(); }
  } catch (err) {
    pageError("study", err, "study-error");
  }
}

PAGES.study = {
  start() {
    $("study-subject").addEventListener("change", studyLoadPaths);
    $("study-design").addEventListener("change", studyCount);
    for (const id of ["study-samples", "study-pop", "study-gen"]) $(id).addEventListener("change", studyCount);
    $("study-outputs").addEventListener("change", studyResponses);
    $("study-add-factor").addEventListener("click", () => {
      if ($("study-factors").children.length < 4) $("study-factors").append(studyFactorRow({ path: STUDY.paths.length ? STUDY.paths[0].path : "" }));
      studyCount();
    });
    $("study-run").addEventListener("click", studyRun);
    $("study-stop").addEventListener("click", () => studyAction("stop"));
    $("study-resume").addEventListener("click", () => studyAction("resume"));
  },
  shown() {
    // the subject may have changed on its page: list its paths again (the factors start over)
    const key = JSON.stringify(studySubject());
    if (key !== STUDY.subjectKey) studyLoadPaths();
  },
};
