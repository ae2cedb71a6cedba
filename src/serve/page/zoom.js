// Zoom, pan and the outline of the hovered panel, in the figure's user units (canvas pixels).
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// The figure's whole canvas (its view box as drawn), kept on the element
// (not as an attribute: the figure stays the server's text).
function canvasBox(svg) {
  if (!svg.pitaCanvas) {
    const b = svg.viewBox.baseVal;
    svg.pitaCanvas = [b.x, b.y, b.width, b.height];
  }
  return svg.pitaCanvas;
}

// The view box: the part zoomed into, or the whole canvas.
function applyBox(index) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  if (!svg) return;
  const whole = canvasBox(svg);
  if (v.box) {
    svg.setAttribute("viewBox", v.box.join(" "));
    svg.classList.add("zoomed");
  } else if (svg.classList.contains("zoomed")) {
    svg.setAttribute("viewBox", whole.join(" "));
    svg.classList.remove("zoomed");
  }
}

// The pointer's place in the figure's user units (canvas pixels).
function svgPoint(svg, e) {
  const p = svg.createSVGPoint();
  p.x = e.clientX; p.y = e.clientY;
  return p.matrixTransform(svg.getScreenCTM().inverse());
}

function zoom(index, e) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  if (!svg || wheelDistance(index, e)) return;  // shift+wheel: a perspective camera's distance (camera.js)
  e.preventDefault();
  const at = svgPoint(svg, e);
  const [x, y, w, h] = v.box || canvasBox(svg);
  const width = canvasBox(svg)[2];
  // At most the whole canvas, at least 1/50 of it.
  const f = Math.min(width / w, Math.max(e.deltaY > 0 ? 1.25 : 0.8, 0.02 * width / w));
  const box = [at.x - (at.x - x) * f, at.y - (at.y - y) * f, w * f, h * f];
  v.box = box[2] >= width - 1e-9 ? null : box;
  applyBox(index);
}

function pan(index, down) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  if (!svg || !v.box || down.button !== 0 || down.target.classList.contains("handle")) return;
  if (turnsAt(index, down)) return;  // a drag on a 3D panel turns it (camera.js); shift+drag pans
  down.preventDefault();
  const inverse = svg.getScreenCTM().inverse();
  const start = new DOMPoint(down.clientX, down.clientY).matrixTransform(inverse);
  const box0 = v.box.slice();
  const move = (e) => {
    const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(inverse);
    v.box = [box0[0] - (p.x - start.x), box0[1] - (p.y - start.y), box0[2], box0[3]];
    applyBox(index);
  };
  const up = () => { window.removeEventListener("pointermove", move); window.removeEventListener("pointerup", up); };
  window.addEventListener("pointermove", move);
  window.addEventListener("pointerup", up);
}

// After a new figure or frame: its zoom, and the outline of the panel under the pointer.
function decorate(index) {
  applyBox(index);
  outline(index);
}

function outline(index) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  if (!svg) return;
  let rect = svg.querySelector("rect.outline");
  const cell = v.panel >= 0 && v.panels ? v.panels[v.panel] : null;
  if (!cell) { if (rect) rect.remove(); return; }
  if (!rect) {
    rect = document.createElementNS("http://www.w3.org/2000/svg", "rect");
    rect.setAttribute("class", "outline");
    svg.appendChild(rect);
  }
  const [x, y, w, h] = cell;
  rect.setAttribute("x", x + 1); rect.setAttribute("y", y + 1);
  rect.setAttribute("width", Math.max(0, w - 2)); rect.setAttribute("height", Math.max(0, h - 2));
}
