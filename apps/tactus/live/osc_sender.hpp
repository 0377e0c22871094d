// Sends what the engine hears and plays to --osc-send, for Max, Pd and SuperCollider patches:
//   /tactus/features loudness_db brightness_hz noisiness pitch_hz   at --osc-rate
//   /tactus/vibration frequency_hz amplitude                         at --osc-rate
//   /tactus/onset strength                                           at every onset
// (floats; strength is the onset detection function's value). Control thread (FrameMonitor's).
#pragma once

#include <lo/lo.h>

#include <string>

#include "osc_server.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::live {

class OscSender {
  public:
    explicit OscSender(const OscEndpoint& to);
    ~OscSender();
    OscSender(const OscSender&) = delete;
    OscSender& operator=(const OscSender&) = delete;

    void send_state(const AnalysisFrame& frame);
    void send_onset(const AnalysisFrame& frame);

  private:
    lo_address address_;
};

}  // namespace tactus::live
