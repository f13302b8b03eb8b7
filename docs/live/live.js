// A lesson's live page (OUT/NN_name/live.html, made by make_live.py): the lesson's
// own program, compiled to WebAssembly, run in a Web Worker (live_worker.js) from a
// form built from the lesson's option table (--options-json). The form's values go to
// the program as a command line; the program checks them, as it checks a terminal's,
// and its one-line error is shown as it is (the form is `novalidate`: the browser's
// own range checks would speak in the program's place; min and max only bound the
// number fields' arrows). What the program prints and writes appears
// as it comes: lines, pictures, charts, tables.
//
// The page reads `?name=value` from its address into the form (`?run` also starts the
// run), so a link can open a lesson with settings of its own. The state of the last
// run is kept in window.giLive for the browser test.
/* global giLiveWorker, giLessonSource, giLiveFiles, GI_LIVE */
(function () {
  'use strict';
  // Options that belong to the program's host, not to the form: the page's file system
  // is in memory and its program runs on one thread.
  const HIDDEN = new Set(['--out', '--threads', '--mesh-folder']);

  const $ = (id) => document.getElementById(id);
  const state = window.giLive = {options: null, status: null, seconds: null, files: {}, lines: [], running: false};
  let worker = null, timer = null, fields = [];

  function element(tag, attributes, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attributes || {})) {
      if (k === 'class') e.className = v;
      else if (k === 'text') e.textContent = v;
      else e.setAttribute(k, v);
    }
    for (const c of children) e.append(c);
    return e;
  }

  function startWorker() {
    const source = giLessonSource + '\n(' + giLiveWorker.toString() + ')();\n';
    worker = new Worker(URL.createObjectURL(new Blob([source], {type: 'text/javascript'})));
    worker.onmessage = (event) => receive(event.data);
    worker.onerror = (event) => {
      say('The program could not be started in this browser: ' + (event.message || 'unknown error'), true);
      finish(1, null);
    };
  }

  // ---- the form, from the option table ----

  function field(option) {
    const id = 'option' + option.name;
    const label = element('label', {for: id}, element('code', {text: option.name}));
    let input;
    if (option.kind === 'flag') {
      input = element('input', {type: 'checkbox', id});
    } else if (option.kind === 'choice') {
      input = element('select', {id});
      for (const c of option.choices) input.append(element('option', {value: c, text: c}));
      input.value = option.default;
    } else if (option.kind === 'integer' || option.kind === 'real' || option.kind === 'optional') {
      input = element('input', {type: 'number', id, min: option.min, max: option.max,
                                step: option.kind === 'real' ? 'any' : (option.rule === 'even' ? 2 : 1)});
      if (option.kind !== 'optional') input.value = option.default;
      else input.placeholder = 'unset';
    } else {
      input = element('input', {type: 'text', id, spellcheck: 'false'});
      input.value = option.default;
      if (option.shape) input.placeholder = option.shape;
    }
    let range = '';
    if (option.min !== null && option.kind !== 'unsigned') range = `[${option.min}, ${option.max}]`;
    if (option.rule) range += (range ? ', ' : '') + option.rule;
    if (option.shape) range = 'written ' + option.shape;
    const help = element('span', {class: 'help', text: option.help + (range ? ' — ' + range : '')});
    return {option, input, row: element('div', {class: 'field'}, label, input, help)};
  }

  function value(f) {
    return f.option.kind === 'flag' ? (f.input.checked ? 'on' : '') : f.input.value;
  }

  function defaultValue(f) {
    return f.option.kind === 'flag' || f.option.kind === 'optional' ? '' : f.option.default;
  }

  // The command line: only what differs from the defaults, so that the untouched form
  // is the lesson run with no options, as on a terminal.
  function commandLine() {
    const args = [];
    for (const f of fields) {
      const v = value(f);
      if (v === defaultValue(f)) continue;
      if (f.option.kind === 'flag') args.push(f.option.name);
      else args.push(f.option.name + '=' + v);
    }
    return args;
  }

  function showCommand() {
    $('command').textContent = [GI_LIVE.lesson, ...commandLine()].join(' ');
  }

  function buildForm(table) {
    state.options = table;
    $('summary').textContent = table.summary;
    const form = $('fields');
    form.textContent = '';
    fields = table.options.filter((o) => !HIDDEN.has(o.name)).map(field);
    for (const f of fields) {
      form.append(f.row);
      f.input.addEventListener('input', showCommand);
      f.input.addEventListener('change', showCommand);
    }
    // Settings from the address: ?width=64&run
    const query = new URLSearchParams(location.search);
    for (const f of fields) {
      const given = query.get(f.option.name.replace(/^--/, ''));
      if (given === null) continue;
      if (f.option.kind === 'flag') f.input.checked = given !== '0' && given !== 'false';
      else f.input.value = given;
    }
    showCommand();
    $('run').disabled = false;
    $('defaults').disabled = false;
    if (query.has('run')) run();
  }

  // ---- a run ----

  function say(text, failed) {
    const status = $('status');
    status.textContent = text;
    status.classList.toggle('failed', !!failed);
  }

  function run() {
    if (state.running) return;
    state.running = true;
    state.status = null;
    for (const f of Object.values(state.files)) URL.revokeObjectURL(f.url);  // the last run's pictures
    state.files = {};
    state.lines = [];
    for (const a of $('pages').querySelectorAll('a')) URL.revokeObjectURL(a.href);
    for (const id of ['outputs', 'tables', 'files', 'log', 'pages']) $(id).textContent = '';
    $('run').disabled = true;
    $('stop').disabled = false;
    $('progress').value = 0;
    $('progress-label').textContent = '';
    const started = performance.now();
    timer = setInterval(() => say(`running: ${((performance.now() - started) / 1000).toFixed(1)} s`), 200);
    worker.postMessage({type: 'run', args: commandLine(), files: typeof giLiveFiles === 'undefined' ? [] : giLiveFiles});
  }

  function finish(status, seconds) {
    clearInterval(timer);
    state.running = false;
    state.status = status;
    state.seconds = seconds;
    $('run').disabled = false;
    $('stop').disabled = true;
    const time = seconds === null ? '' : ` in ${seconds.toFixed(1)} s`;
    if (status === 0) {
      $('progress').value = 100;
      say(`done${time}: status 0, ${Object.keys(state.files).length} files written`);
    } else {
      // The program's own last word on stderr says why: "--width must be in [16, 4096], got 5".
      const errors = state.lines.filter((l) => l.stream === 'stderr');
      const last = errors.length ? ': ' + errors[errors.length - 1].text : '';
      const why = {1: 'failed while running', 2: 'refused', 3: 'stopped at an exercise not done yet'}[status] || 'ended';
      say(`${why}${time}, status ${status}${last}`, true);
    }
    offerPages();
  }

  // ---- the pages a run writes: its report page and, for lessons 08-13, its viewer ----

  // A page the run wrote, made whole: each script and style sheet it names from the
  // run (viewer_data.js, viewer.css) put inside it, and each picture or file it links
  // as a data: address. It is then opened from memory as a blob: a page in memory has
  // no folder for relative names to be found in, and may not load another blob. A
  // name outside the run's files (the chapter, another page) is left as it is.
  function base64Of(bytes) {
    let text = '';
    for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    return btoa(text);
  }

  function pageUrl(path) {
    const folder = path.slice(0, path.lastIndexOf('/') + 1);
    const file = (name) => state.files[folder + name];
    const text = (f) => new TextDecoder().decode(f.bytes);
    let page = text(state.files[path]);
    page = page.replace(/<script src="([^"#?:]+)"><\/script>/g, (whole, name) =>
      file(name) ? '<script>' + text(file(name)).replace(/<\/script/gi, '<\\/script') + '</script>' : whole);
    page = page.replace(/<link rel="stylesheet" href="([^"#?:]+)">/g, (whole, name) =>
      file(name) ? '<style>' + text(file(name)) + '</style>' : whole);
    page = page.replace(/\b(src|href)="([^"#?:]+)"/g, (whole, attribute, name) => {
      const f = file(name);
      if (!f || name.endsWith('.html')) return whole;
      const type = TYPES[name.split('.').pop()] || 'application/octet-stream';
      return `${attribute}="data:${type};base64,${base64Of(f.bytes)}"`;
    });
    return URL.createObjectURL(new Blob([page], {type: 'text/html'}));
  }

  function offerPages() {
    const links = $('pages');
    for (const a of links.querySelectorAll('a')) URL.revokeObjectURL(a.href);  // the last run's pages
    links.textContent = '';
    const folder = 'out/' + GI_LIVE.lesson + '/';
    const offers = [['viewer.html', 'Open the interactive viewer', 'viewer-link'],
                    ['index.html', 'Open the report page of this run', '']];
    for (const [name, text, kind] of offers) {
      if (!state.files[folder + name]) continue;
      links.append(element('a', {href: pageUrl(folder + name), target: '_blank', class: kind, text}), ' ');
    }
  }

  function stop() {
    if (!state.running) return;
    worker.terminate();
    clearInterval(timer);
    state.running = false;
    state.status = 'stopped';
    $('run').disabled = false;
    $('stop').disabled = true;
    say('stopped: the run was ended before it finished; the outputs below are what it had written', true);
    offerPages();
    startWorker();
  }

  function receive(message) {
    if (message.type === 'options') {
      if (message.status !== 0 || !message.json) {
        say('The program did not describe its options: ' + (message.error || 'status ' + message.status), true);
        return;
      }
      buildForm(JSON.parse(message.json));
      say('ready');
    } else if (message.type === 'line') {
      state.lines.push(message);
      const line = element('span', {class: message.stream, text: message.text + '\n'});
      $('log').append(line);
    } else if (message.type === 'progress') {
      $('progress').value = message.percent;
      $('progress-label').textContent = message.percent >= 100 ? '' : message.label;
    } else if (message.type === 'file') {
      show(message.path, message.bytes);
    } else if (message.type === 'exit') {
      finish(message.status, message.seconds);
    }
  }

  // ---- outputs, as they are written ----

  const TYPES = {png: 'image/png', svg: 'image/svg+xml', csv: 'text/csv', json: 'application/json',
                 html: 'text/html', txt: 'text/plain', pfm: 'application/octet-stream'};

  function csvRows(text) {
    // A table the lessons write: cells with a comma or a quote are quoted (table.cpp).
    const rows = [];
    for (const line of text.split('\n')) {
      if (!line) continue;
      const cells = [];
      let cell = '', quoted = false;
      for (let i = 0; i < line.length; ++i) {
        const c = line[i];
        if (quoted) {
          if (c === '"' && line[i + 1] === '"') { cell += '"'; ++i; } else if (c === '"') quoted = false; else cell += c;
        } else if (c === '"') quoted = true;
        else if (c === ',') { cells.push(cell); cell = ''; } else cell += c;
      }
      cells.push(cell);
      rows.push(cells);
    }
    return rows;
  }

  function tableOf(text, name) {
    const rows = csvRows(text);
    const table = element('table', {}, element('caption', {text: name}));
    if (!rows.length) return table;
    const head = element('tr');
    for (const h of rows[0]) head.append(element('th', {text: h}));
    table.append(element('thead', {}, head));
    const body = element('tbody');
    for (const r of rows.slice(1)) {
      const tr = element('tr');
      for (const c of r) tr.append(element('td', {text: c, class: isFinite(Number(c)) && c !== '' ? 'number' : ''}));
      body.append(tr);
    }
    table.append(body);
    return element('div', {class: 'table'}, table);
  }

  // A picture is shown at a whole multiple of its size, at least 320 pixels wide where
  // that fits, as on the lesson's report page (report_page.cpp, shown_width).
  function shownWidth(width) {
    if (width <= 0) return 0;
    return width * Math.max(1, Math.min(Math.floor(1100 / width), Math.ceil(320 / width)));
  }

  function show(path, bytes) {
    const extension = path.split('.').pop();
    const blob = new Blob([bytes], {type: TYPES[extension] || 'application/octet-stream'});
    const url = URL.createObjectURL(blob);
    const old = state.files[path];
    if (old) URL.revokeObjectURL(old.url);
    state.files[path] = {url, size: bytes.length, bytes};
    const id = 'file-' + path.replace(/[^A-Za-z0-9_-]/g, '_');
    let item;
    const link = element('a', {href: url, download: path.split('/').pop(), class: 'file', text: path});
    if (extension === 'png' || extension === 'svg') {
      const img = element('img', {src: url, alt: path});
      if (extension === 'png') img.addEventListener('load', () => { img.style.width = shownWidth(img.naturalWidth) + 'px'; });
      item = element('figure', {id, class: extension === 'svg' ? 'chart' : ''}, img, element('figcaption', {}, link));
    } else if (extension === 'csv') {
      // The printed log shows each table as the lesson formats it; here is its CSV.
      item = element('details', {id}, element('summary', {}, 'table ', link), tableOf(new TextDecoder().decode(bytes), path));
    } else {
      item = element('li', {id}, link, ` (${bytes.length} bytes)`);
    }
    const existing = document.getElementById(id);
    if (existing) existing.replaceWith(item);
    else $(extension === 'csv' ? 'tables' : (item.tagName === 'LI' ? 'files' : 'outputs')).append(item);
  }

  document.addEventListener('DOMContentLoaded', () => {
    $('run').addEventListener('click', run);
    $('stop').addEventListener('click', stop);
    $('defaults').addEventListener('click', () => {
      for (const f of fields) {
        if (f.option.kind === 'flag') f.input.checked = false;
        else f.input.value = defaultValue(f);
      }
      showCommand();
    });
    $('form').addEventListener('submit', (event) => { event.preventDefault(); run(); });
    say('loading the program…');
    startWorker();
    worker.postMessage({type: 'options'});
  });
})();
