#include "tactus/io/text_output.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "tactus/io/temporary_path.hpp"

namespace tactus {
namespace {

// ": <strerror>" when the C library said why a stream failed, else nothing.
std::string system_reason() {
    return errno != 0 ? fmt::format(": {}", std::strerror(errno)) : std::string{};
}

}  // namespace

TextOutput::TextOutput(const std::filesystem::path& path) : path_(path) {
    if (is_stdout(path)) {
        stdout_ = &std::cout;
        return;
    }
    temporary_ = temporary_path_for(path);
    track_temporary(temporary_);
    errno = 0;
    file_.emplace(temporary_);
    if (!*file_) {
        const std::string reason = system_reason();
        file_.reset();
        discard_temporary(temporary_);
        throw std::runtime_error(fmt::format("{}: cannot write{}", path.string(), reason));
    }
}

TextOutput::~TextOutput() {
    if (file_ && !committed_) {
        file_->close();
        discard_temporary(temporary_);
    }
}

void TextOutput::commit() {
    // errno is not cleared first: a stream that failed mid-run keeps failing silently, and the
    // reason is what the failing write left in errno.
    if (!file_) {
        std::cout.flush();
        if (!std::cout)
            throw std::runtime_error(fmt::format("stdout: write failed{}", system_reason()));
        return;
    }
    file_->flush();
    file_->close();
    if (file_->fail()) {  // the destructor discards the temporary
        const std::string reason = system_reason();
        throw std::runtime_error(fmt::format("{}: write failed{}", path_.string(), reason));
    }
    commit_temporary(temporary_, path_);
    committed_ = true;
}

}  // namespace tactus
