// The rows `tactus analyze` writes and tactus.analyze() returns: every analysis frame's features
// and vibration program (paper Figure 4), with the sensation level each channel of touch receives
// from the vibration through an actuator (actuator/drive_meter.hpp, readings every 10 ms: a row
// takes the levels at its own time, interpolated between the readings around it). Frames come off
// the engine's frame queue between process() calls, as a live front end takes them; a row is handed
// on once the meter has heard the vibration up to its time. Setup/offline thread only (not
// real-time: it allocates).
#pragma once

#include <array>
#include <deque>
#include <functional>
#include <string_view>
#include <vector>

#include "tactus/actuator/drive_meter.hpp"
#include "tactus/actuator/profile.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/engine/onset_decisions.hpp"
#include "tactus/perception/meter.hpp"

namespace tactus {

class AnalysisRows {
  public:
    static constexpr std::array<std::string_view, 29> kColumns = {
        "time_s",        "loudness_db",      "brightness_hz",     "noisiness",
        "pitch_hz",      "pitch_confidence", "onset_odf",         "onset",
        "onset_time_s",  "hit_db",           "hit_brightness_hz", "part",
        "part_decided",  "hit_strength_db",  "frequency_hz",      "amplitude",
        "square_mix",    "trigger",          "attack_ms",         "decay_ms",
        "sustain",       "flutter_hz",       "flutter_amplitude", "pressure",
        "P_sl_db",       "NPI_sl_db",        "NPII_sl_db",        "NPIII_sl_db",
        "combined_sl_db"};
    using Row = std::array<double, kColumns.size()>;
    // The frame's own columns (features and vibration program) come first, the sensation levels
    // (four channels and combined) last.
    static constexpr size_t kFrameColumns = kColumns.size() - 5;
    // A column's index by name (kColumns.size(): none).
    static constexpr size_t column(std::string_view name) {
        size_t i = 0;
        while (i < kColumns.size() && kColumns[i] != name) ++i;
        return i;
    }
    // The one text column: the latest hit's DrumPart, held in a Row as its index, written as its
    // name (kDrumPartNames).
    static constexpr size_t kPartColumn = [] {
        size_t i = 0;
        while (kColumns[i] != "part") ++i;
        return i;
    }();
    static DrumPart part_of(const Row& row) {
        return static_cast<DrumPart>(static_cast<int>(row[kPartColumn]));
    }
    // A frame's own columns; the sensation levels 0.
    static Row row_of(const AnalysisFrame& frame, double sample_rate_hz);

    // `engine` must have its frame queue enabled; `actuator` turns the vibration into skin
    // displacement for the meter. `on_onset`, if given, receives each onset once its part is
    // decided (engine/onset_decisions.hpp), as its frames are taken, before their rows.
    AnalysisRows(const Engine& engine, ActuatorProfile actuator,
                 std::function<void(const Row&)> on_row,
                 std::function<void(const DecidedOnset&)> on_onset = {});
    // Once the engine is prepared, before any audio.
    void start(double sample_rate_hz);
    // The engine's frames so far (call after each process()).
    void take_frames(Engine& engine);
    // The first actuator's vibration of the block just processed.
    void vibration(const float* samples, int count);
    // The rows still held, with the last reading (and the onset still waiting for its part).
    void finish();

    size_t rows() const { return rows_; }
    size_t onsets() const { return onsets_; }

  private:
    void write_rows(bool finished);

    const Engine& engine_;
    ActuatorProfile actuator_;
    std::function<void(const Row&)> on_row_;
    std::function<void(const DecidedOnset&)> on_onset_;
    OnsetDecisions decisions_;
    DriveMeter meter_;
    std::deque<Row> pending_;
    std::deque<perception::MeterReading> readings_;
    perception::MeterReading before_;  // the latest reading at or before the next row
    size_t rows_ = 0, onsets_ = 0;
};

}  // namespace tactus
