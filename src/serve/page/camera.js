// Turning 3D scenes: a drag on a panel turns the scene's camera and the server draws the figure
// with it (/api/figure/N?camera=AZ,EL[,DIST]), and the slider's frames while the view is held
// turned; "Save view" writes it into the scene file (--edit).
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// Degrees of turn per CSS pixel dragged: across a 600 px figure, most of a turn.
const kDegreesPerPixel = 0.5;
// The limits of "camera" (scene/limits.hpp): the elevation from straight down to straight up.
const kMaxElevation = 90;

// Tenths of a degree: what a pixel of drag resolves, written short ("-52.5", not 17 digits).
const tenth = (x) => Math.round(x * 10) / 10;
// The azimuth kept within (-180, 180], inside the reader's +-360.
const wrapAzimuth = (a) => tenth(a - 360 * Math.ceil((a - 180) / 360));
const turnKey = (turn) => turn ? `${turn.azimuth},${turn.elevation}${turn.distance ? `,${turn.distance}` : ""}` : "";

// The query of the figure with the turned camera ("" when the view is the file's).
function turnedQuery(index) {
  const v = views.get(index);
  return v.turned ? `&camera=${turnKey(v.turned)}` : "";
}

// After /api/scenes: the scene's camera (null for a scene of the plane), and
// the turned view dropped once the file has it (after "Save view").
function cameraState(index, scene) {
  const v = views.get(index);
  v.camera = scene.camera || null;
  v.figure.classList.toggle("turns", !!v.camera);
  if (!v.camera) { v.turned = null; if (v.cameraTools) v.cameraTools.style.display = "none"; return; }
  const c = v.camera;
  if (v.turned && !c.auto && c.azimuth === v.turned.azimuth && c.elevation === v.turned.elevation &&
      (!v.turned.distance || v.turned.distance === c.distance)) {
    v.turned = null;
  }
  cameraTools(index);
  v.figure.title = "drag: turn the camera; shift+drag: pan (when zoomed); wheel: zoom" +
    (c.perspective ? "; shift+wheel: nearer or farther" : "") + "; \u2190 \u2192: a frame; space: play";
  showCamera(index);
}

// The camera's tools under the figure: what it shows, "reset view" and "Save view".
function cameraTools(index) {
  const v = views.get(index);
  if (v.cameraTools) { v.cameraTools.style.display = ""; return; }
  v.cameraTools = el("span", "camera-tools", v.tools);
  v.cameraShown = el("span", "camera", v.cameraTools);
  v.cameraShown.setAttribute("aria-live", "polite");
  v.resetView = el("button", "reset-view", v.cameraTools);
  v.resetView.textContent = "reset view";
  v.resetView.title = "the camera the scene file gives";
  v.resetView.addEventListener("click", () => {
    v.turned = null; showCamera(index);
    if (v.t !== null) { v.shown = null; seek(index, v.k); } else frame(index);
  });
  v.saveView = el("button", "save-view", v.cameraTools);
  v.saveView.textContent = "Save view";
  v.saveView.title = "write this camera into the scene file (its azimuth and elevation; \"auto\": false)";
  v.saveView.addEventListener("click", () => saveView(index));
}

// The camera shown: the turned one, or the file's as each panel is drawn ("auto" may turn it).
function showCamera(index) {
  const v = views.get(index);
  if (!v.cameraShown) return;
  const c = v.camera;
  const drawn = v.turned || (c.panels && c.panels[0]) || c;
  const distance = v.turned && v.turned.distance ? v.turned.distance : c.distance;
  let text = `camera: azimuth ${drawn.azimuth}\u00b0, elevation ${drawn.elevation}\u00b0` +
             (c.perspective ? `, distance ${g4(distance)}` : "");
  if (v.turned) {
    text += ` (turned; the file: ${c.azimuth}\u00b0, ${c.elevation}\u00b0${c.auto ? ", auto" : ""})`;
  } else if (c.auto) {
    text += ` (auto; the file: ${c.azimuth}\u00b0, ${c.elevation}\u00b0)`;
  }
  v.cameraShown.textContent = text;
  v.resetView.style.display = v.turned ? "" : "none";
  v.saveView.style.display = v.turned && c.save ? "" : "none";
}

// The server could not draw the turned view (a perspective camera among the solids): why, after the camera.
function turnFailed(index, failure) {
  const v = views.get(index);
  if (!v.cameraShown || !failure) return;
  const why = failure.error || (failure.reason ? describe(failure) : "");
  if (why) v.cameraShown.textContent += ` — not drawn: ${why}`;
}

