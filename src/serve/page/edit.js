// --edit: the handles, drags shown live and written back into the scene file, selection and nudges, undo and redo.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// --edit: each keyframe's tail and tip, each pose's corners, drawn over the
// figure (its user units are canvas pixels) and dragged; the server turns a
// drag into the scene file's new values and answers how to undo it. While
// the button is held, the server draws the figure with the drag made in
// memory (POST /api/preview), in the views held since the first drag, so that
// nothing refits under the pointer.
function drawHandles(index, handles) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  v.shownHandles = handles || [];
  if (!svg || !v.shownHandles.length) return;
  for (const h of v.shownHandles) {
    const c = document.createElementNS("http://www.w3.org/2000/svg", "circle");
    const dragged = v.drag && sameHandle(v.drag.handle, h);
    c.setAttribute("cx", dragged ? v.drag.at[0] : h.at[0]);
    c.setAttribute("cy", dragged ? v.drag.at[1] : h.at[1]);
    c.setAttribute("r", 7);
    c.setAttribute("class", `handle ${h.part}`);
    c.classList.toggle("selected", sameHandle(v.selected, h));
    c.dataset.pointer = h.pointer;
    c.dataset.part = h.part;
    c.dataset.panel = String(h.panel);
    c.addEventListener("pointerdown", (down) => startDrag(index, h, down));
    svg.appendChild(c);
  }
}

const sameHandle = (a, b) => !!a && !!b && a.panel === b.panel && a.pointer === b.pointer && a.part === b.part;

// The circle of handle h in the figure shown.
function handleCircle(index, h) {
  const v = views.get(index);
  return [...v.figure.querySelectorAll("circle.handle")].find(c =>
    c.dataset.pointer === h.pointer && c.dataset.part === h.part && c.dataset.panel === String(h.panel));
}

// The views edits are read and drawn in: those of the figure shown when the first edit began, until "fit".
// With "camera": {"auto": true}, the camera the panels were drawn with then is held too: an edit
// could make auto turn the view under the pointer (when the panels' own autos differ, it is not).
function holdViews(v) {
  if (!v.held && v.sceneViews) {
    v.held = v.sceneViews;
    const panels = v.camera && v.camera.auto && v.camera.panels ? v.camera.panels : [];
    const same = panels.length && panels.every(p => p.azimuth === panels[0].azimuth && p.elevation === panels[0].elevation);
    v.heldCamera = same ? { azimuth: panels[0].azimuth, elevation: panels[0].elevation } : null;
  }
  return v.held;
}

function select(index, h) {
  const v = views.get(index);
  v.selected = h ? { panel: h.panel, pointer: h.pointer, part: h.part } : null;
  for (const c of v.figure.querySelectorAll("circle.handle")) {
    c.classList.toggle("selected", !!h && c === handleCircle(index, h));
  }
}

// A press on a handle selects it; moving it drags it (live figure), releasing writes the edit.
function startDrag(index, h, down) {
  const v = views.get(index);
  if (down.button !== 0) return;
  down.preventDefault();
  down.stopPropagation();
  v.figure.focus({ preventScroll: true });  // the keys (arrows, Escape, Ctrl+Z) go to this figure
  select(index, h);
  const toSvg = (e) => svgPoint(v.figure.querySelector("svg"), e);
  const drag = v.drag = { handle: h, at: h.at.slice(), moved: false, inFlight: null, dirty: false, movedAt: 0 };
  const move = (e) => {
    const p = toSvg(e);
    drag.at = [p.x, p.y];
    drag.moved = true;
    drag.movedAt = performance.now();
    const c = handleCircle(index, h);
    if (c) { c.setAttribute("cx", p.x); c.setAttribute("cy", p.y); }
    preview(index, drag);
  };
  const up = async (e) => {
    window.removeEventListener("pointermove", move);
    window.removeEventListener("pointerup", up);
    if (v.drag === drag) v.drag = null;
    if (drag.inFlight) drag.inFlight.abort();
    if (!drag.moved) return;  // a click: the handle selected only
    const p = toSvg(e);
    await edit(index, { drag: { panel: h.panel, pointer: h.pointer, part: h.part, to: [p.x, p.y], version: v.version },
                        views: holdViews(v), camera: v.heldCamera }, true);
  };
  window.addEventListener("pointermove", move);
  window.addEventListener("pointerup", up);
}

