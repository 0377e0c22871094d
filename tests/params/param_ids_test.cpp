// The parameter table's stable ids against the committed list (src/tactus/params/param_ids.txt):
// renumbering a parameter, reusing an id or adding a parameter without its line fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "tactus/params/params.hpp"

namespace tactus {
namespace {

struct IdLine {
    std::string key;
    bool retired = false;
};

// id -> line; fails the test on a malformed or repeated line.
std::map<uint32_t, IdLine> committed_ids() {
    std::ifstream file(std::string(TACTUS_SOURCE_DIR) + "/src/tactus/params/param_ids.txt");
    EXPECT_TRUE(file) << "param_ids.txt not found";
    std::map<uint32_t, IdLine> ids;
    std::set<std::string> keys;
    std::string line;
    for (int number = 1; std::getline(file, line); ++number) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        uint32_t id = 0;
        IdLine entry;
        std::string mark, extra;
        fields >> id >> entry.key >> mark >> extra;
        EXPECT_TRUE(id > 0 && !entry.key.empty() && (mark.empty() || mark == "retired") &&
                    extra.empty())
            << "param_ids.txt:" << number << ": expected '<id> <key> [retired]': " << line;
        entry.retired = mark == "retired";
        EXPECT_TRUE(keys.insert(entry.key).second)
            << "param_ids.txt:" << number << ": " << entry.key << " listed twice";
        EXPECT_TRUE(ids.emplace(id, entry).second)
            << "param_ids.txt:" << number << ": id " << id << " listed twice";
    }
    return ids;
}

TEST(ParamIds, EveryParameterKeepsItsCommittedId) {
    const auto ids = committed_ids();
    const uint32_t next = ids.empty() ? 1 : ids.rbegin()->first + 1;
    for (const ParamSpec& s : param_table()) {
        const std::string key(s.key);
        const auto line = ids.find(s.id);
        if (line == ids.end()) {
            ADD_FAILURE() << key << " has id " << s.id << ", not in param_ids.txt: a new "
                          << "parameter takes the next free id, " << next;
            continue;
        }
        EXPECT_EQ(line->second.key, key)
            << "id " << s.id << " belongs to " << line->second.key << " in param_ids.txt; " << key
            << " may not take it (a renamed parameter changes its line's key)";
        EXPECT_FALSE(line->second.retired)
            << "id " << s.id << " is retired: " << key << " may not reuse it";
    }
}

TEST(ParamIds, EveryCommittedIdIsInTheTableOrRetired) {
    for (const auto& [id, line] : committed_ids()) {
        if (line.retired) continue;
        EXPECT_TRUE(find_param(id).has_value())
            << "param_ids.txt lists " << id << " " << line.key
            << " but the table has no such id: mark it retired, never delete it";
    }
}

TEST(ParamIds, LookupByIdAndKeyAgree) {
    for (const ParamSpec& s : param_table()) {
        ASSERT_TRUE(find_param(s.id).has_value());
        EXPECT_EQ(*find_param(s.id), s.param);
        EXPECT_EQ(*find_param(s.key), s.param);
    }
    EXPECT_FALSE(find_param(uint32_t{0}).has_value());
}

}  // namespace
}  // namespace tactus
