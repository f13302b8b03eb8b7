#!/usr/bin/env node
// Runs one lesson built as WebAssembly under Node.js, as its native twin runs:
//
//   node docs/live/node_run.js build/wasm/bin/01_rays.js --out /tmp/out/01_rays
//
// The lesson's file defines gi_lesson(settings) (cmake/toolchains/emscripten.cmake),
// which starts one run. Its file system is Emscripten's in-memory one; before main,
// each folder at the top of this machine's file system is mounted at its own name
// (NODEFS), and the working folder is this process's, so that every path the lesson
// is given or builds in (--out, --scene, GI_SOURCE_DIR/lessons/references) means
// what it means to a native program. main's exit status becomes this process's.
'use strict';
const fs = require('fs');
const path = require('path');

const [lessonFile, ...args] = process.argv.slice(2);
if (!lessonFile) {
  process.stderr.write('usage: node node_run.js LESSON.js [the lesson\'s options]\n');
  process.exit(2);
}

// Every top-level folder but the kernel's own (/dev, /proc, /sys: Emscripten keeps
// its own /dev and /proc, and a lesson reads neither).
function mountHostFolders(FS) {
  const NODEFS = FS.filesystems.NODEFS;
  for (const name of fs.readdirSync('/')) {
    if (['dev', 'proc', 'sys'].includes(name)) continue;
    let isFolder = false;
    try {
      isFolder = fs.statSync('/' + name).isDirectory();
    } catch (e) {
      continue;  // a dangling link or a folder this user may not look into
    }
    if (!isFolder) continue;
    const at = '/' + name;
    if (!FS.analyzePath(at).exists) FS.mkdir(at);
    FS.mount(NODEFS, {root: at}, at);
  }
  FS.chdir(process.cwd());
}

// The progress bar, drawn as the native program draws it: on a terminal only
// (lib/gi/report/progress.cpp hands the host each redraw).
function drawProgress(label, percent) {
  const width = 30, filled = Math.floor(width * percent / 100);
  const bar = percent >= 100 ? ' '.repeat(label.length + 40) : `${label} [${'#'.repeat(filled)}${' '.repeat(width - filled)}] ${String(percent).padStart(3)}%`;
  process.stderr.write('\r' + bar + (percent >= 100 ? '\r' : ''));
}

// A missing file or one that is not a lesson built by the wasm preset: one line, status 2.
let gi_lesson = null;
try {
  gi_lesson = require(path.resolve(lessonFile));
} catch (error) {
  process.stderr.write(`node_run.js: cannot load ${lessonFile}: ${String(error.message).split('\n')[0]}\n`);
  process.exit(2);
}
if (typeof gi_lesson !== 'function') {
  process.stderr.write(`node_run.js: ${lessonFile} is not a lesson built by the wasm preset (it defines no gi_lesson)\n`);
  process.exit(2);
}
gi_lesson({
  arguments: args,
  thisProgram: path.basename(lessonFile, '.js'),
  preRun: [(module) => mountHostFolders(module.FS)],
  print: (line) => process.stdout.write(line + '\n'),
  printErr: (line) => process.stderr.write(line + '\n'),
  onProgress: process.stderr.isTTY ? drawProgress : undefined,
}).catch((error) => {
  // Emscripten ends the process itself when main returns (EXIT_RUNTIME); only a
  // failure to load the module reaches here.
  process.stderr.write(`${lessonFile}: ${error && error.message ? error.message : error}\n`);
  process.exit(1);
});
