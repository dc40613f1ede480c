#include "gen/mesh_io/three_mf_volumes.h"

#include <cstdlib>

namespace tsf::mesh_io {
namespace {

std::string xmlEscape(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string xmlUnescape(std::string_view text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '&') {
            out += text[i];
            continue;
        }
        static const std::pair<std::string_view, char> kEntities[] = {
            {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
        bool done = false;
        for (const auto& [entity, c] : kEntities)
            if (text.substr(i, entity.size()) == entity) {
                out += c;
                i += entity.size() - 1;
                done = true;
                break;
            }
        if (!done) out += '&';
    }
    return out;
}

// The value of attribute name="..." inside the tag text; "" when absent.
std::string attribute(std::string_view tag, std::string_view name) {
    const std::string key = " " + std::string(name) + "=\"";
    const size_t at = tag.find(key);
    if (at == std::string_view::npos) return "";
    const size_t from = at + key.size(), to = tag.find('"', from);
    if (to == std::string_view::npos) return "";
    return xmlUnescape(tag.substr(from, to - from));
}

}  // namespace

std::string slicerModelConfig(unsigned object_id, const std::string& object_name, const std::vector<ThreeMfVolume>& volumes) {
    std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<config>\n";
    o += " <object id=\"" + std::to_string(object_id) + "\" instances_count=\"1\">\n";
    o += "  <metadata type=\"object\" key=\"name\" value=\"" + xmlEscape(object_name) + "\"/>\n";
    for (const ThreeMfVolume& v : volumes) {
        o += "  <volume firstid=\"" + std::to_string(v.first_triangle) + "\" lastid=\"" + std::to_string(v.last_triangle) +
             "\">\n";
        o += "   <metadata type=\"volume\" key=\"name\" value=\"" + xmlEscape(v.name) + "\"/>\n";
        o += "   <metadata type=\"volume\" key=\"volume_type\" value=\"ModelPart\"/>\n";
        o += "  </volume>\n";
    }
    o += " </object>\n</config>\n";
    return o;
}

std::map<unsigned, std::vector<ThreeMfVolume>> parseSlicerModelConfig(std::string_view xml) {
    std::map<unsigned, std::vector<ThreeMfVolume>> out;
    std::vector<ThreeMfVolume>* object = nullptr;
    ThreeMfVolume* volume = nullptr;
    for (size_t at = xml.find('<'); at != std::string_view::npos; at = xml.find('<', at + 1)) {
        const size_t end = xml.find('>', at);
        if (end == std::string_view::npos) break;
        const std::string_view tag = xml.substr(at, end - at);
        if (tag.rfind("<object ", 0) == 0) {
            object = &out[unsigned(std::strtoul(attribute(tag, "id").c_str(), nullptr, 10))];
            volume = nullptr;
        } else if (tag.rfind("<volume ", 0) == 0 && object) {
            const std::string first = attribute(tag, "firstid"), last = attribute(tag, "lastid");
            if (first.empty() || last.empty()) continue;
            object->push_back({"", size_t(std::strtoull(first.c_str(), nullptr, 10)),
                               size_t(std::strtoull(last.c_str(), nullptr, 10))});
            volume = &object->back();
        } else if (tag.rfind("</volume", 0) == 0) {
            volume = nullptr;
        } else if (tag.rfind("<metadata ", 0) == 0 && volume && attribute(tag, "type") == "volume" &&
                   attribute(tag, "key") == "name") {
            volume->name = attribute(tag, "value");
        }
    }
    return out;
}

}  // namespace tsf::mesh_io
