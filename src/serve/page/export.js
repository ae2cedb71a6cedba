// Export: the current frame and the animation as pita render --at and pita animate write them.
// Part of pita serve's page: src/CMakeLists.txt joins src/serve/page/*.js, in
// its order, into page.html's one script.

function exportUrl(index, what) {
  const v = views.get(index);
  const at = what !== "animation" && v.t !== null ? `&at=${v.t}` : "";
  return api(`/api/export/${index}`, `&what=${what}${at}`);
}

// A download of the server's answer, named by its Content-Disposition.
function download(url) {
  const a = document.createElement("a");
  a.href = url;
  a.download = "";
  document.body.appendChild(a);
  a.click();
  a.remove();
}
