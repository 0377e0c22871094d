// A fresh temporary directory per test, removed afterwards, and the check that nothing in it
// is a leftover temporary file.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <string>

namespace tactus::test {

class TempDirTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (std::filesystem::temp_directory_path() / "tactus-XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }

    // No file anywhere under the directory is a temporary (the library writes outputs to
    // ".<name>.tmp-<pid>" and renames them on success): a finished or failed run left none.
    void expect_no_temporaries() const {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(dir_))
            EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
                << entry.path();
    }

    std::filesystem::path dir_;
};

}  // namespace tactus::test
