// "Did you mean": the closest of some names to what was typed (Levenshtein edit distance), and
// names compared as people type them (case, '_' for '-').
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tactus {

inline size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// Lower case, '_' and ' ' as '-': "LRA_175" and "lra-175" are one name.
inline std::string folded_name(std::string_view name) {
    std::string out(name);
    for (char& c : out) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (c == '_' || c == ' ') c = '-';
    }
    return out;
}

// The candidate closest to `typed` (folded), or empty when none is within a third of its
// length: a suggestion should look like what was meant. Only the first 64 characters are
// compared (edit distance costs length x length).
template <class Names>
std::string nearest_name(std::string_view typed, const Names& candidates) {
    constexpr size_t kComparedChars = 64;
    const std::string key = folded_name(typed.substr(0, kComparedChars));
    std::string best;
    size_t best_distance = SIZE_MAX;
    for (const auto& candidate : candidates) {
        const std::string_view name = candidate;
        const size_t d = edit_distance(key, folded_name(name));
        if (d < best_distance) best_distance = d, best = std::string(name);
    }
    return best_distance <= std::max<size_t>(2, key.size() / 3) ? best : std::string();
}

}  // namespace tactus
