"use strict";
const $ = id => document.getElementById(id);
const arrived = new Map(), files = new Map(), columns = new Map();
window.pitaRows = (k, rows) => arrived.set(k, rows);
window.pitaColumn = (key, values) => columns.set(key, values);
let order = null, page = 0, shown = 0, sorted = 0;
const say = text => { $("status").textContent = text; };
const nameOf = key => key === "index" ? "index" : sweep.columns.find(c => c.key === key).name;
function load(src) {
  return new Promise((resolve, reject) => {
    const s = document.createElement("script");
    s.src = src;
    s.onload = () => { s.remove(); resolve(); };
    s.onerror = () => { s.remove(); reject(new Error("cannot load " + src + " (is the index/ folder beside index.html?)")); };
    document.head.appendChild(s);
  });
}
// The rows of index/rows-K.js; the last 64 files used are kept (a Map in order of use).
async function rowsFile(k) {
  let rows = files.get(k);
  if (rows) {
    files.delete(k);
  } else {
    await load(`index/rows-${k}.js`);
    rows = arrived.get(k);
    arrived.delete(k);
  }
  files.set(k, rows);
  while (files.size > 64) files.delete(files.keys().next().value);
  return rows;
}
const pageRows = () => Number($("size").value);
const pages = () => Math.max(1, Math.ceil(sweep.count / pageRows()));
function compare(values, desc) {
  return (a, b) => {
    const x = values[a], y = values[b];
    if (x === null || y === null) return (x === null) - (y === null) || a - b;
    const c = typeof x === "number" && typeof y === "number" ? x - y : (String(x) < String(y) ? -1 : String(x) > String(y) ? 1 : 0);
    return (desc ? -c : c) || a - b;
  };
}
// The order of the rows for the menus' column and direction; a later call wins.
async function sortBy() {
  const ticket = ++sorted, key = $("sort").value, desc = $("order").value === "desc";
  if (key === "index") {
    order = desc ? Uint32Array.from({length: sweep.count}, (_, i) => sweep.count - 1 - i) : null;
    return;
  }
  let values = columns.get(key);
  if (!values) {
    say(`loading the column ${nameOf(key)}…`);
    await load(`index/column-${key}.js`);
    values = columns.get(key);
    for (const other of [...columns.keys()]) if (other !== key) columns.delete(other);
  }
  say(`sorting ${sweep.count} rows…`);
  await new Promise(r => setTimeout(r));
  if (ticket !== sorted) return;
  const positions = new Uint32Array(sweep.count);
  for (let i = 0; i < positions.length; ++i) positions[i] = i;
  order = positions.sort(compare(values, desc));
}
function cell(tr, text, className) {
  const td = tr.insertCell();
  td.textContent = text ?? "";
  if (className) td.className = className;
  return td;
}
function rowElement(row) {
  const [index, status, thumb, full] = row;
  const tr = document.createElement("tr");
  tr.className = status === "ok" ? "ok" : "failed";
  tr.dataset.index = index;
  cell(tr, `#${index}`);
  if (sweep.figures) {
    const td = cell(tr, "");
    if (thumb || full) {
      const a = document.createElement("a");
      a.href = full || thumb;
      if (thumb) {
        const img = document.createElement("img");
        img.loading = "lazy"; img.src = thumb; img.alt = `variant ${index}`;
        a.appendChild(img);
      } else {
        a.textContent = "figure";
      }
      td.appendChild(a);
    }
  }
  sweep.columns.forEach((c, i) => cell(tr, row[4 + i], c.key === "status" || c.key.startsWith("v") ? "text" : ""));
  return tr;
}
async function show() {
  const ticket = ++shown, size = pageRows();
  document.body.dataset.busy = "yes";
  page = Math.min(Math.max(page, 0), pages() - 1);
  const first = page * size, last = Math.min(sweep.count, first + size);
  const positions = [];
  for (let i = first; i < last; ++i) positions.push(order ? order[i] : i);
  const needed = [...new Set(positions.map(p => Math.floor(p / sweep.perFile)))];
  if (needed.some(k => !files.has(k))) say("loading…");
  const got = new Map(await Promise.all(needed.map(async k => [k, await rowsFile(k)])));
  if (ticket !== shown) return;
  const body = document.createElement("tbody");
  body.id = "rows";
  for (const p of positions) body.appendChild(rowElement(got.get(Math.floor(p / sweep.perFile))[p % sweep.perFile]));
  $("rows").replaceWith(body);
  $("page").value = page + 1;
  $("page").max = pages();
  $("pages").textContent = `of ${pages()} (rows ${last > first ? first + 1 : 0}–${last} of ${sweep.count})`;
  $("first").disabled = $("prev").disabled = page === 0;
  $("next").disabled = $("last").disabled = page >= pages() - 1;
  const wanted = new URLSearchParams({sort: nameOf($("sort").value), order: $("order").value, page: page + 1, rows: size});
  history.replaceState(null, "", "#" + wanted);
  say("");
  document.body.dataset.busy = "";
  document.body.dataset.shown = wanted.toString();
}
async function resort() {
  page = 0;
  const ticket = sorted + 1;
  await sortBy();
  if (ticket === sorted) await show();  // else a later sort shows its own
}
const run = action => action().catch(e => { say(e.message); document.body.dataset.busy = ""; });
function start() {
  const head = $("head");
  const th = (text, key) => {
    const h = document.createElement("th");
    h.textContent = text;
    if (key) {
      h.title = `sort by ${text}`;
      h.onclick = () => {
        if ($("sort").value === key) $("order").value = $("order").value === "asc" ? "desc" : "asc";
        else { $("sort").value = key; $("order").value = "asc"; }
        run(resort);
      };
    }
    head.appendChild(h);
  };
  th("#", "index");
  if (sweep.figures) th("figure");
  for (const c of sweep.columns) {
    th(c.name, c.key);
    const o = document.createElement("option");
    o.value = c.key; o.textContent = c.name;
    $("sort").appendChild(o);
  }
  // The address names the sort, the order, the page and its rows: #sort=NAME&order=desc&page=3&rows=100.
  const follow = () => {
    const wanted = new URLSearchParams(location.hash.slice(1));
    const option = Array.from($("sort").options).find(o => o.textContent === wanted.get("sort"));
    $("sort").value = option ? option.value : "index";
    $("order").value = wanted.get("order") === "desc" ? "desc" : "asc";
    $("size").value = ["50", "100", "500"].includes(wanted.get("rows")) ? wanted.get("rows") : "100";
    page = Math.max(0, (Number(wanted.get("page")) || 1) - 1);
  };
  follow();
  window.addEventListener("hashchange", () => { follow(); run(async () => { await sortBy(); await show(); }); });
  $("sort").onchange = $("order").onchange = () => run(resort);
  $("size").onchange = () => { page = 0; run(show); };
  $("first").onclick = () => { page = 0; run(show); };
  $("prev").onclick = () => { page -= 1; run(show); };
  $("next").onclick = () => { page += 1; run(show); };
  $("last").onclick = () => { page = pages() - 1; run(show); };
  $("page").onchange = () => { page = (Math.floor(Number($("page").value)) || 1) - 1; run(show); };
  run(async () => { await sortBy(); await show(); });
}
start();
