// The analyses (engine/recorded_analysis.hpp) of the latest files `tactus studio` rendered,
// each under its file (path, size and modification time) and the values of the parameters the
// analysis reads (Analyzer::reads): a render whose change leaves those as they were plays the
// analysis back instead of analysing the file again (report_render.hpp). Any thread (a mutex
// guards it).
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "tactus/engine/recorded_analysis.hpp"
#include "tactus/params/params.hpp"

namespace tactus::cli {

class AnalysisCache {
  public:
    static constexpr size_t kKept = 4;  // analyses (about 0.6 MB for 30 s of sound each)

    // What an analysis of `input` with `settings` is kept under; throws std::runtime_error
    // naming the file when it cannot be read.
    static std::string key_of(const std::filesystem::path& input, const Settings& settings);
    // The analysis kept under `key`, or null.
    std::shared_ptr<const RecordedAnalysis> find(const std::string& key) const;
    // Keeps `analysis` under `key` (the oldest of more than kKept is let go).
    void keep(const std::string& key, std::shared_ptr<const RecordedAnalysis> analysis);

  private:
    mutable std::mutex mutex_;
    std::vector<std::pair<std::string, std::shared_ptr<const RecordedAnalysis>>>
        kept_;  // oldest first
};

}  // namespace tactus::cli
