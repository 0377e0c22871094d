#include "osc_sender.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace tactus::live {

OscSender::OscSender(const OscEndpoint& to)
    : address_(lo_address_new(to.host.c_str(), std::to_string(to.port).c_str())) {
    if (!address_)
        throw std::runtime_error(fmt::format("--osc-send {}:{}: not an address", to.host, to.port));
}

OscSender::~OscSender() {
    lo_address_free(address_);
}

void OscSender::send_state(const AnalysisFrame& frame) {
    const Features& f = frame.features;
    lo_send(address_, "/tactus/features", "ffff", static_cast<float>(f.loudness_db),
            static_cast<float>(f.brightness_hz), static_cast<float>(f.noisiness),
            static_cast<float>(f.pitch_hz));
    lo_send(address_, "/tactus/vibration", "ff", static_cast<float>(frame.control.frequency_hz),
            static_cast<float>(frame.control.amplitude));
}

// The part's name is a constant, null-terminated literal (kDrumPartNames): nothing is built.
void OscSender::send_onset(const DecidedOnset& onset) {
    lo_send(address_, "/tactus/onset", "sf", name_of(onset.part).data(),
            static_cast<float>(onset.strength_db));
}

}  // namespace tactus::live
