// Writes the audio fuzz target's seed corpus: tiny real files in every container libsndfile
// writes here (WAV int/float, AIFF, FLAC, OGG, CAF, W64, AU, MP3), mono and stereo, so the fuzzer
// starts from valid headers of each kind rather than discovering them.
#include <sndfile.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_audio_seeds DIR\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    struct Kind {
        const char* name;
        int format;
    };
    const Kind kinds[] = {{"pcm16.wav", SF_FORMAT_WAV | SF_FORMAT_PCM_16},
                          {"float.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT},
                          {"pcm24.aiff", SF_FORMAT_AIFF | SF_FORMAT_PCM_24},
                          {"pcm16.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16},
                          {"vorbis.ogg", SF_FORMAT_OGG | SF_FORMAT_VORBIS},
                          {"double.caf", SF_FORMAT_CAF | SF_FORMAT_DOUBLE},
                          {"ulaw.au", SF_FORMAT_AU | SF_FORMAT_ULAW},
                          {"pcm8.w64", SF_FORMAT_W64 | SF_FORMAT_PCM_U8},
                          {"layer3.mp3", SF_FORMAT_MPEG | SF_FORMAT_MPEG_LAYER_III}};
    constexpr int kFrames = 64;
    for (const Kind& kind : kinds) {
        for (int channels : {1, 2}) {
            SF_INFO info{};
            info.samplerate = 8000;
            info.channels = channels;
            info.format = kind.format;
            const auto path = dir / (std::to_string(channels) + "ch-" + kind.name);
            SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
            if (!file) {
                std::fprintf(stderr, "%s: %s\n", path.c_str(), sf_strerror(nullptr));
                return 1;
            }
            std::vector<float> samples(static_cast<size_t>(kFrames) * channels);
            for (int i = 0; i < kFrames * channels; ++i)
                samples[i] = 0.5f * std::sin(0.3f * static_cast<float>(i));
            sf_writef_float(file, samples.data(), kFrames);
            sf_close(file);
        }
    }
    return 0;
}
