#include "tactus/io/meter_run.hpp"

#include <vector>

#include "tactus/dsp/downmix.hpp"

namespace tactus {

RunSummary meter_source(AudioSource& vibration, const ActuatorProfile& actuator,
                        double contact_area_cm2, const DriveMeter::OnReading& on_reading,
                        const RunCallbacks& callbacks) {
    DriveMeter meter;
    std::vector<float> mono;
    int channels = 1;
    const RunSummary run = stream_source(
        vibration,
        [&](const ProcessSpec& spec) {
            meter.prepare(spec.sample_rate_hz, actuator, contact_area_cm2);
            channels = spec.channels;
            mono.resize(static_cast<size_t>(spec.max_block));
        },
        [&](const float* const* in, int frames) {  // the actuators' mean
            downmix_mean(in, channels, 0, mono.data(), frames);
            meter.write(mono.data(), frames, on_reading);
        },
        callbacks);
    meter.finish(on_reading);
    return run;
}

}  // namespace tactus
