// The timeline under the figure: a marker at each keyframe's, point's or pose's time; with --edit, dragged to edit "t".
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// One row per place the keys are given (the scene's, a panel's own), all on
// one scale from the least time to the greatest (a margin each side, so that
// the end markers can be taken and moved inwards).
function drawTimeline(index) {
  const v = views.get(index);
  const strip = v.timelineStrip;
  const rows = v.keys || [];
  const times = rows.flatMap(r => r.times.map(k => k.t));
  strip.replaceChildren();
  strip.classList.toggle("shown", times.length > 0);
  if (!times.length) return;
  let lo = Math.min(...times), hi = Math.max(...times);
  if (!(hi > lo)) { lo -= 1; hi += 1; }
  const pad = (hi - lo) * 0.04;
  const range = { lo: lo - pad, hi: hi + pad };
  const several = rows.length > 1;
  for (const row of rows) {
    const line = el("div", "timeline-row", strip);
    const label = el("span", "timeline-label", line);
    const kind = row.keys.split("/").pop();
    label.textContent = several ? `${kind} of panel${row.panels.length > 1 ? "s" : ""} ${row.panels.map(p => p + 1).join(", ")}` : kind;
    label.title = `the times of ${row.keys}`;
    const track = el("div", "timeline-track", line);
    row.times.forEach((key, k) => marker(index, track, range, key, k));
  }
}

function marker(index, track, range, key, k) {
  const v = views.get(index);
  const m = el("div", "marker", track);
  m.dataset.pointer = key.pointer;
  const place = (t) => {
    m.style.left = `${100 * (t - range.lo) / (range.hi - range.lo)}%`;
    m.firstChild.textContent = `${k}: t=${g4(t)}`;
  };
  el("span", k % 2 ? "marker-label high" : "marker-label", m);  // alternate heights: near times stay legible
  place(key.t);
  m.title = v.editing ? `${key.pointer}: t = ${key.t} (drag to move it; the times must increase)`
                      : `${key.pointer}: t = ${key.t} (start pita serve with --edit to move it)`;
  m.classList.toggle("editable", v.editing);
  if (!v.editing) return;
  m.addEventListener("pointerdown", (down) => {
    if (down.button !== 0) return;
    down.preventDefault();
    m.setPointerCapture(down.pointerId);
    const box = track.getBoundingClientRect();
    const timeAt = (e) => range.lo + (range.hi - range.lo) * Math.min(1, Math.max(0, (e.clientX - box.left) / box.width));
    let t = key.t, moved = false;
    v.markerDrag = true;
    const move = (e) => { t = timeAt(e); moved = true; place(t); m.classList.add("dragging"); };
    const up = async () => {
      m.removeEventListener("pointermove", move);
      m.removeEventListener("pointerup", up);
      m.classList.remove("dragging");
      v.markerDrag = false;
      if (!moved) return;
      // Written to what a pixel of the strip resolves.
      const step = (range.hi - range.lo) / Math.max(box.width, 1);
      await edit(index, { time: { pointer: key.pointer, t, step } }, true);
    };
    m.addEventListener("pointermove", move);
    m.addEventListener("pointerup", up);
  });
}
