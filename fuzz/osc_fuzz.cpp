// libFuzzer target: any bytes as one UDP packet to `tactus live`'s OSC server, through the
// server's own handling (decode, check against the address space, coalesce, apply through
// LiveControl to an engine). Every refusal is one line; the settings stay inside the table's
// ranges whatever arrives.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fuzz_check.hpp"
#include "live/osc_server.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    tactus::Engine engine;  // not prepared: changes apply at once, on this thread
    engine.set_actuators(std::vector<tactus::ActuatorOutput>(2));
    tactus::live::LiveControl control(engine, {});
    const std::vector<std::vector<std::byte>> packets{
        {reinterpret_cast<const std::byte*>(data),
         reinterpret_cast<const std::byte*>(data) + size}};
    tactus::live::handle_osc_packets(packets, control, [](const std::string& line) {
        tactus::fuzz::check_message(line.c_str());
    });
    tactus::fuzz::check_in_range(control.settings());
    tactus::fuzz::check_in_range(engine.settings());
    return 0;
}
