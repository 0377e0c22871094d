#include "tactus/engine/analysis_rows.hpp"

#include <cmath>
#include <utility>

namespace tactus {
static_assert(AnalysisRows::kColumns.size() - AnalysisRows::kFrameColumns ==
              perception::kChannels.size() + 1);  // and the combined level

AnalysisRows::Row AnalysisRows::row_of(const AnalysisFrame& frame, double sample_rate_hz) {
    const Features& f = frame.features;
    const ControlFrame& c = frame.control;
    return {f.frame_end_sample / sample_rate_hz,
            f.loudness_db,
            f.brightness_hz,
            f.noisiness,
            f.pitch_hz,
            f.pitch_confidence,
            f.onset_odf,
            f.onset ? 1.0 : 0.0,
            f.onset ? f.onset_sample / sample_rate_hz : 0.0,
            c.frequency_hz,
            c.amplitude,
            c.square_mix,
            c.trigger ? 1.0 : 0.0,
            c.attack_ms,
            c.decay_ms,
            c.sustain,
            c.flutter_hz,
            c.flutter_amplitude,
            c.pressure};
}

AnalysisRows::AnalysisRows(const Engine& engine, ActuatorProfile actuator,
                           std::function<void(const Row&)> on_row)
    : engine_(engine), actuator_(std::move(actuator)), on_row_(std::move(on_row)) {}

void AnalysisRows::start(double sample_rate_hz) {
    meter_.prepare(
        sample_rate_hz, [this](double f) { return actuator_.displacement_um_at(f); },
        engine_.settings()[P::perception_contact_area_cm2]);
}

void AnalysisRows::take_frames(Engine& engine) {
    for (AnalysisFrame frame; engine.pop_frame(frame);) {
        pending_.push_back(row_of(frame, engine_.sample_rate_hz()));
        onsets_ += frame.features.onset;
    }
}

void AnalysisRows::vibration(const float* samples, int count) {
    meter_.write(samples, count,
                 [this](const perception::MeterReading& r) { readings_.push_back(r); });
    metered_samples_ += count;
    write_rows_up_to(static_cast<double>(metered_samples_));
}

void AnalysisRows::finish() {
    write_rows_up_to(INFINITY);
}

void AnalysisRows::write_rows_up_to(double samples) {
    const double sample_rate_hz = engine_.sample_rate_hz();
    while (!pending_.empty() && pending_.front()[0] * sample_rate_hz <= samples + 0.5) {
        Row values = pending_.front();
        pending_.pop_front();
        while (!readings_.empty() && readings_.front().time_s <= values[0] + 1e-9) {
            current_ = readings_.front();
            readings_.pop_front();
        }
        const size_t first = kFrameColumns;
        for (size_t i = 0; i < current_.level_db.size(); ++i)
            values[first + i] = current_.level_db[i];
        values[first + current_.level_db.size()] = current_.combined_db;
        on_row_(values);
        ++rows_;
    }
}

}  // namespace tactus
