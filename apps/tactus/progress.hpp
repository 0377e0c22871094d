// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <cstdint>
#include <string>

namespace tactus::cli {

class Progress {
  public:
    explicit Progress(std::string label);
    ~Progress();
    void update(int64_t done, int64_t total);
    bool enabled() const { return enabled_; }

  private:
    std::string label_;
    bool enabled_ = false;
    int last_percent_ = -1;
};

}  // namespace tactus::cli
