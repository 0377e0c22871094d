#include "session.hpp"

#include <fmt/format.h>
#include <stdlib.h>

#include <fstream>
#include <random>

#include "tactus/io/audio_reader.hpp"

namespace tactus::cli {
namespace {

// 128 random bits as 32 hex digits.
std::string random_token() {
    std::random_device device;
    std::string token;
    for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", device());
    return token;
}

std::filesystem::path make_folder() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "tactus-studio-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
        throw std::runtime_error(fmt::format("{}: cannot create the session's folder", pattern));
    return pattern;
}

}  // namespace

void check_plain_name(const std::string& name) {
    if (name.empty() || name.size() > 200 || name.front() == '.' ||
        name.find_first_of(std::string("/\\\0", 3)) != std::string::npos)
        throw std::runtime_error(
            fmt::format("'{}': not a plain file name (no folder, no leading dot)", name));
}

StudioSession::StudioSession(const std::vector<std::filesystem::path>& files)
    : token_(random_token()), folder_(make_folder()) {
    for (const auto& path : files) {
        std::string name = path.filename().string();
        // Two files of the same name from different folders: the second is told apart.
        for (int n = 2; file(name); ++n) name = fmt::format("{} ({})", path.filename().string(), n);
        files_.emplace_back(name, std::filesystem::absolute(path));
    }
}

StudioSession::~StudioSession() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
}

bool StudioSession::token_matches(const std::string& token) const {
    unsigned diff = token.size() != token_.size();
    for (size_t i = 0; i < token_.size(); ++i)
        diff |= static_cast<unsigned>(token_[i] ^ (i < token.size() ? token[i] : 0));
    return diff == 0;
}

std::vector<std::string> StudioSession::file_names() const {
    std::lock_guard lock(mutex_);
    std::vector<std::string> names;
    for (const auto& [name, path] : files_) names.push_back(name);
    return names;
}

std::optional<std::filesystem::path> StudioSession::file(const std::string& name) const {
    std::lock_guard lock(mutex_);
    for (const auto& [listed, path] : files_)
        if (listed == name) return path;
    return std::nullopt;
}

std::filesystem::path StudioSession::output_path(const std::string& name) const {
    check_plain_name(name);
    return folder_ / "out" / name;
}

std::string StudioSession::add_upload(const std::string& name, const std::string& bytes) {
    check_plain_name(name);
    if (bytes.size() > kMaxUploadBytes)
        throw std::runtime_error(fmt::format("{}: {} bytes, more than the {} an upload may have",
                                             name, bytes.size(), kMaxUploadBytes));
    std::lock_guard lock(mutex_);
    if (uploads_ >= kMaxUploads)
        throw std::runtime_error(
            fmt::format("{}: a session takes at most {} uploads", name, kMaxUploads));
    for (const auto& [listed, path] : files_)
        if (listed == name) throw std::runtime_error(fmt::format("{}: already listed", name));
    const std::filesystem::path folder = folder_ / fmt::format("upload-{}", uploads_ + 1);
    std::filesystem::create_directories(folder);
    const std::filesystem::path path = folder / name;
    {
        std::ofstream out(path, std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out) throw std::runtime_error(fmt::format("{}: cannot write the upload", name));
    }
    try {
        AudioReader reader(path);  // refused now, not at the first render
    } catch (const std::exception& e) {
        std::error_code ignored;
        std::filesystem::remove_all(folder, ignored);
        throw std::runtime_error(fmt::format("{}: not a sound file tactus reads", name));
    }
    ++uploads_;
    files_.emplace_back(name, path);
    return name;
}

int64_t StudioSession::keep_render(std::shared_ptr<const Samples> samples) {
    std::lock_guard lock(mutex_);
    const int64_t id = next_render_++;
    renders_[id] = std::move(samples);
    while (renders_.size() > kKeptRenders) renders_.erase(renders_.begin());
    return id;
}

std::shared_ptr<const StudioSession::Samples> StudioSession::render(int64_t id) const {
    std::lock_guard lock(mutex_);
    const auto it = renders_.find(id);
    return it == renders_.end() ? nullptr : it->second;
}

}  // namespace tactus::cli
