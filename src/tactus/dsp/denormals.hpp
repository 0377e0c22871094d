// Flush-to-zero for the scope of a process() call: decaying filter states would otherwise crawl
// through denormal numbers, which are slow (x86: MXCSR FTZ and DAZ; aarch64: FPCR.FZ; 32-bit Arm:
// FPSCR.FZ; both Arm bits flush inputs and results alike) and never exactly 0. Other targets run
// unchanged.
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
#elif defined(__arm__) && defined(__ARM_FP)
    // 32-bit Arm with a VFP unit (armhf: Raspberry Pi OS 32-bit, Bela): scalar float arithmetic
    // runs on VFP, which computes denormals unless FPSCR.FZ is set (NEON always flushes).
    ScopedFlushDenormals() noexcept {
        __asm__ __volatile__("vmrs %0, fpscr" : "=r"(saved_));
        __asm__ __volatile__("vmsr fpscr, %0" : : "r"(saved_ | kFz) : "memory");
    }
    ~ScopedFlushDenormals() {
        __asm__ __volatile__("vmsr fpscr, %0" : : "r"(saved_) : "memory");
    }

  private:
    static constexpr unsigned kFz = 1u << 24;  // FPSCR bit 24 (FZ), Arm ARM (ARMv7-A) A2.7.3
    unsigned saved_;
#else
    ScopedFlushDenormals() noexcept = default;
#endif
};

}  // namespace tactus
