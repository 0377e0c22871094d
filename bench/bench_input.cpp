#include "bench_input.hpp"

#include <algorithm>
#include <stdexcept>

#include "tactus/analysis/analyzer.hpp"
#include "tactus/core/units.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/mapping/mapper.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus::bench {

const std::vector<float>& amen() {
    static const std::vector<float> samples = [] {
        MonoAudio audio = read_mono(kAmenPath);
        if (audio.sample_rate_hz != kRateHz)
            throw std::runtime_error("loop_amen_full.flac: expected 44.1 kHz");
        return std::move(audio.samples);
    }();
    return samples;
}

int hop_samples(const Settings& settings) {
    return std::max<int>(1, static_cast<int>(ms_to_samples(settings[P::analysis_hop_ms], kRateHz)));
}

const std::vector<ControlFrame>& amen_control() {
    static const std::vector<ControlFrame> frames = [] {
        const Settings settings;
        Analyzer analyzer;
        analyzer.prepare(kRateHz, settings);
        Mapper mapper;
        mapper.prepare(settings, kRateHz / analyzer.hop_samples());
        std::vector<ControlFrame> out;
        const std::vector<float>& in = amen();
        const int hop = analyzer.hop_samples();
        for (size_t i = 0; i + hop <= in.size(); i += hop)
            if (analyzer.write(in.data() + i, hop)) out.push_back(mapper.map(analyzer.analyse()));
        return out;
    }();
    return frames;
}

const std::vector<float>& amen_vibration() {
    static const std::vector<float> samples = [] {
        const Settings settings;
        Voice voice;
        voice.prepare(kRateHz, settings[P::post_band_high_hz]);
        const int hop = hop_samples(settings);
        std::vector<float> out(amen_control().size() * hop);
        for (size_t f = 0; f < amen_control().size(); ++f) {
            voice.render(out.data() + f * hop, hop);
            voice.apply(amen_control()[f]);
        }
        return out;
    }();
    return samples;
}

}  // namespace tactus::bench
