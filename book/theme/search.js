// The book's full-text search, on the reader's machine: no server, no library.
//
// book/build_book.py writes search-index.js next to the pages: every page cut
// into its sections (heading, anchor, plain text, the quoted code included).
// This script loads it the first time the search box is used (a <script> tag,
// which works from file:// too), and ranks the pages that contain every word
// of the query:
//   - each word counts 1 + ln(occurrences on the page),
//   - plus 6 when the page's title holds it and 3 when one of its headings does,
//   - plus 4 for the first chapter, in reading order, that uses it: the book
//     teaches in order, so that is where a call or an idea is introduced.
// Each result links to the section that holds the most matches, with a snippet.
// index.html?q=WORDS opens with the results for WORDS.
(function () {
  "use strict";

  var script = document.currentScript;
  var base = script ? script.src.replace(/[^\/]*$/, "") : "";
  var index = null;       // {pages: [[file, title, kind]], sections: [[page, id, heading, text]]}
  var lowered = null;     // per section: [heading, text] in lower case
  var loading = false;
  var pending = null;     // the query to run once the index is there

  function load(then) {
    if (index) { then(); return; }
    pending = then;
    if (loading) return;
    loading = true;
    var tag = document.createElement("script");
    tag.src = base + "search-index.js";
    tag.onload = function () {
      index = window.BOOK_SEARCH_INDEX;
      lowered = index.sections.map(function (s) { return [s[2].toLowerCase(), s[3].toLowerCase()]; });
      if (pending) pending();
    };
    tag.onerror = function () { status("The search index (search-index.js) could not be loaded."); };
    document.head.appendChild(tag);
  }

  function occurrences(text, word) {
    var count = 0, at = text.indexOf(word);
    while (at !== -1) { count += 1; at = text.indexOf(word, at + word.length); }
    return count;
  }

  function search(query) {
    var words = query.toLowerCase().split(/\s+/).filter(function (w) { return w.length > 0; });
    if (!words.length) return [];
    var pages = index.pages.map(function (page, i) {
      return {page: i, score: 0, hits: words.map(function () { return 0; }), best: -1, bestHits: -1,
              inHeading: words.map(function () { return false; })};
    });
    lowered.forEach(function (section, s) {
      var p = pages[index.sections[s][0]], total = 0;
      words.forEach(function (w, k) {
        var n = occurrences(section[1], w) + occurrences(section[0], w);
        if (occurrences(section[0], w)) p.inHeading[k] = true;
        p.hits[k] += n;
        total += n;
      });
      if (total > p.bestHits) { p.bestHits = total; p.best = s; }
    });
    var found = pages.filter(function (p) { return p.hits.every(function (n) { return n > 0; }); });
    words.forEach(function (w, k) {
      var first = null;
      found.forEach(function (p) {
        if (index.pages[p.page][2] === "chapter" && (first === null || p.page < first.page)) first = p;
      });
      if (first) { first.score += 4; first.firstUse = true; }
    });
    found.forEach(function (p) {
      var title = index.pages[p.page][1].toLowerCase();
      words.forEach(function (w, k) {
        p.score += 1 + Math.log(p.hits[k]);
        if (title.indexOf(w) !== -1) p.score += 6;
        else if (p.inHeading[k]) p.score += 3;
      });
    });
    found.sort(function (a, b) { return b.score - a.score || a.page - b.page; });
    return found.map(function (p) { p.words = words; return p; });
  }

  // Up to ~160 characters around the first match, the matches marked.
  function snippet(text, words) {
    var lower = text.toLowerCase(), at = -1;
    words.forEach(function (w) {
      var i = lower.indexOf(w);
      if (i !== -1 && (at === -1 || i < at)) at = i;
    });
    var start = Math.max(0, at - 60), end = Math.min(text.length, start + 160);
    var piece = (start > 0 ? "\u2026" : "") + text.slice(start, end) + (end < text.length ? "\u2026" : "");
    var out = document.createElement("span");
    out.className = "snippet";
    var lowerPiece = piece.toLowerCase(), i = 0;
    while (i < piece.length) {
      var next = -1, word = "";
      words.forEach(function (w) {
        var j = lowerPiece.indexOf(w, i);
        if (j !== -1 && (next === -1 || j < next)) { next = j; word = w; }
      });
      if (next === -1) { out.appendChild(document.createTextNode(piece.slice(i))); break; }
      out.appendChild(document.createTextNode(piece.slice(i, next)));
      var mark = document.createElement("mark");
      mark.textContent = piece.slice(next, next + word.length);
      out.appendChild(mark);
      i = next + word.length;
    }
    return out;
  }

  var form, input, list, statusLine;

  function status(text) { if (statusLine) statusLine.textContent = text; }

  function show(query) {
    list.textContent = "";
    if (!query.trim()) { status(""); return; }
    var results = search(query);
    status(results.length ? results.length + (results.length === 1 ? " page" : " pages")
                          : "Nothing found for \u201c" + query + "\u201d.");
    results.slice(0, 12).forEach(function (r) {
      var page = index.pages[r.page], section = index.sections[r.best];
      var item = document.createElement("li");
      var link = document.createElement("a");
      link.href = base + page[0] + (section[1] ? "#" + section[1] : "");
      link.textContent = page[1];
      item.appendChild(link);
      if (r.firstUse) {
        var first = document.createElement("span");
        first.className = "first-use";
        first.textContent = " first used here";
        item.appendChild(first);
      }
      if (section[2] && section[2] !== page[1]) {
        var where = document.createElement("span");
        where.className = "where";
        where.textContent = section[2];
        item.appendChild(where);
      }
      item.appendChild(snippet(section[3], r.words));
      list.appendChild(item);
    });
  }

  function run() { load(function () { show(input.value); }); }

  function init() {
    form = document.querySelector("form.search");
    if (!form) return;
    input = form.querySelector("input");
    list = form.querySelector(".search-results");
    statusLine = form.querySelector(".search-status");
    var timer = null;
    input.addEventListener("focus", function () { load(function () {}); });
    input.addEventListener("input", function () {
      clearTimeout(timer);
      timer = setTimeout(run, 120);
    });
    form.addEventListener("submit", function (event) {
      event.preventDefault();
      load(function () {
        show(input.value);
        var first = list.querySelector("a");
        if (first) window.location.href = first.href;
      });
    });
    input.addEventListener("keydown", function (event) {
      if (event.key === "Escape") { input.value = ""; show(""); }
    });
    document.addEventListener("keydown", function (event) {
      var typing = /^(INPUT|TEXTAREA|SELECT)$/.test((event.target || {}).tagName || "");
      if (event.key === "/" && !typing) { event.preventDefault(); input.focus(); }
    });
    var match = /[?&]q=([^&#]*)/.exec(window.location.search);
    if (match) {
      input.value = decodeURIComponent(match[1].replace(/\+/g, " "));
      run();
    }
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
  else init();
})();
