#include "live_control.hpp"

#include <fmt/format.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "tactus/io/actuator_file.hpp"
#include "tactus/io/layout_file.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::live {
namespace {

// How long a change waits for room in the engine's queue before it is given up.
constexpr auto kQueueWait = std::chrono::seconds(2);
constexpr auto kQueuePoll = std::chrono::milliseconds(1);

}  // namespace

LiveControl::LiveControl(Engine& engine, std::vector<std::string> assignments,
                         Layout::ProfileLoader load_profile)
    : engine_(engine),
      assignments_(std::move(assignments)),
      load_profile_(load_profile ? std::move(load_profile) : [](const std::string& name) {
          return load_actuator(resolve_actuator(name));
      }) {}

// Engine::set and friends throw std::runtime_error only when the queue to the audio thread is
// full (validation errors are std::invalid_argument): wait for the audio thread to take some.
template <typename F>
void LiveControl::retry_while_full(F&& change) {
    const auto give_up = std::chrono::steady_clock::now() + kQueueWait;
    for (;;) {
        try {
            change();
            return;
        } catch (const std::invalid_argument&) {
            throw;
        } catch (const std::runtime_error&) {
            if (std::chrono::steady_clock::now() > give_up) throw;
            std::this_thread::sleep_for(kQueuePoll);
        }
    }
}

void LiveControl::set(P id, double value) {
    retry_while_full([&] { engine_.set(id, value); });
}

void LiveControl::load_preset_file(const std::filesystem::path& path) {
    Settings next;
    apply_preset_file(next, path);  // everything validated before anything applies
    for (const auto& a : assignments_) apply_assignment(next, a);
    retry_while_full([&] { engine_.set(next); });
}

void LiveControl::load_preset(const std::string& name_or_path) {
    load_preset_file(resolve_preset(name_or_path));
}

void LiveControl::load_layout(const std::string& name_or_path) {
    const Layout layout = tactus::load_layout(resolve_layout(name_or_path));
    if (static_cast<int>(layout.outputs.size()) != engine_.actuators())
        throw std::invalid_argument(fmt::format("layout {} has {} output(s); {} actuator(s) play",
                                                layout.name, layout.outputs.size(),
                                                engine_.actuators()));
    const std::vector<ActuatorOutput> outputs = layout.actuator_outputs(load_profile_);
    retry_while_full([&] { engine_.set_outputs(outputs); });
}

void LiveControl::run(const OscCommand& command) {
    if (const auto* c = std::get_if<SetParameter>(&command)) return set(c->id, c->value);
    if (std::holds_alternative<QueryParameter>(command)) return;  // answered by the server
    if (const auto* c = std::get_if<LoadPreset>(&command)) return load_preset(c->name);
    if (const auto* c = std::get_if<ActuatorGain>(&command))
        return retry_while_full([&] { engine_.set_actuator_gain_db(c->actuator, c->gain_db); });
    if (const auto* c = std::get_if<ActuatorRoute>(&command))
        return retry_while_full([&] { engine_.set_route(c->actuator, c->route); });
    if (const auto* c = std::get_if<LoadLayout>(&command)) return load_layout(c->name);
    const auto& t = std::get<TriggerPulse>(command);
    double frequency_hz = t.frequency_hz, amplitude = t.amplitude;
    if (!t.with_values) {
        const Settings now = settings();
        frequency_hz = now[P::frequency_out_max];
        amplitude = now[P::amplitude_out_max];
    }
    retry_while_full([&] { engine_.trigger(frequency_hz, amplitude); });
}

}  // namespace tactus::live
