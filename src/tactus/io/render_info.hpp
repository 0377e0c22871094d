// How an output was made (input, preset, the settings changed from it, actuator, tactus
// version), as every output carries it: a WAV's INFO chunk (ISFT, ICMT), a CSV's header comment,
// a JSON field, a haptic file's metadata. `meter` reads the actuator back from a rendered file.
#pragma once

#include <string>
#include <vector>

namespace tactus {

struct RenderInfo {
    std::string source;                // the input file's name
    std::string preset;                // name or path
    std::vector<std::string> changes;  // key=value settings changed from the preset
    std::string actuator;              // profile name, empty for none
    std::string version;               // tactus version
    std::string layout{};              // layout name or path, empty for none

    // One line for people: "tactus 0.1.0 from amen.flac: preset tfd --set k=v, actuator lra-175".
    std::string describe() const;
    // One line for programs: "tactus=0.1.0; source=amen.flac; preset=tfd; set=k=v k=v;
    // actuator=lra-175; layout=controller" (fields without a value left out).
    std::string comment() const;
    // Reads comment()'s form back; fields it does not find stay empty.
    static RenderInfo from_comment(const std::string& text);
};

}  // namespace tactus
