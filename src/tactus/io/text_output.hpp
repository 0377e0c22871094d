// A text output that is either stdout or a file written atomically (temporary + rename on
// commit; removed if never committed).
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>

namespace tactus {

class TextOutput {
  public:
    // Empty path or "-": stdout.
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
