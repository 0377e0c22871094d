// libFuzzer target: any bytes as an audio file, read the way every command reads its input
// (AudioReader, to the end). Reading either succeeds or throws std::runtime_error with a
// one-line message; whatever is decoded goes through the engine, whose vibration must be finite
// and never above full scale. The engine is prepared once (at 44.1 kHz, whatever the file says):
// its filter design costs more than reading a small file, and the sample-rate check is tested on
// its own. The bytes go through a real file because libsndfile opens paths.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

#include "fuzz_check.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"

namespace {

constexpr int kBlock = 1024;

std::filesystem::path scratch_file() {
    const auto dir = std::filesystem::exists("/dev/shm") ? std::filesystem::path("/dev/shm")
                                                         : std::filesystem::temp_directory_path();
    return dir / ("tactus-audio-fuzz-" + std::to_string(getpid()));
}

// The file the bytes are written to, removed when the process exits normally.
struct Scratch {
    const std::filesystem::path path = scratch_file();
    ~Scratch() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const Scratch scratch;
    const std::filesystem::path& path = scratch.path;
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
    std::fclose(file);

    // One engine per channel count, prepared once: the engine downmixes.
    static std::map<int, std::unique_ptr<tactus::Engine>> engines;
    try {
        tactus::AudioReader reader(path);
        std::unique_ptr<tactus::Engine>& engine = engines[reader.channels()];
        if (!engine) {
            engine = std::make_unique<tactus::Engine>();
            engine->prepare(
                {.sample_rate_hz = 44100, .max_block = kBlock, .channels = reader.channels()});
        }
        engine->reset();
        tactus::ChannelBlock in(reader.channels(), kBlock);
        float out[kBlock];
        float* outs[] = {out};
        while (const int got = reader.read(in.data(), kBlock)) {
            engine->process(in.data(), outs, got);
            for (int i = 0; i < got; ++i)
                if (!(std::abs(out[i]) <= 1.0f)) std::abort();
        }
    } catch (const std::runtime_error& e) {
        tactus::fuzz::check_message(e.what());
    } catch (const std::invalid_argument& e) {  // a channel count the engine does not take
        tactus::fuzz::check_message(e.what());
    }
    return 0;
}
