// The slider and play: frames seeked in the animated SVG the server makes once per save.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// The time of frame k (animate::Timeline::time): the time pita render --at draws.
function frameTime(tl, k) {
  if (tl.loop) return tl.first + (tl.last - tl.first) * k / tl.frames;
  if (k === tl.frames - 1) return tl.last;
  return tl.first + (tl.last - tl.first) * k / (tl.frames - 1);
}

// Shows frame k: seeks the animated SVG when the page has it (no request),
// else fetches the frame (cancelling the one it supersedes).
function seek(index, k) {
  const v = views.get(index);
  const tl = v.timeline;
  if (!tl) return;
  k = tl.loop ? ((k % tl.frames) + tl.frames) % tl.frames : Math.max(0, Math.min(tl.frames - 1, k));
  v.k = k;
  v.t = frameTime(tl, k);
  v.slider.value = String(k);
  const name = tl.what === "pattern" ? "\u03c4" : "t";
  v.time.textContent = `${name} = ${v.t.toFixed(3)}  (frame ${k + 1} of ${tl.frames})`;
  v.still.style.display = "";
  // The animated SVG has the scene's own camera: a view turned in the page (camera.js) fetches its frames.
  if (v.animation !== null && !v.turned) {
    if (v.shown !== "animation") {
      v.frames = (v.frames || 0) + 1;  // a frame still on its way is not shown
      if (v.fetching) v.fetching.abort();
      v.figure.innerHTML = scoped(v.animation, `s${index}-`);
      v.shown = "animation";
      v.figure.classList.remove("stale");
      decorate(index);
    }
    const svg = v.figure.querySelector("svg");
    svg.pauseAnimations();
    // Frame k shows from k / fps to (k + 1) / fps: its middle.
    svg.setCurrentTime((k + 0.5) / tl.fps);
    if (v.shownFrame !== k) { v.shownFrame = k; v.changes++; }
  } else if (!(v.playing && v.fetching)) {
    frame(index);  // in play, the next frame is asked for once the last one came
  }
}

// The animated SVG of the figure shown (made once per save by the server);
// until it comes, or when the server has none, frames are fetched one by one.
async function loadAnimation(index) {
  const v = views.get(index);
  const version = v.version;
  v.animation = null;
  v.animationRefused = null;
  if (!v.timeline) return;
  const response = await fetch(api(`/api/animation/${index}`)).catch(() => null);
  if (!response || version !== v.version) return;
  if (!response.ok) {  // why the frames are fetched one by one (the slider's title says it)
    const answer = await response.json().catch(() => ({}));
    if (version !== v.version) return;
    v.animationRefused = answer.error || `the server says ${response.status}`;
    v.slider.title = `frames drawn by the server one by one: ${v.animationRefused}`;
    return;
  }
  const svg = await response.text();
  if (version !== v.version) return;
  v.animation = svg;
  if (v.t !== null) { v.shown = null; seek(index, v.k); }  // a frame shown: from this animation now
}

function stop(index) {
  const v = views.get(index);
  v.playing = false;
  v.play.textContent = "play";
}

// Play: at each frame of the display, the frame of the animation's clock.
function toggle(index) {
  const v = views.get(index);
  if (v.playing) return stop(index);
  if (!v.timeline) return;
  v.playing = true;
  v.play.textContent = "pause";
  const tl = v.timeline;
  let start = null;
  const step = (now) => {
    if (!v.playing) return;
    if (start === null) start = now - (v.t === null ? 0 : v.k) * 1000 / tl.fps;
    let k = Math.floor((now - start) / 1000 * tl.fps);
    if (!tl.loop && k >= tl.frames) { seek(index, tl.frames - 1); return stop(index); }
    if (k !== v.k || v.t === null) seek(index, k);
    requestAnimationFrame(step);
  };
  requestAnimationFrame(step);
}
