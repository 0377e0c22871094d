// One `tactus studio` session: its token, its temporary folder (uploads and exports, removed
// when the session ends) and the sound files it may read (those named on the command line and
// those uploaded), by name only: a request names a listed file, never a path. Any thread (a
// mutex guards the lists).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "analysis_cache.hpp"

namespace tactus::cli {

class StudioSession {
  public:
    static constexpr size_t kMaxUploadBytes = 200u << 20;  // per file (a 20-minute 44.1 kHz WAV)
    static constexpr size_t kMaxUploads = 32;
    static constexpr size_t kKeptRenders = 4;  // the renders whose samples the page may fetch

    // Files named on the command line (checked: each exists and is a file). Creates the folder.
    explicit StudioSession(const std::vector<std::filesystem::path>& files);
    ~StudioSession();  // removes the folder and everything in it
    StudioSession(const StudioSession&) = delete;
    StudioSession& operator=(const StudioSession&) = delete;

    const std::string& token() const { return token_; }
    const std::filesystem::path& folder() const { return folder_; }
    // Constant-time comparison with the session's token.
    bool token_matches(const std::string& token) const;

    // The listed files' names, in the order they were added.
    std::vector<std::string> file_names() const;
    // The path of the listed file called `name`; none for any other name.
    std::optional<std::filesystem::path> file(const std::string& name) const;
    // Writes `bytes` into the folder as `name` (a plain file name: no folder, no "..", no
    // leading dot) and lists it; throws std::runtime_error with a one-line message when the name,
    // the size or the count is refused, or the file is not audio libsndfile reads (then nothing
    // is kept).
    std::string add_upload(const std::string& name, const std::string& bytes);
    // A path in the folder for an output named `name` (checked as for uploads).
    std::filesystem::path output_path(const std::string& name) const;

    // A render's samples, kept for the page to fetch (the kKeptRenders latest); returns its id.
    struct Samples {
        std::vector<float> sound, vibration;
    };
    int64_t keep_render(std::shared_ptr<const Samples> samples);
    std::shared_ptr<const Samples> render(int64_t id) const;
    // The analyses of the files rendered, played back while a change leaves them as they were.
    AnalysisCache& analyses() { return analyses_; }

  private:
    std::string token_;
    std::filesystem::path folder_;
    mutable std::mutex mutex_;
    std::vector<std::pair<std::string, std::filesystem::path>> files_;
    size_t uploads_ = 0;
    std::map<int64_t, std::shared_ptr<const Samples>> renders_;
    int64_t next_render_ = 1;
    AnalysisCache analyses_;
};

// Throws std::runtime_error unless `name` is a plain file name (no '/', '\\', NUL, not "." or
// "..", no leading dot, at most 200 bytes).
void check_plain_name(const std::string& name);

}  // namespace tactus::cli
