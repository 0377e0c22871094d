// Replays fuzz inputs without libFuzzer, so ordinary (GCC, test) builds compile every fuzz target
// and run it on its seeds. Calls LLVMFuzzerTestOneInput once on the bytes of each file named on
// the command line, or of each file in a named directory (sorted), and prints what it replayed.
// A failed check aborts inside the target, as under libFuzzer; an unreadable argument, a return
// value other than 0 or -1 (libFuzzer's "keep" and "reject"), or no inputs at all exits 1.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

bool replay(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "%s: cannot read\n", path.c_str());
        return false;
    }
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::printf("replaying %s (%zu bytes)\n", path.c_str(), bytes.size());
    std::fflush(stdout);  // so a crash's report follows the input that caused it
    const int result =
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    if (result == 0 || result == -1) return true;
    std::fprintf(stderr, "%s: LLVMFuzzerTestOneInput returned %d\n", path.c_str(), result);
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE_OR_DIR...\n", argv[0]);
        return 2;
    }
    std::vector<std::filesystem::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::filesystem::path arg = argv[i];
        if (!std::filesystem::is_directory(arg)) {
            inputs.push_back(arg);
            continue;
        }
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::directory_iterator(arg))
            if (entry.is_regular_file()) files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        inputs.insert(inputs.end(), files.begin(), files.end());
    }
    int failed = 0;
    for (const auto& input : inputs) failed += !replay(input);
    std::printf("replayed %zu inputs, %d failed\n", inputs.size(), failed);
    return inputs.empty() || failed > 0 ? 1 : 0;
}
