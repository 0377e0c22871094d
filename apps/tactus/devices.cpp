// tactus devices: every audio backend of this build (RtAudio: ALSA, PulseAudio, JACK) with its
// devices, their channel counts and rates, as `tactus live --backend B --output DEV` names them.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iostream>

#include "commands.hpp"
#include "helper_commands.hpp"
#include "live/device_stream.hpp"

namespace tactus::cli {
namespace {

void list_devices() {
    for (const RtAudio::Api api : live::backends()) {
        std::cout << RtAudio::getApiName(api) << " (" << RtAudio::getApiDisplayName(api) << ")\n";
        try {
            RtAudio audio(api);
            audio.showWarnings(false);
            const std::vector<RtAudio::DeviceInfo> infos = live::probe_devices(audio);
            if (infos.empty())
                std::cout << (api == RtAudio::UNIX_JACK ? "  no devices (no JACK server running)\n"
                                                        : "  no devices\n");
            for (size_t i = 0; i < infos.size(); ++i) {
                const RtAudio::DeviceInfo& info = infos[i];
                if (!info.probed) continue;
                const std::string rates = fmt::format("{}", fmt::join(info.sampleRates, " "));
                std::cout << fmt::format("  {}: {}  in {}  out {}  rates {}{}{}\n", i, info.name,
                                         info.inputChannels, info.outputChannels, rates,
                                         info.isDefaultOutput ? "  default output" : "",
                                         info.isDefaultInput ? "  default input" : "");
            }
        } catch (const RtAudioError& e) {
            std::cout << "  unavailable: " << e.getMessage() << '\n';
        }
    }
}

}  // namespace

void add_devices(CLI::App& app) {
    CLI::App* command = app.add_subcommand(kDevicesCommand.name, kDevicesCommand.description);
    command->callback([] { list_devices(); });
}

}  // namespace tactus::cli
