// bearingkit serve: the bearing page's "in its structure" card — a file's [structure] (flexible rings on
// their seats and flanges, or an imported FE compliance), shown as `bearingkit analyze` and the report show
// it: per row the loaded elements, Q_max and p_max on rigid and on flexible rings and their change; s0 and
// the basic rating life each way; each ring's deflection, twist, bending moments and largest fibre stress;
// the element loads and the ring's deflection and moments against azimuth. Every number is the server's
// (the case's `flexible` dict of Analysis.to_dict(), SI); this file only converts units and draws. The
// seed-002 ball–column bearing's own flexible ring (no [structure]) shows in the same card (renderSeedRing).
// The warnings the structure carries are in the case's warnings, shown by app.js with every other one.
"use strict";

// Azimuths in degrees on (−180°, 180°] and the order that sorts them (the report's unrolled axis).
function unrolled(rad) {
  const deg = rad.map((p) => {
    let d = ((((p * 180) / Math.PI) % 360) + 360) % 360;
    if (d > 180) d -= 360;
    return d;
  });
  const order = deg.map((v, i) => i).sort((i, j) => deg[i] - deg[j]);
  return { x: order.map((i) => deg[i]), order };
}

// The largest magnitude of a list (what the CLI prints as |w| ≤ …); null for an empty or missing one.
function maxAbs(values) {
  if (!values || !values.length) return null;
  return Math.max(...values.map((v) => Math.abs(v)));
}

function structureStatus(f) {
  const how = f.coupling || {};
  const parts = [`Newton, ${how.iterations} iterations, ${f.converged ? "converged" : "NOT converged"}`];
  if (how.force_balance !== null && how.force_balance !== undefined) {
    parts.push(`the element forces balance the load to ${Math.max(how.force_balance, 1e-16).toExponential(0)} of it`);
  }
  return `Rigid rings against the rings and supports of [structure] (${parts.join("; ")}). ` +
    "The rigid rings are what the catalogue methods assume; the flexible ones carry the structure given.";
}

