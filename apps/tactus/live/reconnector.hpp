// Opens a lost device again, on a thread of its own, once a period, until it is back. A device
// library can block for a long time, or for good, while it tears a lost connection down (a JACK
// client of a dead server waits for the server to go, jack_stream.hpp): off the control thread,
// `tactus live` keeps its clock and still stops at --duration or Ctrl-C.
#pragma once

#include <chrono>
#include <functional>
#include <memory>

#include "live/device_stream.hpp"

namespace tactus::live {

class Reconnector {
  public:
    // Opens and starts a stream, or throws (the device is not back yet).
    using Open = std::function<std::unique_ptr<DeviceStream>()>;

    // Closes `lost` and calls `open` every `period` until it returns a stream. Control thread.
    Reconnector(std::unique_ptr<DeviceStream> lost, Open open, std::chrono::milliseconds period);
    // Stops asking. A worker still inside the device library after a grace period is left
    // there (it holds nothing of the caller's once `open` has returned).
    ~Reconnector();
    Reconnector(const Reconnector&) = delete;
    Reconnector& operator=(const Reconnector&) = delete;

    // Control thread: the stream, started, once the device is back; null until then.
    std::unique_ptr<DeviceStream> take();

  private:
    struct State;
    std::shared_ptr<State> state_;
};

}  // namespace tactus::live