// The panel under the pointer, or -1.
function panelAt(index, e) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  if (!svg || !v.panels) return -1;
  const at = svgPoint(svg, e);
  return v.panels.findIndex(([x, y, w, h]) => at.x >= x && at.x < x + w && at.y >= y && at.y < y + h);
}

// A press that turns: the left button on a panel of a 3D scene, without Shift (Shift pans).
function turnsAt(index, e) {
  const v = views.get(index);
  return !!v.camera && e.button === 0 && !e.shiftKey && panelAt(index, e) >= 0;
}

// A drag on a 3D panel: horizontal motion turns the azimuth, vertical the
// elevation (clamped); each move asks for the figure, one request at a time.
function turn(index, down) {
  const v = views.get(index);
  if (!turnsAt(index, down) || down.target.classList.contains("handle")) return;
  down.preventDefault();
  const panel = panelAt(index, down);
  const from = v.turned || (v.camera.panels && v.camera.panels[panel]) || v.camera;
  const start = { azimuth: from.azimuth, elevation: from.elevation, distance: v.turned ? v.turned.distance : null };
  const move = (e) => {
    const azimuth = wrapAzimuth(start.azimuth - (e.clientX - down.clientX) * kDegreesPerPixel);
    const elevation = tenth(Math.max(-kMaxElevation, Math.min(kMaxElevation,
                                     start.elevation + (e.clientY - down.clientY) * kDegreesPerPixel)));
    const next = { azimuth, elevation, distance: start.distance };
    if (turnKey(next) === turnKey(v.turned)) return;
    // Turning shows the figure itself: a frame of the slider has the scene's own camera.
    if (v.t !== null) { stop(index); v.t = null; v.k = 0; v.slider.value = "0"; v.time.textContent = ""; }
    v.turned = next;
    v.turnMovedAt = e.timeStamp;  // when the move happened (performance.now's clock)
    showCamera(index);
    askTurned(index);
  };
  const up = () => { window.removeEventListener("pointermove", move); window.removeEventListener("pointerup", up); };
  window.addEventListener("pointermove", move);
  window.addEventListener("pointerup", up);
}

// At most one turned figure on its way: while one is, the latest camera waits
// and is asked for when it comes (afterFrame).
function askTurned(index) {
  const v = views.get(index);
  if (v.fetching && v.fetchingTurn) { v.turnWanted = true; return; }
  v.turnWanted = false;
  frame(index);
}

// frame()'s answer came (shown, or refused): the camera turned since is asked for now.
function afterFrame(index) {
  const v = views.get(index);
  if (!v.turnWanted) return;
  v.turnWanted = false;
  if (turnKey(v.turned) !== v.shownTurn && v.t === null) frame(index);
}

// Shift+wheel over a perspective 3D panel: the camera nearer (up) or farther;
// true when it took the wheel (else the wheel zooms the view box, zoom.js).
function wheelDistance(index, e) {
  const v = views.get(index);
  if (!v.camera || !v.camera.perspective || !e.shiftKey || panelAt(index, e) < 0) return false;
  e.preventDefault();
  const delta = e.deltaY || e.deltaX;
  if (!delta) return true;
  const c = v.camera;
  const from = v.turned || { ...((c.panels && c.panels[panelAt(index, e)]) || c), distance: null };
  const distance = Math.max(1e-3, (from.distance || c.distance) * (delta > 0 ? 1.1 : 1 / 1.1));
  v.turned = { azimuth: from.azimuth, elevation: from.elevation, distance: parseFloat(distance.toPrecision(4)) };
  v.turnMovedAt = performance.now();
  showCamera(index);
  askTurned(index);
  return true;
}

// "Save view": the turned camera written into the scene file, through the edit
// that keeps every other byte (members the file lacks are added; undo takes
// them out again); "auto": false too, so that the file draws what the page shows.
async function saveView(index) {
  const v = views.get(index);
  const c = v.camera, t = v.turned;
  if (!t || !c) return;
  const changes = [{ pointer: "/camera/azimuth", value: String(t.azimuth) },
                   { pointer: "/camera/elevation", value: String(t.elevation) }];
  if (t.distance && t.distance !== c.distance) changes.push({ pointer: "/camera/distance", value: String(t.distance) });
  if (c.auto) changes.push({ pointer: "/camera/auto", value: "false" });
  v.saveView.disabled = true;
  try {
    await edit(index, { changes }, true);
  } finally {
    v.saveView.disabled = false;
  }
}
