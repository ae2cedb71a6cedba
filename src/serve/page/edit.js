// --edit: the handles, drags written back into the scene file, undo.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// --edit: each keyframe's tail and tip, each pose's corners, drawn over the
// figure (its user units are canvas pixels) and dragged; the server turns a
// drag into the scene file's new values and answers how to undo it.
function drawHandles(index) {
  const v = views.get(index);
  const svg = v.figure.querySelector("svg");
  if (!svg || !v.handles.length) return;
  for (const h of v.handles) {
    const c = document.createElementNS("http://www.w3.org/2000/svg", "circle");
    c.setAttribute("cx", h.at[0]);
    c.setAttribute("cy", h.at[1]);
    c.setAttribute("r", 7);
    c.setAttribute("class", `handle ${h.part}`);
    c.dataset.pointer = h.pointer;
    c.dataset.part = h.part;
    c.dataset.panel = String(h.panel);
    c.addEventListener("pointerdown", (down) => {
      down.preventDefault();
      c.setPointerCapture(down.pointerId);
      const toSvg = (e) => {
        const p = svg.createSVGPoint();
        p.x = e.clientX; p.y = e.clientY;
        return p.matrixTransform(svg.getScreenCTM().inverse());
      };
      const move = (e) => { const p = toSvg(e); c.setAttribute("cx", p.x); c.setAttribute("cy", p.y); };
      const up = async (e) => {
        c.removeEventListener("pointermove", move);
        c.removeEventListener("pointerup", up);
        const p = toSvg(e);
        await edit(index, { drag: { panel: h.panel, pointer: h.pointer, part: h.part, to: [p.x, p.y],
                                    version: v.version } }, true);
      };
      c.addEventListener("pointermove", move);
      c.addEventListener("pointerup", up);
    });
    svg.appendChild(c);
  }
}

async function edit(index, request, remember) {
  const v = views.get(index);
  const mine = v.edits = (v.edits || 0) + 1;  // the page shows what the latest edit says
  const response = await fetch(api(`/api/edit/${index}`), { method: "POST", body: JSON.stringify(request),
                                                           headers: { "Content-Type": "application/json" } });
  const answer = await response.json();
  if (response.ok && remember) v.undo.push(answer.previous);
  v.undoButton.style.display = v.undo.length ? "" : "none";
  if (mine !== v.edits) return response.ok;
  if (response.ok) {
    v.refused.classList.remove("shown");
  } else {
    v.refused.textContent = answer.refused ? `refused: ${describe(answer.refused)}` : `refused: ${answer.error}`;
    v.refused.classList.add("shown");
    v.refusedDigest = answer.digest;  // the text it was refused against
    await frame(index);  // the handles back where the file has them
  }
  return response.ok;
}

async function undo(index) {
  const v = views.get(index);
  const last = v.undo.pop();
  v.undoButton.style.display = v.undo.length ? "" : "none";
  if (last) await edit(index, { changes: last }, false);
}