function renderStructure(c) {
  const f = c.flexible;
  const card = $("structure-card");
  card.hidden = !f;
  for (const id of ["structure-status", "structure-rows", "structure-change", "structure-rings", "structure-rings-note", "structure-plots"]) $(id).replaceChildren();
  if (!f) return;
  if (!f.rigid_vs_flexible) {
    renderSeedRing(c, f);
    return;
  }
  const status = $("structure-status");
  status.textContent = structureStatus(f);
  status.className = f.converged ? "small" : "small bad";

  // per row: rigid → flexible (the CLI's table, the report's table)
  const rows = Object.entries(f.rigid_vs_flexible).map(([name, r]) => [
    name,
    { text: `${r.loaded_count_rigid} → ${r.loaded_count_flexible}`, id: `st-loaded-${name}`, value: r.loaded_count_flexible },
    num(r.max_load_rigid_N, 1, 6, { id: `st-qmax-rigid-${name}` }),
    num(r.max_load_flexible_N, 1, 6, { id: `st-qmax-flex-${name}` }),
    r.max_load_change === null ? "—" : { text: `${r.max_load_change >= 0 ? "+" : ""}${fmt(r.max_load_change * 100, 3)} %`, id: `st-change-${name}`, value: r.max_load_change },
    num(r.max_pressure_rigid_Pa, 1e-6, 5, { id: `st-pmax-rigid-${name}` }),
    num(r.max_pressure_flexible_Pa, 1e-6, 5, { id: `st-pmax-flex-${name}` }),
  ]);
  table("structure-rows", ["row", "loaded", "Q_max rigid [N]", "Q_max flexible [N]", "change", "p_max rigid [MPa]", "p_max flexible [MPa]"], rows);

  // what the flexibility changes: peak element load, s0 and the basic rating life (pipeline.structure.change)
  const ch = f.change || {};
  const ratio = (v) => (v === null || v === undefined ? "—" : num(v, 1, 4));
  const changes = [
    ["largest element load Q_max [N]", num(ch.max_load_rigid_N, 1, 6, { id: "st-q-rigid" }), num(ch.max_load_flexible_N, 1, 6, { id: "st-q-flex" }), ratio(ch.max_load_ratio)],
    ["static safety s0", num(ch.static_safety_rigid, 1, 4, { id: "st-s0-rigid" }), num(ch.static_safety_flexible, 1, 4, { id: "st-s0-flex" }), ratio(ch.static_safety_ratio)],
    ["basic rating life L10 [10⁶ rev]", num(ch.life_rev_rigid, 1e-6, 4, { id: "st-life-rigid" }), num(ch.life_rev_flexible, 1e-6, 4, { id: "st-life-flex" }), ratio(ch.life_rev_ratio)],
  ];
  table("structure-change", ["", "rigid rings", "flexible rings", "flexible / rigid"], changes);

  // each ring: its largest deflections, twist, moments and fibre stress (72 azimuths of the coupled solution)
  const rings = (f.structure && f.structure.rings) || [];
  const ringRows = rings.map((r) => {
    const side = r.side;
    if (!r.radial_deflection_m) { // an imported compliance: the nodes' displacements are not resolved into a ring
      const what = r.model === "imported" ? `imported ${r.kind} (${r.nodes} nodes, ${(r.dofs || []).join(" ")}${r.source ? `, ${r.source}` : ""})` : (r.model || "rigid");
      return [side, { text: what, cls: "wrap" }, "—", "—", "—", "—", "—", "—", "—"];
    }
    const mm = (k, s, d, id) => num(maxAbs(r[k]), s, d, { id: `st-${id}-${side}` });
    return [
      side,
      { text: r.model ? `${r.model}${r.section ? `, ${r.section}` : ""}` : "curved beam", cls: "wrap" },
      mm("radial_deflection_m", 1e6, 4, "w"),
      mm("tangential_deflection_m", 1e6, 4, "v"),
      mm("axial_deflection_m", 1e6, 4, "u"),
      mm("twist_rad", 1e6, 4, "twist"),
      mm("bending_moment_Nm", 1, 4, "m-in"),
      mm("out_of_plane_moment_Nm", 1, 4, "m-out"),
      num(r.max_fibre_stress_Pa ?? null, 1e-6, 4, { id: `st-sigma-${side}` }),
    ];
  });
  table("structure-rings", ["ring", "model", "|w| [µm]", "|v| [µm]", "|u| [µm]", "|φ| [µrad]", "|M_in| [N·m]", "|M_out| [N·m]", "σ max [MPa]"], ringRows);
  $("structure-rings-note").textContent = "Largest over the circumference: radial w (outward +), tangential v and axial u " +
    "deflection and twist φ of the ring's centroid, its in-plane and out-of-plane bending moments, and the largest hoop " +
    "fibre stress over the section's outline (N/A + M_in Δr/I_in + M_out Δz/I_out).";

  // against azimuth: element loads rigid and flexible per row; each ring's deflection and moments
  const plots = [];
  const rigidRows = Object.fromEntries(c.rows.map((r) => [r.name, r]));
  for (const row of f.rows) {
    const { x, order } = unrolled(row.azimuth_rad);
    const rigid = rigidRows[row.name];
    const series = [];
    if (rigid) series.push({ x, y: order.map((i) => rigid.loads_N[i] / 1e3), label: "rigid" });
    series.push({ x, y: order.map((i) => row.loads_N[i] / 1e3), label: "flexible" });
    plots.push(chart({ width: 460, height: 240, series, xlabel: "azimuth ψ [°]", ylabel: "element load Q [kN]", title: `${row.name}: element loads, rigid → flexible rings` }));
  }
  for (const r of rings) {
    if (!r.radial_deflection_m) continue;
    const { x, order } = unrolled(r.shape_azimuth_rad);
    const at = (k, s) => order.map((i) => r[k][i] * s);
    plots.push(chart({
      width: 460, height: 240, xlabel: "azimuth θ [°]", ylabel: "deflection [µm]", title: `${r.side} ring: deflection around the circumference`,
      series: [{ x, y: at("radial_deflection_m", 1e6), label: "w radial" }, { x, y: at("tangential_deflection_m", 1e6), label: "v tangential" },
        { x, y: at("axial_deflection_m", 1e6), label: "u axial" }],
    }));
    plots.push(chart({
      width: 460, height: 240, xlabel: "azimuth θ [°]", ylabel: "twist φ [µrad]", title: `${r.side} ring: twist of the section`,
      series: [{ x, y: at("twist_rad", 1e6), label: "φ" }],
    }));
    plots.push(chart({
      width: 460, height: 240, xlabel: "azimuth θ [°]", ylabel: "bending moment [N·m]", title: `${r.side} ring: bending moments`,
      series: [{ x, y: at("bending_moment_Nm", 1), label: "in plane" }, { x, y: at("out_of_plane_moment_Nm", 1), label: "out of plane" }],
    }));
  }
  $("structure-plots").replaceChildren(...plots);
}

