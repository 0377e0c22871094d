#include "tactus/dsp/real_fft.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <new>

#include "tactus/dsp/fft_wisdom.hpp"

namespace tactus {
namespace {

// FFTW's planner is not thread-safe; plans are made off the audio thread, one at a time.
std::mutex planner_mutex;

// One pair of plans per size for the whole process, made when the size is first prepared and
// kept to the end (planning costs 10^7 instructions a size, 10^6 with the build's wisdom; every
// RealFft of that size shares them through FFTW's new-array execute functions, which are
// thread-safe). The buffers they are made on come from fftwf_alloc_*, aligned as every RealFft's
// are. planner_mutex held.
struct Plans {
    fftwf_plan forward = nullptr, inverse = nullptr;
};
const Plans& plans_for(int size) {
    static auto* const plans = new std::map<int, Plans>;  // never freed: plans outlive statics
    auto found = plans->find(size);
    if (found != plans->end()) return found->second;
    // The build's wisdom for the size, if any: the planner takes the plan it records.
    const FftWisdom* const end = kFftWisdom + kFftWisdomEntries;
    const FftWisdom* entry = std::lower_bound(kFftWisdom, end, size,
                                              [](const FftWisdom& w, int n) { return w.size < n; });
    if (entry != end && entry->size == size) fftwf_import_wisdom_from_string(entry->wisdom);
    float* time = fftwf_alloc_real(static_cast<size_t>(size));
    fftwf_complex* spectrum = fftwf_alloc_complex(static_cast<size_t>(size) / 2 + 1);
    if (!time || !spectrum) throw std::bad_alloc();
    const Plans made{fftwf_plan_dft_r2c_1d(size, time, spectrum, FFTW_ESTIMATE),
                     fftwf_plan_dft_c2r_1d(size, spectrum, time, FFTW_ESTIMATE)};
    fftwf_free(time);
    fftwf_free(spectrum);
    if (!made.forward || !made.inverse) throw std::bad_alloc();
    return plans->emplace(size, made).first->second;
}

}  // namespace

RealFft::~RealFft() {
    release();
}

void RealFft::release() {
    fftwf_free(time_);
    fftwf_free(spectrum_);
    forward_ = inverse_ = nullptr;
    time_ = nullptr;
    spectrum_ = nullptr;
    size_ = 0;
}

void RealFft::prepare(int size) {
    if (size == size_) return;
    release();
    size_ = size;
    time_ = fftwf_alloc_real(static_cast<size_t>(size));
    spectrum_ = fftwf_alloc_complex(static_cast<size_t>(size) / 2 + 1);
    if (!time_ || !spectrum_) throw std::bad_alloc();
    {
        std::lock_guard lock(planner_mutex);
        const Plans& plans = plans_for(size);
        forward_ = plans.forward;
        inverse_ = plans.inverse;
    }
    for (int i = 0; i < size; ++i) time_[i] = 0.0f;
}

}  // namespace tactus