// The figure with the drag made, from the server: at most one request in
// flight; when it comes, the latest position is asked for (the server's own
// speed sets the rate).
async function preview(index, drag) {
  const v = views.get(index);
  if (drag.inFlight) { drag.dirty = true; return; }
  const control = drag.inFlight = new AbortController();
  drag.dirty = false;
  const movedAt = drag.movedAt;
  const h = drag.handle;
  try {
    const response = await fetch(api(`/api/preview/${index}`), {
      method: "POST", signal: control.signal,
      body: JSON.stringify({ drag: { panel: h.panel, pointer: h.pointer, part: h.part, to: drag.at },
                             views: holdViews(v), camera: v.heldCamera }) });
    const answer = await response.json();
    if (v.drag !== drag) return;  // released: the edit's figure comes
    if (response.ok) {
      v.frames = (v.frames || 0) + 1;  // a figure still on its way is older than this one
      v.figure.innerHTML = scoped(answer.svg, `s${index}-`);
      v.shown = "still";
      v.changes++;
      v.figure.classList.remove("stale");
      decorate(index);
      drawHandles(index, answer.handles);
      v.refused.classList.remove("shown");
      // Pointer move to the figure on screen (the next frame drawn), in ms: the browser test prints them.
      requestAnimationFrame(() => (window.pitaPreviewLatencies = window.pitaPreviewLatencies || []).push(performance.now() - movedAt));
    } else {
      // Refused: the reason over the figure, which does not move.
      v.refused.textContent = answer.refused ? `refused: ${describe(answer.refused)}` : `refused: ${answer.error}`;
      v.refused.classList.add("shown");
    }
  } catch (error) {
    return;  // cancelled by the release
  } finally {
    if (drag.inFlight === control) drag.inFlight = null;
  }
  if (drag.dirty && v.drag === drag) preview(index, drag);
}

// Keys on the figure with a handle selected: arrows nudge it one canvas
// pixel (Shift: ten), Escape deselects. True when the key was taken.
function nudgeKey(index, e) {
  const v = views.get(index);
  if (!v.selected || e.ctrlKey || e.metaKey || e.altKey) return false;
  if (e.key === "Escape") { e.preventDefault(); select(index, null); return true; }
  const steps = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[e.key];
  if (!steps || v.t !== null) return false;
  e.preventDefault();
  const h = v.shownHandles.find(x => sameHandle(x, v.selected));
  if (!h) return true;
  const n = e.shiftKey ? 10 : 1;
  // Where the handle is now in the views held: the next press nudges from
  // there, also before the server's new figure has come.
  h.at = [h.at[0] + steps[0] * n, h.at[1] + steps[1] * n];
  const c = handleCircle(index, h);
  if (c) { c.setAttribute("cx", h.at[0]); c.setAttribute("cy", h.at[1]); }
  edit(index, { drag: { panel: h.panel, pointer: h.pointer, part: h.part, to: h.at.slice() }, views: holdViews(v),
                camera: v.heldCamera }, true);
  return true;
}

// An edit of scene `index`, after the ones before it: `kind` says what its
// answer's undo goes to: true or "new" (the undo stack; redo emptied),
// "undo" (the redo stack), "redo" (the undo stack). Returns the answer, or
// null when refused.
function edit(index, request, kind) {
  const v = views.get(index);
  const run = () => sendEdit(index, request, kind === true ? "new" : kind);
  const done = v.queue.then(run, run);
  v.queue = done.catch(() => null);
  return done;
}

async function sendEdit(index, request, kind) {
  const v = views.get(index);
  lastEdited = index;
  const mine = v.edits = (v.edits || 0) + 1;  // the page shows what the latest edit says
  const response = await fetch(api(`/api/edit/${index}`), { method: "POST", body: JSON.stringify(request),
                                                           headers: { "Content-Type": "application/json" } });
  const answer = await response.json();
  if (response.ok) {
    if (kind === "new") { v.undo.push(answer.previous); v.redo = []; }
    if (kind === "undo") v.redo.push(answer.previous);
    if (kind === "redo") v.undo.push(answer.previous);
  }
  v.undoButton.style.display = v.undo.length ? "" : "none";
  v.redoButton.style.display = v.redo.length ? "" : "none";
  if (mine !== v.edits) return response.ok ? answer : null;
  if (response.ok) {
    v.refused.classList.remove("shown");
  } else {
    v.refused.textContent = answer.refused ? `refused: ${describe(answer.refused)}` : `refused: ${answer.error}`;
    v.refused.classList.add("shown");
    v.refusedDigest = answer.digest;  // the text it was refused against
    drawTimeline(index);  // a marker back where the file has it
    await frame(index);  // the handles back where the file has them
  }
  return response.ok ? answer : null;
}

// Undo and redo put back the text each edit replaced: byte for byte. An
// edit on its way is undone (redone) once its answer has come.
async function replay(index, kind) {
  const v = views.get(index);
  await v.queue;
  const stack = v[kind];
  const last = stack.pop();
  if (!last) return;
  if (!(await edit(index, { changes: last }, kind))) stack.push(last);
  v[`${kind}Button`].style.display = stack.length ? "" : "none";
}

const undo = (index) => replay(index, "undo");
const redo = (index) => replay(index, "redo");

// Ctrl+Z undoes, Ctrl+Shift+Z and Ctrl+Y redo, in the scene whose figure or
// controls have the focus, else the one edited last.
let lastEdited = null;
window.addEventListener("keydown", (e) => {
  if (!(e.ctrlKey || e.metaKey) || e.altKey) return;
  const key = e.key.toLowerCase();
  if (key !== "z" && key !== "y") return;
  const section = document.activeElement && document.activeElement.closest ? document.activeElement.closest("section.scene") : null;
  const index = section ? parseInt(section.id.slice("scene-".length), 10) : lastEdited;
  if (index === null || !views.has(index) || !views.get(index).editing) return;
  e.preventDefault();
  if (key === "y" || e.shiftKey) redo(index); else undo(index);
});
