// A text output that is either stdout or a file written atomically (temporary + rename on
// commit; removed if never committed).
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>

namespace tactus {

// An output path that means stdout: empty or "-".
inline bool is_stdout(const std::filesystem::path& path) {
    return path.empty() || path == "-";
}

class TextOutput {
  public:
    // is_stdout(path): stdout.
    explicit TextOutput(const std::filesystem::path& path);
    ~TextOutput();
    TextOutput(const TextOutput&) = delete;
    TextOutput& operator=(const TextOutput&) = delete;

    std::ostream& stream() { return file_ ? static_cast<std::ostream&>(*file_) : *stdout_; }
    void commit();

  private:
    std::filesystem::path path_, temporary_;
    std::optional<std::ofstream> file_;
    std::ostream* stdout_ = nullptr;
    bool committed_ = false;
};

}  // namespace tactus
