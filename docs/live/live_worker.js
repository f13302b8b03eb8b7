// The Web Worker that runs a lesson for its page (live.js). A page opened from file://
// may not start a worker from a file, so the page builds this one from text: the
// lesson's own program (gi_lesson, from live_lesson.js) followed by this function,
// called. Nothing here runs on the page's own thread.
//
// The page asks, the worker answers:
//   {type: 'options'}             -> {type: 'options', json}     the lesson's --options-json
//   {type: 'run', args, files}    -> {type: 'line', stream, text}  each line printed
//                                    {type: 'progress', label, percent}
//                                    {type: 'file', path, bytes}   each output, as it is written
//                                    {type: 'exit', status, seconds}
// One run at a time. Stop is the page ending this worker and starting another: a
// lesson in the middle of main cannot be asked to return.
/* global gi_lesson */
function giLiveWorker() {
  'use strict';
  const OUT = '/out';  // where a lesson's default --out (out/NN_name) lands: the working folder is /

  // Every file under `folder`: path -> the file system's node.
  function filesUnder(FS, folder, found) {
    if (!FS.analyzePath(folder).exists) return found;
    for (const name of FS.readdir(folder)) {
      if (name === '.' || name === '..') continue;
      const path = folder + '/' + name;
      const stat = FS.stat(path);
      if (FS.isDir(stat.mode)) filesUnder(FS, path, found);
      // A file being written whole goes by a hidden name (".x.png.1.0.partial") and
      // is renamed into place when complete (gi/core/atomic_file.cpp): only the
      // complete ones are shown.
      else if (!name.startsWith('.')) found.set(path, stat.mtime.getTime() + ':' + stat.size);
    }
    return found;
  }

  // Sends the files that are new or changed since the last look.
  function sendNewFiles(FS, seen) {
    for (const [path, version] of filesUnder(FS, OUT, new Map())) {
      if (seen.get(path) === version) continue;
      seen.set(path, version);
      const bytes = FS.readFile(path);  // a copy: the page may keep it
      postMessage({type: 'file', path: path.slice(1), bytes}, [bytes.buffer]);  // out/NN_name/...
    }
  }

  // Writes the data files a lesson reads (the stored reference pictures) where the
  // native program finds them.
  function writeFiles(FS, files) {
    for (const {path, base64} of files) {
      const parts = path.split('/').filter(Boolean);
      let folder = '';
      for (const part of parts.slice(0, -1)) {
        folder += '/' + part;
        if (!FS.analyzePath(folder).exists) FS.mkdir(folder);
      }
      const text = atob(base64);
      const bytes = new Uint8Array(text.length);
      for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
      FS.writeFile(path, bytes);
    }
  }

  function options() {
    const lines = [];
    let status = null;
    gi_lesson({
      arguments: ['--options-json'],
      print: (text) => lines.push(text),
      printErr: () => {},
      onExit: (code) => { status = code; },
    }).then(() => {
      postMessage({type: 'options', json: lines.join('\n'), status: status === null ? 0 : status});
    }, (error) => postMessage({type: 'options', json: '', status: 1, error: String(error)}));
  }

  function run(args, files) {
    const seen = new Map();
    const started = performance.now();
    let module = null, ended = false;
    const end = (status) => {
      if (ended) return;
      ended = true;
      if (module) sendNewFiles(module.FS, seen);
      postMessage({type: 'exit', status, seconds: (performance.now() - started) / 1000});
    };
    const line = (stream) => (text) => {
      postMessage({type: 'line', stream, text});
      // A lesson says so when it has written something: that is the moment to look.
      if (module && stream === 'stdout') sendNewFiles(module.FS, seen);
    };
    gi_lesson({
      arguments: args,
      thisProgram: 'lesson',
      preRun: [(m) => { module = m; writeFiles(m.FS, files); }],
      print: line('stdout'),
      printErr: line('stderr'),
      onProgress: (label, percent) => postMessage({type: 'progress', label, percent}),
      onExit: end,
      onAbort: (what) => {
        postMessage({type: 'line', stream: 'stderr', text: 'the program stopped: ' + what});
        end(1);
      },
    }).then(() => end(0), (error) => {
      // Emscripten ends a run that called exit() by throwing; onExit has its status.
      if (!ended) {
        postMessage({type: 'line', stream: 'stderr', text: String(error && error.message ? error.message : error)});
        end(1);
      }
    });
  }

  onmessage = (event) => {
    const message = event.data;
    if (message.type === 'options') options();
    else if (message.type === 'run') run(message.args, message.files || []);
  };
}
