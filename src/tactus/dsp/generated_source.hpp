// The one output of a build-time generator (fir_tables_generator.cpp, fft_wisdom_generator.cpp):
// `write` fills OUTPUT.partial, renamed over OUTPUT once whole, so that an interrupted build never
// leaves a truncated source behind. Called from the generator's main(); returns its exit code.
#pragma once

#include <cstdio>
#include <string>

namespace tactus {

template <class Write>  // void(std::FILE*)
int write_generated_source(int argc, char** argv, Write&& write) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT.cpp\n", argv[0]);
        return 2;
    }
    const std::string path = argv[1], partial = path + ".partial";
    std::FILE* f = std::fopen(partial.c_str(), "w");
    if (!f) {
        std::fprintf(stderr, "%s: cannot write %s\n", argv[0], partial.c_str());
        return 1;
    }
    write(f);
    if (std::fclose(f) != 0 || std::rename(partial.c_str(), path.c_str()) != 0) {
        std::fprintf(stderr, "%s: cannot write %s\n", argv[0], path.c_str());
        return 1;
    }
    return 0;
}

}  // namespace tactus
