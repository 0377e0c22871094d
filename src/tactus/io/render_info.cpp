#include "tactus/io/render_info.hpp"

#include <fmt/format.h>

#include <sstream>

namespace tactus {

std::string RenderInfo::describe() const {
    std::string text = fmt::format("tactus {} from {}: preset {}", version, source, preset);
    for (const auto& c : changes) text += " --set " + c;
    text += actuator.empty() ? ", no actuator profile" : ", actuator " + actuator;
    if (!layout.empty()) text += ", layout " + layout;
    return text;
}

std::string RenderInfo::comment() const {
    std::string text = "tactus=" + version;
    if (!source.empty()) text += "; source=" + source;
    if (!preset.empty()) text += "; preset=" + preset;
    if (!changes.empty()) {
        text += "; set=";
        for (size_t i = 0; i < changes.size(); ++i) text += (i ? " " : "") + changes[i];
    }
    if (!actuator.empty()) text += "; actuator=" + actuator;
    if (!layout.empty()) text += "; layout=" + layout;
    return text;
}

RenderInfo RenderInfo::from_comment(const std::string& text) {
    RenderInfo info;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find("; ", start);
        if (end == std::string::npos) end = text.size();
        const std::string field = text.substr(start, end - start);
        start = end + 2;
        const size_t equals = field.find('=');
        if (equals == std::string::npos) continue;
        const std::string key = field.substr(0, equals), value = field.substr(equals + 1);
        if (key == "tactus")
            info.version = value;
        else if (key == "source")
            info.source = value;
        else if (key == "preset")
            info.preset = value;
        else if (key == "actuator")
            info.actuator = value;
        else if (key == "layout")
            info.layout = value;
        else if (key == "set") {
            std::istringstream words(value);
            for (std::string w; words >> w;) info.changes.push_back(w);
        }
    }
    return info;
}

}  // namespace tactus