// The seed-002 ball–column bearing's own flexible outer ring ([geometry.ring], not [structure]): what
// `bearingkit analyze` prints for it — the coupling, per row the loaded elements, Q_max and p_max of the
// rigid solve (the case's rows) beside the flexible one — and the ring's bending deflection and moment.
function renderSeedRing(c, f) {
  const how = f.coupling || {};
  const status = $("structure-status");
  status.textContent = `Flexible outer ring of the ball–column bearing ([geometry.ring]: beam between housing supports + ` +
    `ovalisation; ${how.method}, ${how.iterations} iterations, ${f.converged ? "converged" : "NOT converged"}). ` +
    "Rigid: the case's own solve above.";
  status.className = f.converged ? "small" : "small bad";
  const rigidRows = Object.fromEntries(c.rows.map((r) => [r.name, r]));
  const rows = f.rows.map((r) => {
    const rigid = rigidRows[r.name] || {};
    return [
      r.name,
      { text: `${rigid.loaded_count} → ${r.loaded_count}`, id: `st-loaded-${r.name}`, value: r.loaded_count },
      num(rigid.max_load_N, 1, 6, { id: `st-qmax-rigid-${r.name}` }),
      num(r.max_load_N, 1, 6, { id: `st-qmax-flex-${r.name}` }),
      num(rigid.max_pressure_Pa, 1e-6, 5, { id: `st-pmax-rigid-${r.name}` }),
      num(r.max_pressure_Pa, 1e-6, 5, { id: `st-pmax-flex-${r.name}` }),
    ];
  });
  table("structure-rows", ["row", "loaded", "Q_max rigid [N]", "Q_max flexible [N]", "p_max rigid [MPa]", "p_max flexible [MPa]"], rows);
  const ring = f.ring;
  const plots = [];
  for (const row of f.rows) {
    const { x, order } = unrolled(row.azimuth_rad);
    const rigid = rigidRows[row.name];
    const series = [];
    if (rigid) series.push({ x, y: order.map((i) => rigid.loads_N[i] / 1e3), label: "rigid" });
    series.push({ x, y: order.map((i) => row.loads_N[i] / 1e3), label: "flexible" });
    plots.push(chart({ width: 460, height: 240, series, xlabel: "azimuth ψ [°]", ylabel: "element load Q [kN]", title: `${row.name}: element loads, rigid → flexible ring` }));
  }
  if (ring && ring.bending_deflection_m) {
    table("structure-rings", ["ring", "model", "|w| bending [µm]", "|M| [N·m]", "σ max [MPa]"], [[
      "outer", { text: `beam + ovalisation (${ring.beam_mode})`, cls: "wrap" },
      num(maxAbs(ring.bending_deflection_m), 1e6, 4, { id: "st-w-outer" }),
      num(maxAbs(ring.bending_moment_Nm), 1, 4, { id: "st-m-in-outer" }),
      num(ring.max_fibre_stress_Pa ?? null, 1e-6, 4, { id: "st-sigma-outer" }),
    ]]);
    $("structure-rings-note").textContent = "Largest over the circumference: the ring's bending deflection (outward +), its bending moment and hoop fibre stress.";
    const { x, order } = unrolled(ring.shape_azimuth_rad);
    const at = (k, sc) => order.map((i) => ring[k][i] * sc);
    plots.push(chart({ width: 460, height: 240, xlabel: "azimuth θ [°]", ylabel: "deflection [µm]", title: "outer ring: bending deflection",
      series: [{ x, y: at("bending_deflection_m", 1e6), label: "w" }] }));
    plots.push(chart({ width: 460, height: 240, xlabel: "azimuth θ [°]", ylabel: "bending moment [N·m]", title: "outer ring: bending moment",
      series: [{ x, y: at("bending_moment_Nm", 1), label: "M" }] }));
  }
  $("structure-plots").replaceChildren(...plots);
}
