#include "tactus/io/meter_run.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "tactus/dsp/downmix.hpp"

namespace tactus {

RunSummary meter_source(
    AudioSource& vibration, const std::vector<MeteredChannel>& metered, double contact_area_cm2,
    const std::function<void(size_t, const perception::MeterReading&)>& on_reading,
    const RunCallbacks& callbacks) {
    std::vector<DriveMeter> meters(metered.size());
    std::vector<DriveMeter::OnReading> readers;
    for (size_t k = 0; k < metered.size(); ++k)
        readers.emplace_back([&, k](const perception::MeterReading& r) { on_reading(k, r); });
    std::vector<float> mono;
    int channels = 1;
    const RunSummary run = stream_source(
        vibration,
        [&](const ProcessSpec& spec) {
            channels = spec.channels;
            for (size_t k = 0; k < metered.size(); ++k) {
                if (metered[k].channel >= channels)
                    throw std::runtime_error(fmt::format("channel {} metered, the file has {}",
                                                         metered[k].channel + 1, channels));
                meters[k].prepare(spec.sample_rate_hz, metered[k].actuator, contact_area_cm2);
            }
            mono.resize(static_cast<size_t>(spec.max_block));
        },
        [&](const float* const* in, int frames) {
            for (size_t k = 0; k < metered.size(); ++k) {
                const float* drive = in[std::max(metered[k].channel, 0)];
                if (metered[k].channel < 0 && channels > 1) {  // the actuators' mean
                    downmix_mean(in, channels, 0, mono.data(), frames);
                    drive = mono.data();
                }
                meters[k].write(drive, frames, readers[k]);
            }
        },
        callbacks);
    for (size_t k = 0; k < metered.size(); ++k) meters[k].finish(readers[k]);
    return run;
}

}  // namespace tactus
