// Every field of every row of the parameter table against the committed text
// (tests/params/param_table.txt): the rows the table generates (the mapping groups) and the rows
// it spells out must stay exactly as they were; a deliberate change updates that file.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tactus/params/params.hpp"

namespace tactus {
namespace {

// One row as one line: every field, numbers in their shortest exact form.
std::string text_of(const ParamSpec& s) {
    std::string choices;
    for (const std::string_view c : s.choices) {
        if (!choices.empty()) choices += ',';
        choices += c;
    }
    return fmt::format("{} {} {} [{}] {} {} {} {} {} {} {} | {}{}{}", static_cast<int>(s.param),
                       s.id, s.key, s.unit, kParamTypeNames[static_cast<int>(s.type)], s.min, s.max,
                       s.default_value, s.curve == ParamCurve::log ? "log" : "lin",
                       s.change == ParamChange::live ? "live" : "structural", s.smoothing_ms,
                       s.help, choices.empty() ? "" : " | ", choices);
}

TEST(ParamTable, EveryRowIsAsCommitted) {
    std::ifstream file(std::string(TACTUS_SOURCE_DIR) + "/tests/params/param_table.txt");
    ASSERT_TRUE(file) << "param_table.txt not found";
    std::string line;
    size_t row = 0;
    for (const ParamSpec& s : param_table()) {
        ASSERT_TRUE(std::getline(file, line)) << "param_table.txt ends before " << s.key;
        EXPECT_EQ(text_of(s), line) << "row " << row;
        ++row;
    }
    EXPECT_FALSE(std::getline(file, line)) << "param_table.txt has more rows: " << line;
}

}  // namespace
}  // namespace tactus
