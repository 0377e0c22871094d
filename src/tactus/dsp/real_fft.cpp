#include "tactus/dsp/real_fft.hpp"

#include <mutex>
#include <new>

namespace tactus {
namespace {
// FFTW's planner is not thread-safe; plans are made off the audio thread, one at a time.
std::mutex planner_mutex;
}  // namespace

RealFft::~RealFft() {
    release();
}

void RealFft::release() {
    std::lock_guard lock(planner_mutex);
    if (forward_) fftwf_destroy_plan(forward_);
    if (inverse_) fftwf_destroy_plan(inverse_);
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
    std::lock_guard lock(planner_mutex);
    size_ = size;
    time_ = fftwf_alloc_real(static_cast<size_t>(size));
    spectrum_ = fftwf_alloc_complex(static_cast<size_t>(size / 2 + 1));
    if (!time_ || !spectrum_) throw std::bad_alloc();
    forward_ = fftwf_plan_dft_r2c_1d(size, time_, spectrum_, FFTW_ESTIMATE);
    inverse_ = fftwf_plan_dft_c2r_1d(size, spectrum_, time_, FFTW_ESTIMATE);
    for (int i = 0; i < size; ++i) time_[i] = 0.0f;
}

}  // namespace tactus
