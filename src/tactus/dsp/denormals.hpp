// Flush-to-zero for the scope of a process() call: decaying filter states would otherwise crawl
// through denormal numbers, which are slow (x86: MXCSR FTZ and DAZ; aarch64: FPCR.FZ, which
// flushes inputs and results alike) and never exactly 0. Other targets run unchanged.
#pragma once

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace tactus {

class ScopedFlushDenormals {
  public:
#if defined(__SSE__) || defined(__x86_64__)
    ScopedFlushDenormals() noexcept : saved_(_mm_getcsr()) {
        _mm_setcsr(saved_ | kFtzDaz);
    }
    ~ScopedFlushDenormals() {
        _mm_setcsr(saved_);
    }

  private:
    static constexpr unsigned kFtzDaz = 0x8040;  // MXCSR bits 15 (FTZ) and 6 (DAZ)
    unsigned saved_;
#elif defined(__aarch64__)
    // The "memory" clobber keeps the scope's loads and stores (a process() call's work)
    // between the two writes.
    ScopedFlushDenormals() noexcept {
        __asm__ __volatile__("mrs %0, fpcr" : "=r"(saved_));
        __asm__ __volatile__("msr fpcr, %0" : : "r"(saved_ | kFz) : "memory");
    }
    ~ScopedFlushDenormals() {
        __asm__ __volatile__("msr fpcr, %0" : : "r"(saved_) : "memory");
    }

  private:
    static constexpr unsigned long kFz = 1ul << 24;  // FPCR bit 24 (FZ), Arm ARM C5.2.8
    unsigned long saved_;
#else
    ScopedFlushDenormals() noexcept = default;
#endif
};

}  // namespace tactus
