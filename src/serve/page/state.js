// The page's shared state: the token every request carries, the views of the scenes, small helpers.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

// The token this page was opened with: every request carries it.
const token = new URLSearchParams(location.search).get("token") || "";
const api = (path, extra) => `${path}?token=${encodeURIComponent(token)}${extra || ""}`;
const views = new Map();  // scene index -> its elements and state

function el(tag, cls, parent) {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (parent) parent.appendChild(e);
  return e;
}

// The error of a scene, as a person reads it: where, then why.
function describe(error) {
  let where = error.file;
  if (error.line > 0) where += `:${error.line}:${error.column}`;
  if (error.pointer) where += `: ${error.pointer}`;
  return `${where}: ${error.reason || error.message}`;
}
