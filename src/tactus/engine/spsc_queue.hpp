// moodycamel::ReaderWriterQueue (Debian's libreaderwriterqueue-dev), the engine's lock-free
// hand-over between threads, included so that ThreadSanitizer sees its orderings with GCC too.
// The queue orders its slots with fences, which TSan does not model; moodycamel annotates them
// for TSan only where the compiler has __has_feature (clang). Under GCC's -fsanitize=thread
// (__SANITIZE_THREAD__, the tsan preset) the same annotations are given here, before its header.
// Nothing changes in any other build.
#pragma once

#if defined(__SANITIZE_THREAD__) && !defined(__clang__)
namespace moodycamel {
inline int ae_tsan_global;
}
extern "C" void AnnotateHappensBefore(const char* file, int line, void* address);
extern "C" void AnnotateHappensAfter(const char* file, int line, void* address);
#define AE_TSAN_ANNOTATE_RELEASE() \
    AnnotateHappensBefore(__FILE__, __LINE__, static_cast<void*>(&::moodycamel::ae_tsan_global))
#define AE_TSAN_ANNOTATE_ACQUIRE() \
    AnnotateHappensAfter(__FILE__, __LINE__, static_cast<void*>(&::moodycamel::ae_tsan_global))
#endif

#include <readerwriterqueue/readerwriterqueue.h>
