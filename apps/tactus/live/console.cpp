#include "console.hpp"

namespace tactus::live {
namespace {

constexpr const char* kClearLine = "\r\x1b[K";  // to the line's start, erase to its end

}  // namespace

void Console::message(const std::string& line) {
    const std::lock_guard lock(mutex_);
    if (!status_.empty()) out_ << kClearLine;
    out_ << "tactus: " << line << '\n';
    if (!status_.empty()) out_ << status_;
    out_.flush();
}

void Console::status(const std::string& text) {
    if (!terminal_) return;
    const std::lock_guard lock(mutex_);
    status_ = text;
    out_ << kClearLine << status_ << std::flush;
}

void Console::keep_status() {
    const std::lock_guard lock(mutex_);
    if (!status_.empty()) out_ << '\n' << std::flush;
    status_.clear();
}

}  // namespace tactus::live
