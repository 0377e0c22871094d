// Real-input FFT of a fixed size (fast for sizes with prime factors 2, 3 and 5) on FFTW3 single
// precision. Buffers are made in prepare(), which takes the process's plans for the size (made
// once, the first time the size is prepared, from the wisdom recorded at build time when the
// build has it: dsp/fft_wisdom.hpp); forward()/inverse() are real-time safe.
#pragma once

#include <fftw3.h>

#include <complex>
#include <vector>

namespace tactus {

class RealFft {
  public:
    RealFft() = default;
    RealFft(const RealFft&) = delete;
    RealFft& operator=(const RealFft&) = delete;
    ~RealFft();

    void prepare(int size);  // may allocate
    int size() const { return size_; }
    int bins() const { return size_ / 2 + 1; }

    float* time() { return time_; }
    std::complex<float>* spectrum() { return reinterpret_cast<std::complex<float>*>(spectrum_); }

    // time() -> spectrum()
    void forward() noexcept { fftwf_execute_dft_r2c(forward_, time_, spectrum_); }
    // spectrum() -> time(), scaled by size
    void inverse() noexcept { fftwf_execute_dft_c2r(inverse_, spectrum_, time_); }

    // RealFfts prepared together (setup and control threads): while one lives on a thread,
    // prepare() there leaves the plans to plan(), which reads the build's wisdom of every new
    // size in one import (FFTW checks its whole configuration, 2 M instructions, on each import)
    // before planning them. Until plan(), the prepared RealFfts have no plans: nothing runs them.
    class PlanTogether {
      public:
        PlanTogether();
        PlanTogether(const PlanTogether&) = delete;
        PlanTogether& operator=(const PlanTogether&) = delete;
        ~PlanTogether();  // without plan() (an exception on the way): the RealFfts stay unplanned
        void plan();      // may allocate

      private:
        std::vector<RealFft*> waiting_;
        std::vector<RealFft*>* outer_;  // an enclosing one's, if any
    };

  private:
    void take_plans();  // the process's plans for size_ (made now if new)
    void release();
    int size_ = 0;
    float* time_ = nullptr;
    fftwf_complex* spectrum_ = nullptr;
    fftwf_plan forward_ = nullptr;  // shared: the process's plans for size_
    fftwf_plan inverse_ = nullptr;
};

}  // namespace tactus
