// libFuzzer target: any bytes as the plugin's saved state (apps/plugin/plugin_state.hpp), as a
// host hands them back. restore_state() never throws; it either takes the state (settings in
// their ranges, written back bit for bit by state_text()) or refuses it with a one-line message
// and gives the table's defaults exactly. Anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "fuzz_check.hpp"
#include "plugin_state.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const tactus::plugin::RestoredState restored = tactus::plugin::restore_state(text);
    if (!restored.error.empty()) {
        tactus::fuzz::check_message(restored.error.c_str());
        if (!tactus::fuzz::same_bits(restored.settings, tactus::Settings{})) std::abort();
        return 0;
    }
    tactus::fuzz::check_in_range(restored.settings);
    const tactus::plugin::RestoredState again =
        tactus::plugin::restore_state(tactus::plugin::state_text(restored.settings));
    if (!again.error.empty() || !tactus::fuzz::same_bits(again.settings, restored.settings))
        std::abort();
    return 0;
}
