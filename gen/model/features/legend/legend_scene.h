// The braille legend on the model: where it goes (placeLegend, called by
// the registry in FeaturePhase::BeforeMarks: legend_feature.h). The plate's
// outline beside the pillars is gen/model/features/legend/legend_plate.h;
// its solid, gen/model/features/legend/legend_join.h.
//
// Placement (decided once, stored in Scene::features): the legend stands on a
// plate grown NORTH of the pillars, away from the orientation notch at the
// south-west corner and clear of every pillar top. The plate's box spans the
// grid box's width (x from 0 to gridWidth, further under a wider legend),
// its top is the floor (the base's top, so it reads as "not data"). It
// reaches south over the cells culled at the model's northern corners, to
// the northmost row at which it stands against pillars rising to its top
// along 60 % of its width (at most to the first row whose kept cells span
// 60 % of the columns; else the row it holds on along most), so it holds on
// along most of its length, not by a corner (tsf verify --tactile checks
// the joint). A flat model's plate stands around a no-data pit in the rows
// it covers (the pit stays a pit: its walls above its top are the plate's
// sides); a mirrored model's never reaches over a whole row with a pit.
// Its south edge runs along the line through the upper side corners of that
// row, which meets hexagon walls only at their corners. The plate is the box
// less the kept hexagons: pillars keep their tops and walls above the floor.
// On a model of few rows the south edge moves north of any row whose walls
// the orientation notch cuts in the data. The braille starts north of the
// hexagons' tips: the title on the first line, the value range of the data
// with its units on the next, lines broken to fit the model's width.
//
// A mirrored model has no floor: there the plate lies in the z band every
// pillar it stands against holds (as the orientation tab does), as thick as
// the base (at least kMinMirroredPlateMm) in the band's middle, its dots on
// its top; the south edge moves north until the pillars share such a band.
//
// Limits (InputError saying what to change): a model cut into halves, a word
// wider than the model, a plate that would stand against the notch even at
// the first row, or (mirrored) no band thick enough even there.
#pragma once

namespace tsf {

/// Thinnest legend plate on a mirrored model, mm (eight 0.2 mm layers).
inline constexpr double kMinMirroredPlateMm = 1.6;

struct Scene;

/// Places the legend when params.words has a title or units (none else).
void placeLegend(Scene& scene);

}  // namespace tsf
