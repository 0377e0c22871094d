#include "plugin_state.hpp"

#include <exception>

#include "tactus/io/preset.hpp"

namespace tactus::plugin {

std::string state_text(const Settings& settings) {
    return preset_text(settings, "tactus plugin state");
}

RestoredState restore_state(std::string_view text) noexcept {
    RestoredState restored;
    try {
        apply_preset_text(restored.settings, text, "plugin state");
    } catch (const std::exception& e) {
        restored.settings = Settings{};
        try {
            restored.error = e.what();
        } catch (...) {
            // out of memory for the message: the defaults still stand
        }
    } catch (...) {
        restored.settings = Settings{};
        restored.error = "plugin state: unreadable";  // short: fits the string's own buffer
    }
    return restored;
}

}  // namespace tactus::plugin
