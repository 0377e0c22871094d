// Reads a TOML file's tables key by key with one-line errors "ORIGIN:LINE:COL: key: problem"
// (actuator profiles, layouts): numbers in a range, strings, names from a list, and every key
// read, so a misspelt one is an error rather than silently ignored.
#pragma once

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tactus/core/printable.hpp"

namespace tactus {

// A data file's text (a profile, a layout); std::runtime_error "KIND file 'PATH' not found".
inline std::string toml_file_text(const std::filesystem::path& path, std::string_view kind) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(fmt::format("{} file '{}' not found", kind, path.string()));
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The text parsed, or std::runtime_error "ORIGIN:LINE:COL: TOML syntax error: ...".
inline toml::table parse_toml(std::string_view text, std::string_view origin) {
    try {
        return toml::parse(text, origin);
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(fmt::format("{}:{}:{}: TOML syntax error: {}", origin,
                                             e.source().begin.line, e.source().begin.column,
                                             printable(e.description())));
    }
}

// One table's keys (`prefix`: its path, for messages).
class TomlReader {
  public:
    TomlReader(const toml::table& table, std::string_view origin, std::string prefix)
        : table_(table), origin_(origin), prefix_(std::move(prefix)) {}

    [[noreturn]] void fail(const toml::node* node, std::string_view key,
                           std::string_view problem) const {
        const auto& where = node ? node->source() : table_.source();
        throw std::runtime_error(fmt::format("{}:{}:{}: {}: {}", origin_, where.begin.line,
                                             where.begin.column,
                                             printable(prefix_ + std::string(key)), problem));
    }
    const toml::node* get(std::string_view key) {
        seen_.insert(std::string(key));
        return table_.get(key);
    }
    double number(std::string_view key, double min, double max, double fallback,
                  bool required = false) {
        const toml::node* node = get(key);
        if (!node) {
            if (required) fail(nullptr, key, "missing (a number is required)");
            return fallback;
        }
        if (!node->is_number()) fail(node, key, "must be a number");
        const double v = *node->value<double>();
        if (!std::isfinite(v) || v < min || v > max)
            fail(node, key, fmt::format("{} is out of range: allowed {} to {}", v, min, max));
        return v;
    }
    std::string text(std::string_view key, std::string fallback) {
        const toml::node* node = get(key);
        if (!node) return fallback;
        if (!node->is_string()) fail(node, key, "must be a string in quotes");
        return *node->value<std::string>();
    }
    template <size_t N>
    size_t choice(std::string_view key, const std::string_view (&names)[N], size_t fallback) {
        const toml::node* node = get(key);
        if (!node) return fallback;
        const std::string value = node->is_string() ? *node->value<std::string>() : "";
        for (size_t i = 0; i < N; ++i)
            if (names[i] == value) return i;
        std::string allowed;
        for (auto n : names) allowed += (allowed.empty() ? "" : ", ") + std::string(n);
        fail(node, key, fmt::format("must be one of: {}", allowed));
    }
    // Every key must have been read: a misspelt key is an error, not silently ignored.
    void reject_unknown_keys() const {
        for (const auto& [key, node] : table_)
            if (!seen_.contains(std::string(key.str()))) fail(&node, key.str(), "unknown key");
    }

  private:
    const toml::table& table_;
    std::string_view origin_;
    std::string prefix_;
    std::set<std::string> seen_;
};

}  // namespace tactus
