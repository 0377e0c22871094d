#include "analysis_cache.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tactus/analysis/analyzer.hpp"

namespace tactus::cli {

std::string AnalysisCache::key_of(const std::filesystem::path& input, const Settings& settings) {
    std::error_code error;
    const auto size = std::filesystem::file_size(input, error);
    const auto modified = std::filesystem::last_write_time(input, error);
    if (error) throw std::runtime_error(fmt::format("{}: {}", input.string(), error.message()));
    std::string key = fmt::format("{}\n{}\n{}", std::filesystem::absolute(input).string(), size,
                                  modified.time_since_epoch().count());
    for (const ParamSpec& p : param_table())
        if (Analyzer::reads(p.param)) key += fmt::format("\n{}={}", p.key, settings[p.param]);
    return key;
}

std::shared_ptr<const RecordedAnalysis> AnalysisCache::find(const std::string& key) const {
    const std::lock_guard lock(mutex_);
    for (const auto& [kept, analysis] : kept_)
        if (kept == key) return analysis;
    return nullptr;
}

void AnalysisCache::keep(const std::string& key, std::shared_ptr<const RecordedAnalysis> analysis) {
    const std::lock_guard lock(mutex_);
    std::erase_if(kept_, [&](const auto& k) { return k.first == key; });
    kept_.emplace_back(key, std::move(analysis));
    if (kept_.size() > kKept) kept_.erase(kept_.begin());
}

}  // namespace tactus::cli
