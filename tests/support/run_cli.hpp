// Runs the tactus command line as a user runs it (through the shell), from a test with its own
// temporary directory: exit code, stdout and stderr; and reads the numbers in its CSV output.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/sound_file.hpp"
#include "support/temp_dir.hpp"

namespace tactus::test {

struct CliResult {
    int exit_code;
    std::string out, err;
};

class Cli : public TempDirTest {
  protected:
    // `prefix` goes before the executable (e.g. to run it as another user); `program` is the
    // built CLI unless another copy is named.
    CliResult run(const std::string& arguments, const std::string& prefix = "",
                  const std::filesystem::path& program = TACTUS_CLI) const {
        const std::filesystem::path err = dir_ / "stderr.txt";
        const std::string command =
            prefix + program.string() + " " + arguments + " 2>" + err.string();
        FILE* pipe = popen(command.c_str(), "r");
        std::string out;
        char buffer[4096];
        while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
        const int status = pclose(pipe);
        std::ifstream e(err);
        std::stringstream s;
        s << e.rdbuf();
        return {WEXITSTATUS(status), out, s.str()};
    }
};

// The cells of one CSV line (analyze's or meter's output, all numeric) as numbers.
// A CSV line's cells as numbers; a text cell (analyze's part) is NaN.
inline std::vector<double> csv_numbers(const std::string& line) {
    std::vector<double> v;
    std::istringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) {
        char* end = nullptr;
        const double x = std::strtod(cell.c_str(), &end);
        v.push_back(end != cell.c_str() && *end == '\0' ? x : std::nan(""));
    }
    return v;
}

// A CSV header's column index by name (the header's cell count: none).
inline size_t csv_column(const std::string& header, const std::string& name) {
    std::istringstream s(header);
    size_t i = 0;
    for (std::string cell; std::getline(s, cell, ','); ++i)
        if (cell == name) return i;
    return i;
}

}  // namespace tactus::test
