// Renders the equations that pymdownx.arithmatex (generic mode) marks: inline
// <span class="arithmatex">\(...\)</span> and display <div class="arithmatex">\[...\]</div>,
// with the KaTeX vendored under docs/vendor/katex (no CDN: the site renders offline).
// A formula KaTeX cannot read is shown in red with class "katex-error" (docs/check_site.py
// fails on it).
(function () {
  function strip(tex) {
    tex = tex.trim();
    var pairs = [["\\(", "\\)"], ["\\[", "\\]"], ["$$", "$$"], ["$", "$"]];
    for (var i = 0; i < pairs.length; i++) {
      var open = pairs[i][0], close = pairs[i][1];
      if (tex.startsWith(open) && tex.endsWith(close) && tex.length >= open.length + close.length) {
        return tex.slice(open.length, tex.length - close.length);
      }
    }
    return tex;
  }
  function render(root) {
    var nodes = root.querySelectorAll(".arithmatex");
    for (var i = 0; i < nodes.length; i++) {
      var node = nodes[i];
      if (node.dataset.rendered) continue;
      katex.render(strip(node.textContent), node, {
        displayMode: node.tagName === "DIV",
        throwOnError: false,
        strict: "ignore",
      });
      node.dataset.rendered = "1";
    }
    document.body.dataset.mathRendered = String(nodes.length);
  }
  if (typeof document$ !== "undefined") {
    document$.subscribe(function () { render(document.body); });
  } else {
    document.addEventListener("DOMContentLoaded", function () { render(document.body); });
  }
})();
