// Real-time safety of tactus~ inside a real Pd. Loaded twice into pd: preloaded (LD_PRELOAD), its
// support/allocation_counter.cpp replaces the allocator and pthread_mutex_lock and counts their
// calls made while the guard is on; as the external [perform_guard~ on|off] (the same file, found
// on Pd's path), it passes its signal through and turns the guard on or off in the DSP chain.
// The test patch wraps tactus~ between the two (render_through.pd), so the counts are what
// tactus~'s perform routine did. At exit it prints "perform-guard: performs=N allocations=A
// locks=L" on stderr.
#include <m_pd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>

#include "support/allocation_counter.hpp"

namespace {

using tactus::test::g_allocator_calls;
using tactus::test::g_mutex_locks;
using tactus::test::t_guarded;

std::atomic<long> g_performs{0};

__attribute__((destructor)) void report() {
    std::fprintf(stderr, "perform-guard: performs=%ld allocations=%ld locks=%ld\n",
                 g_performs.load(), g_allocator_calls.load(), g_mutex_locks.load());
}

// [perform_guard~ on|off]
t_class* guard_class = nullptr;
struct Guard {
    t_object pd;
    t_float scalar_input;
    bool on;
};

t_int* perform(t_int* w) {
    const auto* guard = reinterpret_cast<const Guard*>(w[1]);
    const auto* in = reinterpret_cast<const t_sample*>(w[2]);
    auto* out = reinterpret_cast<t_sample*>(w[3]);
    const auto n = static_cast<int>(w[4]);
    if (in != out) std::copy_n(in, n, out);
    if (guard->on) g_performs.fetch_add(1, std::memory_order_relaxed);
    t_guarded = guard->on;
    return w + 5;
}

}  // namespace

extern "C" {

void perform_guard_tilde_setup() {
    guard_class = class_new(gensym("perform_guard~"),
                            reinterpret_cast<t_newmethod>(+[](t_symbol* state) -> void* {
                                auto* guard = reinterpret_cast<Guard*>(pd_new(guard_class));
                                guard->scalar_input = 0;
                                guard->on = std::strcmp(state->s_name, "on") == 0;
                                outlet_new(&guard->pd, &s_signal);
                                return guard;
                            }),
                            nullptr, sizeof(Guard), CLASS_DEFAULT, A_DEFSYMBOL, A_NULL);
    CLASS_MAINSIGNALIN(guard_class, Guard, scalar_input);
    class_addmethod(guard_class, reinterpret_cast<t_method>(+[](Guard* guard, t_signal** sp) {
                        dsp_add(perform, 4, guard, sp[0]->s_vec, sp[1]->s_vec,
                                static_cast<t_int>(sp[0]->s_n));
                    }),
                    gensym("dsp"), A_CANT, A_NULL);
}

}  // extern "C"
