// The book's figures and tables, on the reader's machine (book/build_book.py
// copies this next to the pages).
//
// A figure (an SVG drawn at build time, a chart) shows shrunk to the column,
// which on a phone makes its text too small to read. A tap or click opens it
// full size in a layer over the page, zoomed so that its smallest text is at
// least data-text-px pixels (the builder writes the figure's width and its
// smallest text, both in the SVG's own units); the layer scrolls both ways and
// closes with its button, Escape, or a tap beside the figure. Without scripts
// the link opens the SVG file itself.
//
// A table wider than the column scrolls sideways in its own box; the line
// above it that says so is shown only where that is the case.
//
// And the maths is typeset, by KaTeX (typeset(), below), and an aside folded
// under its heading opens when a link leads into it (openTarget(), below).
(function () {
  "use strict";

  var layer = null, opener = null;

  function close() {
    if (!layer) return;
    layer.parentNode.removeChild(layer);
    layer = null;
    document.body.classList.remove("figure-open");
    if (opener) opener.focus();
  }

  function open(link) {
    close();
    opener = link;
    var img = link.querySelector("img");
    var width = parseFloat(link.getAttribute("data-width"));
    var text = parseFloat(link.getAttribute("data-min-text"));
    var wanted = parseFloat(link.getAttribute("data-text-px"));
    // Pixels per unit of the SVG: at least 1, and enough for its smallest text.
    var scale = Math.max(1, wanted / text);
    layer = document.createElement("div");
    layer.className = "figure-layer";
    layer.setAttribute("role", "dialog");
    layer.setAttribute("aria-modal", "true");
    layer.setAttribute("aria-label", "The figure, full size");
    var bar = document.createElement("div");
    bar.className = "figure-bar";
    var note = document.createElement("span");
    note.textContent = "Full size: scroll or drag to move around.";
    var button = document.createElement("button");
    button.type = "button";
    button.textContent = "Close \u00d7";
    button.addEventListener("click", close);
    bar.appendChild(note);
    bar.appendChild(button);
    var pane = document.createElement("div");
    pane.className = "figure-pane";
    var big = document.createElement("img");
    big.src = img.src;
    big.alt = img.alt;
    big.style.width = Math.ceil(width * scale) + "px";
    pane.appendChild(big);
    pane.addEventListener("click", function (event) { if (event.target === pane) close(); });
    layer.appendChild(bar);
    layer.appendChild(pane);
    document.body.appendChild(layer);
    document.body.classList.add("figure-open");
    button.focus();
  }

  function markWideTables() {
    var boxes = document.querySelectorAll(".table-wrap");
    for (var i = 0; i < boxes.length; i++) {
      var scroll = boxes[i].querySelector(".table-scroll");
      boxes[i].classList.toggle("overflows", scroll.scrollWidth > scroll.clientWidth + 1);
    }
  }

  // A display formula wider than the column scrolls in its own box (style.css);
  // a phone hides scroll bars, so a box that scrolls is marked, as a wide table is.
  function markWideMaths() {
    var boxes = document.querySelectorAll(".math.display");
    for (var i = 0; i < boxes.length; i++)
      boxes[i].classList.toggle("overflows", boxes[i].scrollWidth > boxes[i].clientWidth + 1);
  }

  // The maths: each <span class="math"> and <div class="math display"> holds TeX,
  // typeset by KaTeX (katex/katex.min.js, Debian's libjs-katex, loaded before this
  // script). A formula KaTeX cannot parse stays as TeX and is a console error, which
  // the browser test reports.
  function typeset() {
    var formulas = document.querySelectorAll(".math");
    if (!formulas.length) return;
    if (!window.katex) { console.error("KaTeX did not load (katex/katex.min.js): the maths shows as TeX"); return; }
    for (var i = 0; i < formulas.length; i++) {
      var tex = formulas[i].textContent;
      try {
        window.katex.render(tex, formulas[i], {displayMode: formulas[i].classList.contains("display"),
                                               throwOnError: true, output: "htmlAndMathml"});
        formulas[i].setAttribute("data-tex", tex);
      } catch (error) {
        console.error("KaTeX cannot typeset '" + tex + "': " + error.message);
      }
    }
  }

  // A folded aside (build_book.py's fold_asides) opens when a link, a search
  // result or the address leads into it; once open, its tables and formulas
  // are measured again (closed, they had no width).
  function openTarget() {
    var id = decodeURIComponent(location.hash.slice(1));
    var target = id && document.getElementById(id);
    var fold = target && target.closest("details.aside");
    if (!fold) return;
    fold.open = true;
    target.scrollIntoView();
  }

  function init() {
    typeset();
    var folds = document.querySelectorAll("details.aside");
    for (var f = 0; f < folds.length; f++)
      folds[f].addEventListener("toggle", function () { markWideTables(); markWideMaths(); });
    openTarget();
    window.addEventListener("hashchange", openTarget);
    var links = document.querySelectorAll("a.figure[data-width]");
    for (var i = 0; i < links.length; i++) {
      links[i].addEventListener("click", function (event) {
        if (event.button !== 0 || event.ctrlKey || event.metaKey || event.shiftKey) return;
        event.preventDefault();
        open(this);
      });
    }
    document.addEventListener("keydown", function (event) {
      if (event.key === "Escape" && layer) { event.preventDefault(); close(); }
    });
    markWideTables();
    window.addEventListener("resize", markWideTables);
    markWideMaths();
    window.addEventListener("resize", markWideMaths);
    window.addEventListener("load", markWideMaths);  // once the fonts have their widths
    window.addEventListener("load", markWideTables);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
  else init();
})();
