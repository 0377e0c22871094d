// Sends what the engine hears and plays to --osc-send, for Max, Pd and SuperCollider patches:
//   /tactus/features loudness_db brightness_hz noisiness pitch_hz   at --osc-rate
//   /tactus/vibration frequency_hz amplitude                         at --osc-rate
//   /tactus/onset part strength_db                                   at every onset
// (floats, but the onset's drum part: a string, "kick", "snare", "hat" or "other"; the onset is
// sent once its part and strength are decided, parts.settle_ms after it:
// engine/onset_decisions.hpp). Control thread (FrameMonitor's).
#pragma once

#include <lo/lo.h>

#include <string>

#include "osc_server.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/engine/onset_decisions.hpp"

namespace tactus::live {

class OscSender {
  public:
    explicit OscSender(const OscEndpoint& to);
    ~OscSender();
    OscSender(const OscSender&) = delete;
    OscSender& operator=(const OscSender&) = delete;

    void send_state(const AnalysisFrame& frame);
    void send_onset(const DecidedOnset& onset);

  private:
    lo_address address_;
};

}  // namespace tactus::live
