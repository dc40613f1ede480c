#include "gen/scad/scad_attachments.h"

#include "gen/model/feature_registry.h"
#include "gen/scad/scad_halves.h"
#include "gen/scad/scad_joined.h"

namespace tsf {
namespace {

// A registry feature's piece (gen/model/feature.h: ScadPiece) as the file
// carries it: joined into the terrain polyhedron when it can be, else for
// the feature's own module.
std::optional<ScadAttachment> scadPiece(const Scene& s, const Feature& f, bool join) {
    if (!f.scad_piece) return std::nullopt;
    std::optional<ScadPiece> piece = f.scad_piece(s);
    if (!piece) return std::nullopt;
    ScadAttachment a;
    a.placed_switch = piece->show_switch;
    const std::optional<Attachment> joined =
        join && f.attachment ? f.attachment(s, Assembly::OnePiece) : std::nullopt;
    a.data = std::move(piece->header);
    const bool own_assert = !piece->own_assert.empty();
    if (joined && scadCanJoin(s, *joined)) {
        a.library_file = "tsf_joined.scad";
        a.data += (piece->joined_lead.empty()
                       ? piece->header_end +
                             "\n// The walls it stands against and its body, joined into the pillars' polyhedron (tsf_joined.scad).\n"
                       : piece->joined_lead) +
                  piece->variable + " = " + scadJoinedData(s, *joined) + ";\n" +
                  (own_assert ? piece->own_assert : scadJoinedAssert(s, piece->show_switch, piece->what));
        a.joined = piece->show_switch + " ? " + piece->variable + " : []";
        return a;
    }
    a.library_file = std::move(piece->library_file);
    a.data += (piece->value_lead.empty() ? piece->header_end + "\n" : piece->value_lead) + piece->variable + " = " + piece->value +
              (own_assert ? ";\n" + piece->own_assert : ";\n\n");
    a.call_prefix = std::move(piece->module_call);
    return a;
}

}  // namespace

std::vector<ScadAttachment> scadAttachments(const Scene& scene, bool join) {
    // The features of the registry stand where they stood before it: the
    // legend, those beside the pillars, then the one carrying the marks.
    std::vector<std::optional<ScadAttachment>> pieces;
    for (const Feature* f : featuresMarksLast())
        pieces.push_back(scadPiece(scene, *f, join));
    pieces.push_back(scadHalves(scene));
    std::vector<ScadAttachment> out;
    for (std::optional<ScadAttachment>& a : pieces)
        if (a) out.push_back(std::move(*a));
    return out;
}

}  // namespace tsf
