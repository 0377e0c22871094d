// Flush-to-zero / denormals-are-zero for the scope of a process() call: decaying filter states
// would otherwise crawl through denormal numbers, which are slow on x86 and never exactly 0.
#pragma once

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace tactus {

class ScopedFlushDenormals {
  public:
#if defined(__SSE__) || defined(__x86_64__)
    ScopedFlushDenormals() noexcept : saved_(_mm_getcsr()) {
        _mm_setcsr(saved_ | 0x8040);
    }
    ~ScopedFlushDenormals() {
        _mm_setcsr(saved_);
    }

  private:
    unsigned saved_;
#else
    ScopedFlushDenormals() noexcept = default;
#endif
};

}  // namespace tactus
