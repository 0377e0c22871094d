// Build-time generator of fft_wisdom.cpp: FFTW's wisdom for the real FFT plans RealFft makes
// (FFTW_ESTIMATE, forward and inverse), one entry per size (the even sizes with prime factors 2,
// 3 and 5 up to kLargestMixed, the powers of two up to kLargestPowerOfTwo), each recorded on its
// own. Importing a size's entry before planning it spares the planner its search (about 10^7
// instructions a size) and gives the plan it would have chosen. Usage: tactus_fft_wisdom OUT.cpp
#include <fftw3.h>

#include <cstdio>
#include <string>

#include "tactus/dsp/generated_source.hpp"

namespace {

constexpr int kLargestMixed = 4096;
constexpr int kLargestPowerOfTwo = 1 << 16;

bool wanted(int n) {
    if (n < 16 || n % 2 != 0) return false;
    if ((n & (n - 1)) == 0) return n <= kLargestPowerOfTwo;
    if (n > kLargestMixed) return false;
    for (int p : {2, 3, 5})
        while (n % p == 0) n /= p;
    return n == 1;
}

}  // namespace

int main(int argc, char** argv) {
    return tactus::write_generated_source(argc, argv, [](std::FILE* f) {
        std::fprintf(f,
                     "// Generated at build time by fft_wisdom_generator.cpp: do not edit.\n"
                     "#include \"tactus/dsp/fft_wisdom.hpp\"\n\n"
                     "namespace tactus {\n\n"
                     "const FftWisdom kFftWisdom[] = {\n");
        int entries = 0;
        for (int n = 16; n <= kLargestPowerOfTwo; ++n) {
            if (!wanted(n)) continue;
            fftwf_forget_wisdom();
            float* time = fftwf_alloc_real(static_cast<size_t>(n));
            fftwf_complex* spectrum = fftwf_alloc_complex(static_cast<size_t>(n) / 2 + 1);
            fftwf_plan forward = fftwf_plan_dft_r2c_1d(n, time, spectrum, FFTW_ESTIMATE);
            fftwf_plan inverse = fftwf_plan_dft_c2r_1d(n, spectrum, time, FFTW_ESTIMATE);
            char* wisdom = fftwf_export_wisdom_to_string();
            std::fprintf(f, "{%d, R\"w(%s)w\"},\n", n, wisdom);
            fftwf_free(wisdom);
            fftwf_destroy_plan(forward);
            fftwf_destroy_plan(inverse);
            fftwf_free(time);
            fftwf_free(spectrum);
            ++entries;
        }
        std::fprintf(f, "};\nconst int kFftWisdomEntries = %d;\n\n}  // namespace tactus\n",
                     entries);
        fftwf_cleanup();
    });
}
