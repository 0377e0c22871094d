// libFuzzer target: any bytes as an audio file, read the way every command reads its input
// (run_file: AudioReader, then the engine). Reading either succeeds or throws
// std::runtime_error with a one-line message; whatever is decoded, the vibration is finite and
// never above full scale. The bytes go through a real file because libsndfile opens paths.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "fuzz_check.hpp"
#include "tactus/io/run_file.hpp"

namespace {

std::filesystem::path scratch_file() {
    const auto dir = std::filesystem::exists("/dev/shm") ? std::filesystem::path("/dev/shm")
                                                         : std::filesystem::temp_directory_path();
    return dir / ("tactus-audio-fuzz-" + std::to_string(getpid()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::filesystem::path path = scratch_file();
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
    std::fclose(file);

    static tactus::Engine engine;
    try {
        tactus::run_file(path, engine, {.on_output = [](const float* v, int n) {
                             for (int i = 0; i < n; ++i)
                                 if (!(std::abs(v[i]) <= 1.0f)) std::abort();
                         }});
    } catch (const std::runtime_error& e) {
        tactus::fuzz::check_message(e.what());
    }
    return 0;
}
