// A scene's section of the page, and its figure or frame fetched from the server.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

function view(scene) {
  if (views.has(scene.index)) return views.get(scene.index);
  const root = el("section", "scene", document.getElementById("scenes"));
  root.id = `scene-${scene.index}`;
  const v = { root, title: el("h2", "", root), path: el("div", "path", root), error: el("div", "error", root),
              controls: el("div", "controls", root), stage: el("div", "stage", root), t: null, k: 0, version: -1,
              playing: false, timeline: null, handles: [], undo: [], hovered: false, panel: -1, box: null,
              animation: null, shown: null, changes: 0, held: null, sceneViews: null, selected: null, redo: [],
              shownHandles: [], keys: [], editing: false, queue: Promise.resolve() };
  v.figure = el("div", "figure", v.stage);
  v.figure.tabIndex = 0;
  v.figure.title = "wheel: zoom; drag the background: pan; \u2190 \u2192: a frame; space: play";
  v.refused = el("div", "refused", v.stage);
  // The keyframes' times under the figure (timeline.js).
  v.timelineStrip = el("div", "timeline", root);
  v.caption = el("p", "caption", root);
  v.tools = el("div", "tools", root);
  v.claims = el("ul", "claims", root);
  v.measures = el("div", "measures", root);
  v.sliderLabel = el("label", "", v.controls);
  v.slider = el("input", "", v.controls);
  v.slider.type = "range";
  v.slider.id = `slider-${scene.index}`;
  v.sliderLabel.htmlFor = v.slider.id;
  v.play = el("button", "play", v.controls);
  v.play.textContent = "play";
  v.play.title = "play the animation at its frames per second (space)";
  v.time = el("span", "time", v.controls);
  v.time.setAttribute("aria-live", "off");
  // Back to the figure itself (and, with --edit, its handles) from a frame of the slider.
  v.still = el("button", "still", v.controls);
  v.still.textContent = "figure";
  v.still.title = "the figure as pita render draws it, with its handles";
  v.still.style.display = "none";
  v.still.addEventListener("click", () => {
    v.t = null; stop(scene.index); v.time.textContent = "";
    v.slider.value = "0"; v.k = 0;
    frame(scene.index);
  });
  // "fit" shows the whole figure again: out of the zoom and pan, and, with
  // --edit, refitted to its content (drags hold the view they started in).
  v.fit = el("button", "fit", v.tools);
  v.fit.textContent = "fit";
  v.fit.title = "the whole figure, fitted to its content (after zooming with the wheel, panning by dragging the " +
                "background, or edits, which keep the view they started in)";
  v.fit.addEventListener("click", () => {
    v.box = null; applyBox(scene.index);
    if (v.held) { v.held = null; if (v.t === null) frame(scene.index); }
  });
  // Export: what pita render --at and pita animate write.
  const exportLink = (what, label, title) => {
    const a = el("a", `export ${what}`, v.tools);
    a.textContent = label; a.title = title; a.setAttribute("role", "button"); a.href = "#";
    a.addEventListener("click", (e) => { e.preventDefault(); a.href = exportUrl(scene.index, what); download(a.href); });
    return a;
  };
  el("span", "", v.tools).textContent = "download:";
  v.exportSvg = exportLink("svg", "SVG", "this frame as pita render [--at t] -o OUT.svg writes it");
  v.exportPng = exportLink("png", "PNG", "this frame as pita render [--at t] -o OUT.png writes it");
  v.exportAnimation = exportLink("animation", "animated SVG", "the animation as pita animate -o OUT.svg writes it");
  v.undoButton = el("button", "undo", root);
  v.undoButton.textContent = "undo";
  v.undoButton.title = "undo the last edit (Ctrl+Z)";
  v.undoButton.style.display = "none";
  v.undoButton.addEventListener("click", () => undo(scene.index));
  v.redoButton = el("button", "redo", root);
  v.redoButton.textContent = "redo";
  v.redoButton.title = "redo the edit undone (Ctrl+Shift+Z or Ctrl+Y)";
  v.redoButton.style.display = "none";
  v.redoButton.addEventListener("click", () => redo(scene.index));
  v.slider.addEventListener("input", () => { stop(scene.index); seek(scene.index, parseInt(v.slider.value, 10)); });
  v.play.addEventListener("click", () => toggle(scene.index));
  v.figure.addEventListener("mouseenter", () => { v.hovered = true; measures(scene.index); });
  v.figure.addEventListener("mouseleave", () => { v.hovered = false; v.panel = -1; showMeasures(scene.index); outline(scene.index); });
  v.figure.addEventListener("mousemove", (e) => pointAt(scene.index, e));
  v.figure.addEventListener("wheel", (e) => zoom(scene.index, e), { passive: false });
  v.figure.addEventListener("pointerdown", (e) => pan(scene.index, e));
  v.figure.addEventListener("pointerdown", (e) => turn(scene.index, e));  // a 3D panel (camera.js)
  // Keys, on the figure or the slider: arrows step a frame, space plays and
  // pauses; on the figure with a handle selected, arrows nudge it (edit.js).
  const keys = (e) => {
    if (e.currentTarget === v.figure && nudgeKey(scene.index, e)) return;
    if (!v.timeline || e.ctrlKey || e.metaKey || e.altKey) return;
    if (e.key === "ArrowRight" || e.key === "ArrowLeft") {
      e.preventDefault(); stop(scene.index);
      seek(scene.index, v.k + (e.key === "ArrowRight" ? 1 : -1));
    } else if (e.key === " ") {
      e.preventDefault(); toggle(scene.index);
    }
  };
  v.figure.addEventListener("keydown", keys);
  v.slider.addEventListener("keydown", keys);
  views.set(scene.index, v);
  return v;
}

