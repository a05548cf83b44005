// The book's full-text search, on the reader's machine: no server, no library.
//
// book/build_book.py writes search-index.js next to the pages: every page cut
// into its sections, and each section's words sorted by where they stand: its
// heading, what the chapter's recap says the section teaches (the recap's
// list of new calls links each to its section), its prose, its code, and the
// comments inside that code. This script loads it the first time the search
// box is used (a <script> tag, which works from file:// too).
//
// A word counts by where it stands, strongest first, because that is where
// the book teaches it rather than mentions it:
//   heading 12, recap 10, prose 3 + ln(times), code 1 + ln(times) / 2,
//   code comment 0.5.
// A section scores the sum over the query's words (a phrase of several words
// found whole in a heading or a recap entry adds 6), and a page scores its
// best section, plus a little for how often the page uses each word, plus 10
// for each word in the page's title and 4 for the first chapter in reading
// order with the word in a heading or its recap (where it is introduced), all
// times 1 for a chapter or an appendix, 0.6 for the performance part and 0.4
// for the index. Only pages holding every word are listed; ties go to the page
// that comes first in reading order. The one result marked "taught here" is
// the first chapter whose best section has the whole query in its heading or
// its recap entry. Each result links to its best section;
// its snippet comes from that section's prose, else its code, else its
// comments (shown as words, without the `//`).
// index.html?q=WORDS opens with the results for WORDS.
(function () {
  "use strict";

  var script = document.currentScript;
  var base = script ? script.src.replace(/[^\/]*$/, "") : "";
  var index = null;       // {pages: [[file, title, kind]], sections: [[page, id, heading, recap, prose, code, comments]]}
  var originals = null;   // per section: [heading, recap, prose, code, comments]
  var lowered = null;     // the same in lower case
  var loading = false;
  var pending = null;     // the query to run once the index is there

  var HEADING = 0, RECAP = 1, PROSE = 2, CODE = 3, COMMENTS = 4;
  var KIND_WEIGHT = {chapter: 1, appendix: 1, performance: 0.6, index: 0.4};
  var LABELS = ["in a heading", "in the recap", "", "in code", "in a code comment"];

  function load(then) {
    if (index) { then(); return; }
    pending = then;
    if (loading) return;
    loading = true;
    var tag = document.createElement("script");
    tag.src = base + "search-index.js";
    tag.onload = function () {
      index = window.BOOK_SEARCH_INDEX;
      originals = index.sections.map(function (s) { return s.slice(2, 7); });
      lowered = originals.map(function (fields) {
        return fields.map(function (t) { return t.toLowerCase(); });
      });
      if (pending) pending();
    };
    tag.onerror = function () { status("The search index (search-index.js) could not be loaded."); };
    document.head.appendChild(tag);
  }

  // A word is found where a word or a part of a name begins: "light" in
  // "lights" and "VkLightInfo", not in "flight"; "descriptor" in
  // "vkAllocateDescriptorSets" (the case of the original text tells).
  function starts(original, at) {
    if (at === 0) return true;
    var before = original.charAt(at - 1);
    return !/[A-Za-z0-9]/.test(before) || (/[a-z0-9]/.test(before) && /[A-Z]/.test(original.charAt(at)));
  }

  function occurrences(lower, original, word) {
    var count = 0, at = lower.indexOf(word);
    while (at !== -1) {
      if (starts(original, at)) count += 1;
      at = lower.indexOf(word, at + 1);
    }
    return count;
  }

  // What a query word is looked for as: "constants" finds "constant" too, and
  // "families" "family" (a plural's stem; the word itself is then found too).
  function stem(word) {
    if (word.length > 4 && /ies$/.test(word)) return word.slice(0, -3);
    if (word.length > 3 && /[^s]s$/.test(word)) return word.slice(0, -1);
    return word;
  }

  // How much one word weighs in one section, and the strongest place it stands there.
  function weigh(fields, originals, word) {
    var n = fields.map(function (text, f) { return occurrences(text, originals[f], word); });
    var score = 0, where = -1;
    if (n[HEADING]) score += 12;
    if (n[RECAP]) score += 10;
    if (n[PROSE]) score += 3 + Math.log(n[PROSE]);
    if (n[CODE]) score += 1 + Math.log(n[CODE]) / 2;
    if (n[COMMENTS]) score += 0.5;
    for (var f = 0; f < n.length; f++) if (n[f]) { where = f; break; }
    return {score: score, count: n[0] + n[1] + n[2] + n[3] + n[4], where: where};
  }

  function search(query) {
    var words = query.toLowerCase().split(/\s+/).filter(function (w) { return w.length > 0; }).map(stem);
    if (!words.length) return [];
    var pages = index.pages.map(function (page, i) {
      return {page: i, hits: words.map(function () { return 0; }), taught: words.map(function () { return false; }),
              best: -1, bestScore: -1, where: -1, bonus: 0, teaches: false, taughtHere: false};
    });
    var phrase = words.join(" ");
    // The whole query as a phrase, each word with its endings ("frames in flight"
    // for "frame in flight"): what a heading or a recap entry must hold for the
    // "taught here" mark.
    var taughtPhrase = new RegExp("(?:^|[^a-z0-9])" + words.map(function (w) {
      var root = w.length > 4 ? w.replace(/(?:ies|y)$/, "") : w;  // "family" and "families"
      return root.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
    }).join("[a-z0-9]*[\\s\\-]+") + "[a-z0-9]*");
    lowered.forEach(function (fields, s) {
      var p = pages[index.sections[s][0]], score = 0, where = -1;
      words.forEach(function (w, k) {
        var weight = weigh(fields, originals[s], w);
        p.hits[k] += weight.count;
        score += weight.score;
        if (weight.where === HEADING || weight.where === RECAP) p.taught[k] = true;
        if (weight.where !== -1 && (where === -1 || weight.where > where)) where = weight.where;
      });
      if (words.length > 1 && (fields[HEADING].indexOf(phrase) !== -1 || fields[RECAP].indexOf(phrase) !== -1)) {
        score += 6;
      }
      if (score > p.bestScore) { p.bestScore = score; p.best = s; p.where = where; }
    });
    var found = pages.filter(function (p) { return p.hits.every(function (n) { return n > 0; }); });
    // The book teaches in order: the first chapter with a word in a heading or
    // its recap is where it is introduced; a page whose title holds it is about it.
    words.forEach(function (w, k) {
      var first = null;
      found.forEach(function (p) {
        if (index.pages[p.page][2] === "chapter" && p.taught[k] && (!first || p.page < first.page)) first = p;
      });
      if (first) first.bonus += 4;
    });
    found.forEach(function (p) {
      var breadth = 0, title = index.pages[p.page][1].toLowerCase();
      p.hits.forEach(function (n) { breadth += 0.3 * Math.log(1 + n); });
      words.forEach(function (w) { if (title.indexOf(w) !== -1) p.bonus += 10; });
      p.score = (p.bestScore + breadth + p.bonus) * (KIND_WEIGHT[index.pages[p.page][2]] || 1);
    });
    // "Taught here" marks one page at most: the first chapter in reading order
    // whose best section holds the whole phrase in its heading or its recap entry.
    var teacher = null;
    found.forEach(function (p) {
      var best = lowered[p.best];
      p.teaches = taughtPhrase.test(best[HEADING]) || taughtPhrase.test(best[RECAP]);
      if (index.pages[p.page][2] === "chapter" && p.teaches && (!teacher || p.page < teacher.page)) teacher = p;
    });
    if (teacher) teacher.taughtHere = true;
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

  // The text a result shows: the section's prose where it holds a word, else its
  // recap entry, its code, its comments (the index keeps them without `//`).
  function snippetSource(s, words) {
    var section = index.sections[s], fields = lowered[s];
    var order = [PROSE, RECAP, CODE, COMMENTS];
    for (var i = 0; i < order.length; i++) {
      var f = order[i];
      if (words.some(function (w) { return fields[f].indexOf(w) !== -1; })) return section[2 + f];
    }
    return section[4] || section[3];
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
      if (r.taughtHere) {
        var taught = document.createElement("span");
        taught.className = "taught";
        taught.textContent = " taught here";
        item.appendChild(taught);
      }
      if (section[2] && section[2] !== page[1]) {
        var where = document.createElement("span");
        where.className = "where";
        where.textContent = section[2] + (LABELS[r.where] && r.where > PROSE ? " (" + LABELS[r.where] + ")" : "");
        item.appendChild(where);
      }
      item.appendChild(snippet(snippetSource(r.best, r.words), r.words));
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
