// Typesets equations with KaTeX at build time, so a chapter page needs only KaTeX's
// style sheet and fonts, and shows its equations with scripts turned off.
//
//   node render_katex.js KATEX_DIR < [{"tex": "a_i", "display": false}, ...]
//
// Prints one result per equation, in order: {"html": ...} or {"error": ...}. An error
// is returned, not thrown, so that make_book.py can name the chapter it came from.
"use strict";
const katex = require(require("path").resolve(process.argv[2], "katex.js"));

let input = "";
process.stdin.setEncoding("utf8");
process.stdin.on("data", (chunk) => { input += chunk; });
process.stdin.on("end", () => {
  const results = JSON.parse(input).map(({ tex, display }) => {
    try {
      return { html: katex.renderToString(tex, { displayMode: display, throwOnError: true, output: "htmlAndMathml" }) };
    } catch (e) {
      return { error: e.message };
    }
  });
  process.stdout.write(JSON.stringify(results));
});