// The figure (t null) or the frame at v.t fetched from the server: the
// latest request wins, and a request it supersedes is cancelled.
async function frame(index) {
  const v = views.get(index);
  // The figure or the frame with the camera turned in the page (camera.js), if it is.
  const turned = v.t === null ? turnKey(v.turned) : "";
  const extra = (v.t === null ? "" : `&at=${v.t}`) + turnedQuery(index);
  const mine = v.frames = (v.frames || 0) + 1;  // answers can come out of order: the latest request wins
  if (v.fetching) v.fetching.abort();
  const control = v.fetching = new AbortController();
  v.fetchingTurn = !!turned;
  const k = v.k;
  let response, svg, failure;
  // While edits hold the views, the figure and its handles in those views
  // (edit.js); a view turned in the page is drawn with its camera (camera.js).
  const held = v.t === null && v.held && !turned ? v.held : null;
  let handles = v.handles;
  try {
    if (held) {
      response = await fetch(api(`/api/preview/${index}`), { method: "POST", signal: control.signal,
                                                             body: JSON.stringify({ views: held, camera: v.heldCamera }) });
      const answer = await response.json();
      if (response.ok) { svg = answer.svg; handles = answer.handles; }
    } else {
      response = await fetch(api(`/api/figure/${index}`, extra), { signal: control.signal });
      if (response.ok) svg = await response.text(); else failure = await response.json().catch(() => null);
    }
  } catch (error) {
    return;  // cancelled: a newer request took its place
  } finally {
    if (v.fetching === control) v.fetching = null;
  }
  if (mine !== v.frames) return;
  if (held && !response.ok && response.status === 400 && v.held === held) {
    v.held = null;  // views the figure no longer has (a panel added or removed): fitted again
    return frame(index);
  }
  v.still.style.display = v.t === null ? "none" : "";
  if (response.ok) {
    v.figure.innerHTML = scoped(svg, `s${index}-`);
    v.svg = svg;  // as the server sent it
    v.shownTurn = turned;
    if (turned) v.turnShownAt = performance.now();
    v.shown = v.t === null ? "still" : "frame";
    v.shownFrame = v.t === null ? null : k;
    v.changes++;
    v.figure.classList.remove("stale");
    v.figure.dataset.version = String(v.version);
    decorate(index);
    if (v.t === null) drawHandles(index, turned ? [] : handles);  // handles only in the file's own camera
  } else {
    v.figure.classList.add("stale");
    if (turned) turnFailed(index, failure);
  }
  afterFrame(index);
}

// cairo names the glyphs and clips of every SVG alike (glyph0-1, clip1): in
// one page the second figure would draw with the first one's glyphs. Each
// figure's ids, and its references to them, get a prefix of their own.
function scoped(svg, prefix) {
  return svg.replace(/\bid="([^"]+)"/g, `id="${prefix}$1"`)
            .replace(/(xlink:href|href)="#([^"]+)"/g, `$1="#${prefix}$2"`)
            .replace(/url\(#([^)]+)\)/g, `url(#${prefix}$1)`);
}
