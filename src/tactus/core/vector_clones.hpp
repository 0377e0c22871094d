// TACTUS_VECTOR_CLONES before a hot loop's function: built by GCC for x86-64, it is compiled
// twice, for the baseline (SSE2) and for AVX2, and the program runs the one the CPU has (GCC's
// target_clones: an ifunc, which the dynamic loader resolves when the library is loaded, never
// on the audio thread). The compiler's vectoriser then fills 256-bit vectors where it can
// (-fopt-info-vec tells where). The same operations in the same order and no fused multiply-adds
// (no "fma" target; tactus builds with -ffp-contract=off): the output is the baseline's, bit for
// bit. Elsewhere (arm64, armhf; Clang, which does not clone templates; ThreadSanitizer builds,
// whose instrumented resolver would run before the sanitizer's runtime) one build, as before.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
#define TACTUS_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define TACTUS_VECTOR_CLONES
#endif
