#!/usr/bin/env node
// Writes three-bumps.pgm: a synthetic 120 x 80 height field with three smooth
// bumps of relative heights 1.0, 0.4 and 0.15 - the kind of field used in the
// thesis user study (one clear maximum, one smaller, one barely there).
//
// Usage: node make_three_bumps.js > three-bumps.pgm
//
// Format: binary PGM (P5), maxval 65535, so samples are 16-bit big-endian.
// Value at pixel centre (x + 0.5, y + 0.5), y down from the top row:
//   round(60000 * sum_k h_k * bump(|p - c_k| / r_k)),  bump(t) = (1 - t^2)^2 for t < 1, else 0
// bumps (cx, cy, r, h): (32, 28, 22, 1.0), (86, 30, 18, 0.4), (62, 62, 14, 0.15).
'use strict';
const kWidth = 120;
const kHeight = 80;
const kScale = 60000;
const kBumps = [
  {cx: 32, cy: 28, r: 22, h: 1.0},
  {cx: 86, cy: 30, r: 18, h: 0.4},
  {cx: 62, cy: 62, r: 14, h: 0.15},
];

const header = Buffer.from(`P5\n# three-bumps: synthetic field for tsf, see examples/README.md\n${kWidth} ${kHeight}\n65535\n`, 'ascii');
const data = Buffer.alloc(kWidth * kHeight * 2);
for (let y = 0; y < kHeight; ++y) {
  for (let x = 0; x < kWidth; ++x) {
    let v = 0;
    for (const b of kBumps) {
      const t = Math.hypot(x + 0.5 - b.cx, y + 0.5 - b.cy) / b.r;
      if (t < 1) v += b.h * (1 - t * t) * (1 - t * t);
    }
    data.writeUInt16BE(Math.round(kScale * v), 2 * (y * kWidth + x));
  }
}
process.stdout.write(Buffer.concat([header, data]));
