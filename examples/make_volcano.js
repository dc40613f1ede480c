#!/usr/bin/env node
// Derives volcano.csv and volcano.asc (Maunga Whau / Mt Eden, Auckland) from
// data/volcano.json of the npm package `vega-datasets`, which holds R's
// `volcano` matrix. See README.md for provenance.
//
// Usage: node make_volcano.js PATH/TO/vega-datasets/data/volcano.json OUT_DIR
//
// Orientation. R documents the 87 x 61 matrix as "rows corresponding to grid
// lines running east to west and columns to grid lines running south to
// north"; its persp() example labels the row index "10 meter spacing (S to
// N)" and the column index "(E to W)". vega-datasets stores it as
// width 87, height 61 with values[k * 87 + m] = volcano[m + 1, 61 - k]
// (checked: its last line is R's first column 100, 101, 102, ...).
// tsf rasters are north-up, west-to-east, so the output is 61 columns
// (west -> east) by 87 rows (north -> south):
//   raster(c, r) = volcano[87 - r, 61 - c] = values[c * 87 + (86 - r)].
// Cells are 10 m; the .asc uses local coordinates (metres) with the
// south-west corner at (0, 0).
'use strict';
const fs = require('fs');
const path = require('path');

const v = JSON.parse(fs.readFileSync(process.argv[2], 'utf8'));
const outDir = process.argv[3];
if (v.width !== 87 || v.height !== 61 || v.values.length !== 87 * 61) throw new Error('unexpected volcano.json layout');
const kCols = 61;
const kRows = 87;
const rows = [];
for (let r = 0; r < kRows; ++r) {
  const row = [];
  for (let c = 0; c < kCols; ++c) row.push(v.values[c * 87 + (86 - r)]);
  rows.push(row.join(','));
}
fs.writeFileSync(path.join(outDir, 'volcano.csv'), rows.join('\n') + '\n');
const asc = [
  'ncols        61',
  'nrows        87',
  'xllcorner    0',
  'yllcorner    0',
  'cellsize     10',
  'NODATA_value -9999',
  ...rows.map((line) => line.replace(/,/g, ' ')),
];
fs.writeFileSync(path.join(outDir, 'volcano.asc'), asc.join('\n') + '\n');
