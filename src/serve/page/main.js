// The index of scenes, the refresh on each save (server-sent events), and the start.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// With several scenes, links to each at the top, with their files' paths.
function index(scenes) {
  const nav = document.getElementById("index");
  nav.classList.toggle("shown", scenes.length > 1);
  if (scenes.length < 2) return;
  nav.firstElementChild.replaceChildren(...scenes.map(scene => {
    const item = document.createElement("li");
    const a = el("a", "", item);
    a.href = `#scene-${scene.index}`;
    a.textContent = scene.title ? `${scene.name}: ${scene.title}` : scene.name;
    el("span", "path", item).textContent = ` ${scene.path}`;
    return item;
  }));
}

async function refresh(only) {
  const response = await fetch(api("/api/scenes"));
  if (!response.ok) { document.getElementById("status").textContent = `the server says ${response.status}`; return; }
  const scenes = await response.json();
  document.getElementById("status").textContent = `${scenes.length} scene${scenes.length === 1 ? "" : "s"}`;
  index(scenes);
  for (const scene of scenes) {
    if (only !== undefined && scene.index !== only) continue;
    const v = view(scene);
    if (scene.version < v.version) continue;  // an older answer, overtaken by a newer one
    v.title.textContent = scene.title ? `${scene.name}: ${scene.title}` : scene.name;
    v.path.textContent = scene.path;
    v.caption.textContent = scene.description || "";
    v.caption.style.display = scene.description ? "" : "none";
    v.error.textContent = scene.error ? describe(scene.error) : "";
    v.error.classList.toggle("shown", !!scene.error);
    v.timeline = scene.timeline;
    v.handles = scene.handles || [];
    v.sceneViews = scene.views || null;  // each panel's world view, which edits hold (edit.js)
    v.editing = !!scene.views;
    if (v.editing) {
      v.figure.title = "drag a handle to edit; click one, then \u2190 \u2192 \u2191 \u2193 nudge it (Shift: ten), Escape " +
                       "deselects; Ctrl+Z: undo, Ctrl+Shift+Z: redo; wheel: zoom; \"fit\": the whole figure refitted";
    }
    v.keys = scene.keys || [];
    // Drawn again only when the times change, and not under a marker being dragged.
    const keysText = JSON.stringify(v.keys) + v.editing;
    if (keysText !== v.keysText && !v.markerDrag) { v.keysText = keysText; drawTimeline(scene.index); }
    v.panels = scene.panels || [];
    cameraState(scene.index, scene);
    if (scene.version !== v.version) {
      // Measures of the figure shown: those under the pointer follow it; the others go.
      v.report = null;
      if (v.hovered) measures(scene.index); else v.measures.textContent = "";
      // A good state of another text than the refused edit's makes the refusal old news.
      if (!scene.error && scene.digest !== v.refusedDigest) v.refused.classList.remove("shown");
    }
    // The caption's claims, as pita check measures them on the figure shown.
    v.claims.replaceChildren(...(scene.claims || []).map(c => {
      const item = document.createElement("li");
      item.className = c.held ? "held" : "failed";
      item.textContent = c.held ? c.says : `${c.says}: ${c.measured}`;
      item.title = c.measured;
      return item;
    }));
    if (scene.timeline) {
      // The slider's steps are the frames of pita animate: frame k at its time t_k.
      const tl = scene.timeline;
      const name = tl.what === "pattern" ? "\u03c4" : "t";
      v.sliderLabel.textContent = `${name} from ${g4(tl.first)} to ${g4(tl.last)}`;
      v.sliderLabel.title = tl.what === "pattern"
        ? "\u03c4: the parameter of the moving keyframes (the animation's pattern)"
        : "t: the scene's time, from its first keyframe's to its last";
      v.slider.min = "0";
      v.slider.max = String(tl.frames - 1);
      v.slider.step = "1";
      v.slider.setAttribute("aria-label", `${name}: frame of ${tl.frames} at ${tl.fps} frames per second`);
      if (v.t === null) v.slider.value = "0";
      if (v.k >= tl.frames) v.k = tl.frames - 1;
      v.controls.classList.add("shown");
    } else {
      v.controls.classList.remove("shown");
    }
    v.exportAnimation.style.display = scene.timeline ? "" : "none";
    if (scene.version !== v.version) {
      v.version = scene.version;
      v.root.dataset.version = String(scene.version);
      loadAnimation(scene.index);
      if (v.t !== null && v.timeline) seek(scene.index, v.k); else await frame(scene.index);
    }
  }
}

refresh().then(() => {
  const events = new EventSource(api("/api/events"));
  // Saves between the first fetch and the stream's start: caught up with once open.
  events.onopen = () => refresh();
  events.onmessage = (message) => { window.pitaLastEvent = Date.now(); refresh(JSON.parse(message.data).scene); };
  events.onerror = () => { document.getElementById("status").textContent = "connection lost: is pita serve running?"; };
});
