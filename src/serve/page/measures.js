// The measures of the panel under the pointer: pita measure's row for it.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// The panel under the pointer (its cell, in canvas pixels): its measures only.
function pointAt(index, e) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  if (!svg || !v.panels) return;
  const at = svgPoint(svg, e);
  const panel = v.panels.findIndex(([x, y, w, h]) => at.x >= x && at.x < x + w && at.y >= y && at.y < y + h);
  if (panel !== v.panel) { v.panel = panel; showMeasures(index); outline(index); }
}

async function measures(index) {
  const v = views.get(index);
  const response = await fetch(api(`/api/measures/${index}`));
  if (!response.ok) return;
  v.report = await response.json();
  showMeasures(index);
}

// A number as pita measure's table writes it (4 significant digits).
function g4(x) {
  return typeof x === "number" ? String(parseFloat(x.toPrecision(4))) : "-";
}

// Letters and digits only: "P1 Pa-Ca" and "P1 (Pa-Ca)" say the same.
const plain = (text) => (text || "").toLowerCase().replace(/[^\p{L}\p{N}]+/gu, "");

// A panel's row of pita measure's table, each cell with its column's name.
function measureRow(m, i) {
  const name = m.title || (m.pointer ? `panel ${i + 1}` : "the scene");
  const head = !m.method || plain(name).includes(plain(m.method)) ? name : `${name} (${m.method})`;
  const cells = [];
  if (m.no_motion) cells.push(`no motion: ${m.no_motion}`);
  const d = m.discrepancy;
  if (d) {
    const of = (key) => ["previous", "average", "pita"].map(n => d[n] && d[n].frames ? g4(d[n][key]) : "-").join(" / ");
    cells.push(`E max prev / avg / pita ${of("max")}`, `E mean ${of("mean")}`);
  }
  if (m.path && m.path.q) {
    cells.push(`length p, q ${g4(m.path.p.length)}, ${g4(m.path.q.length)}`,
               `turning p, q ${g4(m.path.p.turning)}, ${g4(m.path.q.turning)} rad`,
               `inflections p, q ${m.path.p.inflections}, ${m.path.q.inflections}`);
  } else if (m.path && m.path.p) {
    cells.push(`length ${g4(m.path.p.length)}`, `turning ${g4(m.path.p.turning)} rad`,
               `inflections ${m.path.p.inflections}`);
  }
  if (m.winding) cells.push(`winding [${g4(m.winding.min)}, ${g4(m.winding.max)}] rad`);
  if (m.overreaction && m.overreaction.most_sensitive) {
    cells.push(`most sensitive ${m.overreaction.most_sensitive} (${g4(m.overreaction.gain)})`);
  }
  if (m.pop) cells.push(`pop ${m.pop.detected ? "yes" : "no"}${m.pop.parameter ? ` (${m.pop.parameter} ${g4(m.pop.jump)})` : ""}`);
  if (m.ara !== undefined) cells.push(`ARA ${g4(m.ara)}`);
  if (m.area) {
    cells.push(`${m.kind === "poses3d" || m.area.volume ? "volume" : "area"} monotone ${m.area.monotone ? "yes" : "no"}`,
               `largest excursion ${g4(m.area.excursion)} (at t = ${g4(m.area.t_of_excursion)})`,
               `det L first, last ${g4(m.area.first)}, ${g4(m.area.last)}`);
  }
  if (m.velocity_jump !== undefined) cells.push(`velocity jump ${g4(m.velocity_jump)}`);
  return `${head}: ${cells.join("; ")}`;
}

function showMeasures(index) {
  const v = views.get(index);
  if (!v.report) return;
  const motions = v.report.motions;
  const which = v.panel >= 0 && v.panel < motions.length ? [v.panel] : motions.map((m, i) => i);
  v.measures.textContent = which.map(i => measureRow(motions[i], i)).join("\n");
}
