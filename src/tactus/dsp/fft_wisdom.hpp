// FFTW wisdom for RealFft's plans, recorded at build time (fft_wisdom_generator.cpp writes the
// generated fft_wisdom.cpp), one entry per size in increasing order.
#pragma once

namespace tactus {

struct FftWisdom {
    int size;
    const char* wisdom;  // fftwf_export_wisdom_to_string() after planning this size alone
};
extern const FftWisdom kFftWisdom[];
extern const int kFftWisdomEntries;

}  // namespace tactus
