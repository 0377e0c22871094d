#include "tactus/io/analysis_rows.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace tactus {
static_assert(AnalysisRows::kColumns.size() - AnalysisRows::kFrameColumns ==
              perception::kChannels.size() + 1);  // and the combined level
static_assert(AnalysisRows::kPartColumn < AnalysisRows::kFrameColumns);

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
            f.hit_db,
            f.hit_brightness_hz,
            static_cast<double>(f.part),
            f.part_decided ? 1.0 : 0.0,
            f.hit_strength_db,
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
                           std::function<void(const Row&)> on_row,
                           std::function<void(const DecidedOnset&)> on_onset)
    : engine_(engine),
      actuator_(std::move(actuator)),
      on_row_(std::move(on_row)),
      on_onset_(std::move(on_onset)) {}

void AnalysisRows::start(double sample_rate_hz) {
    meter_.prepare(sample_rate_hz, actuator_, engine_.settings()[P::perception_contact_area_cm2]);
    decisions_.reset();
}

void AnalysisRows::take_frames(Engine& engine) {
    for (AnalysisFrame frame; engine.pop_frame(frame);) {
        pending_.push_back(row_of(frame, engine_.sample_rate_hz()));
        onsets_ += frame.features.onset;
        if (on_onset_) decisions_.add(frame.features, on_onset_);
    }
}

void AnalysisRows::vibration(const float* samples, int count) {
    meter_.write(samples, count,
                 [this](const perception::MeterReading& r) { readings_.push_back(r); });
    write_rows(false);
}

// After the last sample the vibration is silent: one more step of it gives the reading after
// the last rows, so they are interpolated as every other row is.
void AnalysisRows::finish() {
    const int step = static_cast<int>(
        std::lround(perception::SensationMeter::kStepS * engine_.sample_rate_hz()));
    const std::vector<float> silence(static_cast<size_t>(step), 0.0f);
    if (!pending_.empty()) vibration(silence.data(), step);
    write_rows(true);
    if (on_onset_) decisions_.finish(on_onset_);
}

// Each row carries the sensation levels at its own time, interpolated between the 10 ms readings
// around it, so they line up with `tactus meter -o` of the rendered vibration. A row waits for
// the reading after it; `finished`: the rest, with the last reading.
void AnalysisRows::write_rows(bool finished) {
    while (!pending_.empty()) {
        Row values = pending_.front();
        const double t = values[0];
        while (!readings_.empty() && readings_.front().time_s <= t + 1e-9) {
            before_ = readings_.front();
            readings_.pop_front();
        }
        if (readings_.empty() && !finished) return;
        pending_.pop_front();
        const perception::MeterReading& after = readings_.empty() ? before_ : readings_.front();
        const double span = after.time_s - before_.time_s;
        const double w = span > 0 ? (t - before_.time_s) / span : 0.0;
        const auto between = [w](double a, double b) { return a + w * (b - a); };
        for (size_t i = 0; i < before_.level_db.size(); ++i)
            values[kFrameColumns + i] = between(before_.level_db[i], after.level_db[i]);
        values[kFrameColumns + before_.level_db.size()] =
            between(before_.combined_db, after.combined_db);
        on_row_(values);
        ++rows_;
    }
}

}  // namespace tactus
