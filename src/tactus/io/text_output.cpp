#include "tactus/io/text_output.hpp"

#include <fmt/format.h>

#include <iostream>
#include <stdexcept>

#include "tactus/io/temporary_path.hpp"

namespace tactus {

TextOutput::TextOutput(const std::filesystem::path& path) : path_(path) {
    if (path.empty() || path == "-") {
        stdout_ = &std::cout;
        return;
    }
    temporary_ = temporary_path_for(path);
    file_.emplace(temporary_);
    if (!*file_) throw std::runtime_error(fmt::format("{}: cannot write", path.string()));
}

TextOutput::~TextOutput() {
    if (file_ && !committed_) {
        file_->close();
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);
    }
}

void TextOutput::commit() {
    if (!file_) {
        std::cout.flush();
        return;
    }
    file_->close();
    if (file_->fail()) throw std::runtime_error(fmt::format("{}: write failed", path_.string()));
    commit_temporary(temporary_, path_);
    committed_ = true;
}

}  // namespace tactus
