// stderr of `tactus live`, shared by the main loop's status line and the messages of the other
// threads (OSC refusals, preset reloads, a new --sync delay, a device lost). On a terminal the
// status line is redrawn in place (\r), so a message first clears it, takes a line of its own,
// and the status line is drawn again below it; elsewhere there is no status line and each
// message is one line. Any thread but the audio thread (it locks).
#pragma once

#include <mutex>
#include <ostream>
#include <string>

namespace tactus::live {

class Console {
  public:
    // `terminal`: `out` is a terminal, where the status line is shown.
    Console(std::ostream& out, bool terminal) : out_(out), terminal_(terminal) {}

    // "tactus: " + line, on a line of its own.
    void message(const std::string& line);
    // The status line, redrawn in place (a terminal only; nothing elsewhere).
    void status(const std::string& text);
    // The status line stays as it is and later messages go below it, without redrawing it.
    void keep_status();
    bool terminal() const { return terminal_; }

  private:
    std::mutex mutex_;
    std::ostream& out_;
    const bool terminal_;
    std::string status_;  // shown on the terminal's last line; empty: none
};

}  // namespace tactus::live
